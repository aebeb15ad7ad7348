// Section meshes from .msh files (inside the gmsh module): 3- or 6-node triangles in the plane
// z = 0, physical curves as boundaries, physical surfaces as regions, physical points as node
// sets.
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "../mesh/section_support.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "gmsh_meshing.hpp"
#include "msh_prescan.hpp"

namespace biphasic::detail {

namespace {

constexpr int kGmshLine2 = 1;
constexpr int kGmshLine3 = 8;

std::string type_name(int type) {
  const auto properties = gmsh_element_type(type);
  return "'" + (properties ? properties->name : std::string("unknown")) + "' (gmsh type " +
         std::to_string(type) + ")";
}

std::string group_name(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  return name.empty() ? std::to_string(tag) : name;
}

// Elements of physical group (dim, tag), by gmsh type: element tags and their node tags.
struct GroupElements {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elements, nodes;
};

GroupElements elements_of_group(int dim, int tag) {
  GroupElements all;
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
  for (const int entity : entities) {
    GroupElements one;
    gmsh::model::mesh::getElements(one.types, one.elements, one.nodes, dim, entity);
    for (std::size_t i = 0; i < one.types.size(); ++i) {
      all.types.push_back(one.types[i]);
      all.elements.push_back(std::move(one.elements[i]));
      all.nodes.push_back(std::move(one.nodes[i]));
    }
  }
  return all;
}

// A physical curve as line elements: their tags and node tags (2 or 3 per element).
struct RawCurve {
  std::string name;
  std::vector<std::size_t> elements;
  std::vector<std::size_t> nodes;
};

// Physical curves merged by name; every element a line of the triangles' order.
std::vector<RawCurve> read_curves(bool quadratic) {
  const int line_type = quadratic ? kGmshLine3 : kGmshLine2;
  const std::size_t per = quadratic ? 3 : 2;
  std::vector<RawCurve> curves;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  for (const auto& [dim, tag] : groups) {
    const std::string name = group_name(dim, tag);
    auto it = std::find_if(curves.begin(), curves.end(),
                           [&](const RawCurve& c) { return c.name == name; });
    if (it == curves.end()) {
      curves.push_back({name, {}, {}});
      it = std::prev(curves.end());
    }
    const GroupElements group = elements_of_group(dim, tag);
    for (std::size_t i = 0; i < group.types.size(); ++i) {
      if (group.elements[i].empty()) continue;
      if (group.types[i] != line_type) {
        throw std::runtime_error("physical curve '" + name + "' has elements of type " +
                                 type_name(group.types[i]) + "; the triangles have " +
                                 (quadratic ? "6" : "3") + " nodes, so its lines must have " +
                                 std::to_string(per) + " nodes");
      }
      if (group.nodes[i].size() != group.elements[i].size() * per) {
        throw std::runtime_error("physical curve '" + name + "' has lines with missing nodes");
      }
      it->elements.insert(it->elements.end(), group.elements[i].begin(), group.elements[i].end());
      it->nodes.insert(it->nodes.end(), group.nodes[i].begin(), group.nodes[i].end());
    }
  }
  for (const RawCurve& c : curves)
    if (c.elements.empty())
      throw std::runtime_error("physical curve '" + c.name + "' has no line elements");
  return curves;
}

// Physical surfaces as regions of `mesh`, whose triangle t is gmsh element elements[t] (the
// rules of read_gmsh's physical volumes: none → no regions, else every triangle in one).
void read_regions(SectionMesh& mesh, const std::vector<std::size_t>& elements) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  if (groups.empty()) return;
  std::unordered_map<std::size_t, std::size_t> triangle_of;
  triangle_of.reserve(elements.size());
  for (std::size_t t = 0; t < elements.size(); ++t) triangle_of.emplace(elements[t], t);
  mesh.triangle_region.assign(mesh.triangles.size(), -1);
  for (const auto& [dim, tag] : groups) {
    const std::string name = group_name(dim, tag);
    const auto found = std::find(mesh.region_names.begin(), mesh.region_names.end(), name);
    const int region = static_cast<int>(found - mesh.region_names.begin());
    if (found == mesh.region_names.end()) mesh.region_names.push_back(name);
    const GroupElements group = elements_of_group(dim, tag);
    for (const auto& list : group.elements) {
      for (const std::size_t element : list) {
        const auto it = triangle_of.find(element);
        if (it == triangle_of.end()) continue;
        int& slot = mesh.triangle_region[it->second];
        if (slot >= 0 && slot != region) {
          throw std::runtime_error("triangle (element tag " + std::to_string(element) +
                                   ") is in two physical surfaces, '" +
                                   mesh.region_names[static_cast<std::size_t>(slot)] + "' and '" +
                                   name + "'");
        }
        slot = region;
      }
    }
  }
  for (std::size_t t = 0; t < mesh.triangle_region.size(); ++t) {
    if (mesh.triangle_region[t] < 0) {
      throw std::runtime_error("triangle (element tag " + std::to_string(elements[t]) +
                               ") is in no physical surface, while others are; put every "
                               "surface in a physical group, or none");
    }
  }
}

SectionMesh extract_section() {
  std::vector<int> volume_types;
  gmsh::model::mesh::getElementTypes(volume_types, 3, -1);
  if (!volume_types.empty()) {
    throw std::runtime_error("the mesh has volume elements (" + type_name(volume_types.front()) +
                             "); a section mesh is two-dimensional (read it with read_gmsh)");
  }
  std::vector<int> surface_types;
  gmsh::model::mesh::getElementTypes(surface_types, 2, -1);
  bool has_linear = false, has_quadratic = false;
  for (const int type : surface_types) {
    if (type == kGmshTri3) {
      has_linear = true;
    } else if (type == kGmshTri6) {
      has_quadratic = true;
    } else {
      throw std::runtime_error("unsupported surface element type " + type_name(type) +
                               "; only 3-node and 6-node triangles are supported");
    }
  }
  if (!has_linear && !has_quadratic) throw std::runtime_error("no triangles");
  if (has_linear && has_quadratic) {
    throw std::runtime_error("mixed element orders: both 3-node and 6-node triangles");
  }
  const bool quadratic = has_quadratic;
  const std::size_t tri_size = quadratic ? 6 : 3;
  std::vector<std::size_t> tri_elements, tri_nodes;
  gmsh::model::mesh::getElementsByType(quadratic ? kGmshTri6 : kGmshTri3, tri_elements, tri_nodes,
                                       -1);
  const std::size_t num_triangles = tri_elements.size();
  if (tri_nodes.size() != num_triangles * tri_size ||
      std::find(tri_nodes.begin(), tri_nodes.end(), std::size_t{0}) != tri_nodes.end()) {
    throw std::runtime_error("triangles with missing nodes (mixed element orders?)");
  }
  const std::vector<RawCurve> curves = read_curves(quadratic);

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> position;
  position.reserve(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i) position.emplace(node_tags[i], i);
  const auto coordinates = [&](std::size_t tag) -> std::array<double, 3> {
    const auto it = position.find(tag);
    if (it == position.end()) {
      throw std::runtime_error("an element uses node tag " + std::to_string(tag) +
                               " which has no coordinates");
    }
    const std::size_t p = 3 * it->second;
    return {coords[p], coords[p + 1], coords[p + 2]};
  };

  // Renumbering: triangle corners first, then (quadratic) edge nodes, each by ascending tag.
  std::vector<std::size_t> corner_tags, edge_tags;
  for (std::size_t t = 0; t < num_triangles; ++t)
    for (std::size_t k = 0; k < tri_size; ++k)
      (k < 3 ? corner_tags : edge_tags).push_back(tri_nodes[t * tri_size + k]);
  for (auto* tags : {&corner_tags, &edge_tags}) {
    std::sort(tags->begin(), tags->end());
    tags->erase(std::unique(tags->begin(), tags->end()), tags->end());
  }
  std::unordered_map<std::size_t, Index> new_index;
  new_index.reserve(corner_tags.size() + edge_tags.size());
  for (const std::size_t tag : corner_tags)
    new_index.emplace(tag, static_cast<Index>(new_index.size()));
  const auto num_vertices = static_cast<Index>(corner_tags.size());
  for (const std::size_t tag : edge_tags) {
    if (!new_index.emplace(tag, static_cast<Index>(new_index.size())).second) {
      throw std::runtime_error("node tag " + std::to_string(tag) +
                               " is both a triangle corner and an edge node");
    }
  }

  // The plane z = 0, to a tolerance relative to the section's extent.
  double extent = 0.0;
  for (const auto* tags : {&corner_tags, &edge_tags})
    for (const std::size_t tag : *tags) {
      const auto x = coordinates(tag);
      extent = std::max({extent, std::abs(x[0]), std::abs(x[1])});
    }
  const double tolerance = 1e-10 * std::max(extent, 1.0);
  const auto point_of = [&](std::size_t tag) -> Point2 {
    const auto x = coordinates(tag);
    if (!(std::abs(x[2]) <= tolerance)) {
      std::ostringstream msg;
      msg << "node tag " << tag << " at (" << x[0] << ", " << x[1] << ", " << x[2]
          << ") has z = " << x[2] << "; a section mesh must lie in the plane z = 0";
      throw std::runtime_error(msg.str());
    }
    return {x[0], x[1]};
  };
  std::vector<Point2> points;
  points.reserve(new_index.size());
  for (const std::size_t tag : corner_tags) points.push_back(point_of(tag));
  for (const std::size_t tag : edge_tags) points.push_back(point_of(tag));

  const auto curve_node = [&](const RawCurve& c, std::size_t e, std::size_t k, std::size_t per) {
    const std::size_t tag = c.nodes[e * per + k];
    const auto it = new_index.find(tag);
    const bool is_end = k < 2;
    if (it == new_index.end() || (it->second < num_vertices) != is_end) {
      throw std::runtime_error("physical curve '" + c.name + "' line (element tag " +
                               std::to_string(c.elements[e]) + "): node tag " +
                               std::to_string(tag) + " is not a triangle " +
                               (is_end ? "corner" : "edge node"));
    }
    return it->second;
  };

  const auto nv = static_cast<std::uint64_t>(num_vertices);
  const auto key = [nv](Index a, Index b) {
    return static_cast<std::uint64_t>(std::min(a, b)) * nv +
           static_cast<std::uint64_t>(std::max(a, b));
  };
  const auto not_an_edge = [](const RawCurve& c, std::size_t e) {
    return std::runtime_error("physical curve '" + c.name + "' line (element tag " +
                              std::to_string(c.elements[e]) + ") is not an edge of any triangle");
  };

  SectionMesh mesh;
  if (!quadratic) {
    std::vector<std::array<Index, 3>> triangles(num_triangles);
    std::unordered_set<std::uint64_t> edges;
    for (std::size_t t = 0; t < num_triangles; ++t) {
      for (std::size_t k = 0; k < 3; ++k) triangles[t][k] = new_index.at(tri_nodes[t * 3 + k]);
      for (const auto& [a, b] : kTriEdges) edges.insert(key(triangles[t][a], triangles[t][b]));
    }
    std::vector<LinearCurve> linear;
    for (const RawCurve& c : curves) {
      std::vector<std::array<Index, 2>> segments(c.elements.size());
      for (std::size_t e = 0; e < segments.size(); ++e) {
        for (std::size_t k = 0; k < 2; ++k) segments[e][k] = curve_node(c, e, k, 2);
        if (segments[e][0] == segments[e][1] || !edges.count(key(segments[e][0], segments[e][1])))
          throw not_an_edge(c, e);
      }
      linear.emplace_back(c.name, std::move(segments));
    }
    mesh = section_p2_from_linear(std::move(points), triangles, linear);
  } else {
    mesh.nodes = std::move(points);
    mesh.num_vertices = num_vertices;
    mesh.triangles.resize(num_triangles);
    for (std::size_t t = 0; t < num_triangles; ++t)
      for (std::size_t k = 0; k < 6; ++k) mesh.triangles[t][k] = new_index.at(tri_nodes[t * 6 + k]);
    // Each vertex pair's edge node, to name the line that does not match the triangles.
    std::unordered_map<std::uint64_t, Index> edge_node;
    for (const Tri6& tri : mesh.triangles)
      for (std::size_t e = 0; e < kTriEdges.size(); ++e)
        edge_node.emplace(key(tri[kTriEdges[e][0]], tri[kTriEdges[e][1]]), tri[3 + e]);
    for (const RawCurve& c : curves) {
      SectionBoundary boundary{c.name, std::vector<Line3>(c.elements.size())};
      for (std::size_t e = 0; e < c.elements.size(); ++e) {
        Line3& s = boundary.segments[e];
        for (std::size_t k = 0; k < 3; ++k) s[k] = curve_node(c, e, k, 3);
        const auto it = edge_node.find(key(s[0], s[1]));
        if (s[0] == s[1] || it == edge_node.end() || it->second != s[2]) throw not_an_edge(c, e);
      }
      mesh.boundaries.push_back(std::move(boundary));
    }
    orient_triangles(mesh);
    orient_boundary_segments(mesh);
  }

  mesh.file_tags.assign(static_cast<std::size_t>(mesh.num_nodes()), -1);
  for (std::size_t i = 0; i < corner_tags.size(); ++i)
    mesh.file_tags[i] = static_cast<Index>(corner_tags[i]);
  if (quadratic) {
    for (std::size_t i = 0; i < edge_tags.size(); ++i)
      mesh.file_tags[corner_tags.size() + i] = static_cast<Index>(edge_tags[i]);
  }

  // Physical points as node sets (merged by name).
  gmsh::vectorpair points_groups;
  gmsh::model::getPhysicalGroups(points_groups, 0);
  for (const auto& [dim, tag] : points_groups) {
    const std::string name = group_name(dim, tag);
    auto it = std::find_if(mesh.node_sets.begin(), mesh.node_sets.end(),
                           [&](const NodeSet& s) { return s.name == name; });
    if (it == mesh.node_sets.end()) {
      mesh.node_sets.push_back({name, 0, {}});
      it = std::prev(mesh.node_sets.end());
    }
    const GroupElements group = elements_of_group(dim, tag);
    for (const auto& list : group.nodes) {
      for (const std::size_t node : list) {
        const auto found = new_index.find(node);
        if (found == new_index.end()) {
          const auto x = coordinates(node);
          std::ostringstream msg;
          msg << "physical point '" << name << "': node tag " << node << " at (" << x[0] << ", "
              << x[1] << ", " << x[2] << ") is not a node of any triangle";
          throw std::runtime_error(msg.str());
        }
        it->nodes.push_back(found->second);
      }
    }
    std::sort(it->nodes.begin(), it->nodes.end());
    it->nodes.erase(std::unique(it->nodes.begin(), it->nodes.end()), it->nodes.end());
    if (it->nodes.empty()) throw std::runtime_error("physical point '" + name + "' has no node");
  }

  read_regions(mesh, tri_elements);
  check_section_mesh(mesh);
  return mesh;
}

}  // namespace

SectionMesh gmsh_read_section(const std::string& path) {
  return with_context("read_gmsh_section: '" + path + "'", [&] {
    SectionMesh mesh;
    with_msh_file(path, [&] { mesh = extract_section(); });
    return mesh;
  });
}

}  // namespace biphasic::detail
