// Meshes from gmsh (inside the gmsh module): the generated quarter cylinder, .msh files (formats
// 2.2 and 4.1), and the gmsh meshing shared by the generators (gmsh_meshing.hpp).
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <mutex>
#include <numbers>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "gmsh_meshing.hpp"
#include "msh_prescan.hpp"

namespace biphasic {

namespace {

using detail::kGmshTet10;
using detail::kGmshTet4;
using detail::kGmshTri3;
using detail::kGmshTri6;

// Our local node k of a 10-node tet is gmsh's local node kFromGmshTet10[k].
constexpr std::array<int, 10> kFromGmshTet10{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};

using detail::kCylinderFaces;

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

// gmsh 4.8 has no query for this: an uninitialized gmsh either leaves the output untouched or
// throws, an initialized one returns the option's value.
bool gmsh_is_initialized() {
  double terminal = std::numeric_limits<double>::quiet_NaN();
  try {
    gmsh::option::getNumber("General.Terminal", terminal);
  } catch (...) {
    return false;
  }
  return !std::isnan(terminal);
}

// Scoped use of the process-wide gmsh: initializes it (and finalizes it on exit) unless it was
// already initialized, in which case it works in a model of its own and afterwards removes
// that model, restores the previously current model and every option it changed.
// Serializes users within the process.
class GmshSession {
 public:
  GmshSession() : lock_(gmsh_mutex()) {
    try {
      owner_ = !gmsh_is_initialized();
      if (owner_) {
        gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
      } else {
        gmsh::model::getCurrent(previous_model_);
      }
      set_number("General.Terminal", 0);
      static unsigned serial = 0;
      model_ = "biphasic_mesh_" + std::to_string(++serial);
      gmsh::model::add(model_);
    } catch (...) {
      restore();
      throw;
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  ~GmshSession() { restore(); }

  /// Sets a numerical gmsh option, remembering its old value when gmsh is shared.
  void set_number(const std::string& name, double value) {
    if (!owner_) {
      double old = 0.0;
      gmsh::option::getNumber(name, old);
      saved_.emplace_back(name, old);
    }
    gmsh::option::setNumber(name, value);
  }

 private:
  void restore() noexcept {
    if (owner_) {
      try {
        gmsh::finalize();
      } catch (...) {
      }
      return;
    }
    if (!model_.empty()) {
      try {
        gmsh::model::setCurrent(model_);
        gmsh::model::remove();
      } catch (...) {
      }
    }
    try {
      gmsh::model::setCurrent(previous_model_);
    } catch (...) {
    }
    for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
      try {
        gmsh::option::setNumber(it->first, it->second);
      } catch (...) {
      }
    }
  }

  std::lock_guard<std::mutex> lock_;
  bool owner_ = false;
  std::string previous_model_;
  std::string model_;
  std::vector<std::pair<std::string, double>> saved_;
};

std::string element_type_name(int type) {
  const auto properties = detail::gmsh_element_type(type);
  return "'" + (properties ? properties->name : std::string("unknown")) + "' (gmsh type " +
         std::to_string(type) + ")";
}

// Physical points and curves of the current model as node sets of `mesh` (whose nodes are
// `new_index` of their gmsh tags): a point's node, a curve's segment end points and the edge
// node of each segment (a linear mesh's straight midpoint, a quadratic mesh's own). Unnamed
// groups are named by their tag. Throws std::runtime_error naming the group for a node that
// is no tetrahedron node, or a segment that is no tetrahedron edge.
std::vector<NodeSet> extract_node_sets(const Mesh& mesh,
                                       const std::unordered_map<std::size_t, Index>& new_index,
                                       const std::function<Point(std::size_t)>& coordinates) {
  std::vector<NodeSet> sets;
  std::unordered_map<std::uint64_t, Index> edge_node;
  const auto nv = static_cast<std::uint64_t>(mesh.num_vertices);
  const auto edge_key = [nv](Index a, Index b) {
    return static_cast<std::uint64_t>(std::min(a, b)) * nv +
           static_cast<std::uint64_t>(std::max(a, b));
  };
  for (int dim : {0, 1}) {
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, dim);
    if (groups.empty()) continue;
    if (dim == 1 && edge_node.empty()) {
      for (const Tet10& t : mesh.tets)
        for (std::size_t e = 0; e < kTetEdges.size(); ++e)
          edge_node.emplace(edge_key(t[kTetEdges[e][0]], t[kTetEdges[e][1]]), t[4 + e]);
    }
    for (const auto& [group_dim, tag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(group_dim, tag, name);
      if (name.empty()) name = std::to_string(tag);
      const std::string what =
          std::string(dim == 0 ? "physical point '" : "physical curve '") + name + "'";
      auto it = std::find_if(sets.begin(), sets.end(), [&](const NodeSet& s) {
        return s.name == name && s.dimension == dim;
      });
      if (it == sets.end()) {
        sets.push_back({name, dim, {}});
        it = std::prev(sets.end());
      }
      const auto node_of = [&](std::size_t file_tag) {
        const auto found = new_index.find(file_tag);
        if (found == new_index.end()) {
          const Point x = coordinates(file_tag);
          std::ostringstream msg;
          msg << what << ": node tag " << file_tag << " at (" << x[0] << ", " << x[1] << ", "
              << x[2] << ") is not a node of any tetrahedron (embed it in the volume or on one "
              << "of its surfaces)";
          throw std::runtime_error(msg.str());
        }
        return found->second;
      };
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(group_dim, tag, entities);
      for (const int entity : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elements, nodes;
        gmsh::model::mesh::getElements(types, elements, nodes, dim, entity);
        for (std::size_t i = 0; i < types.size(); ++i) {
          if (elements[i].empty()) continue;
          const std::size_t per = nodes[i].size() / elements[i].size();
          for (std::size_t e = 0; e < elements[i].size(); ++e) {
            const std::size_t* n = nodes[i].data() + e * per;
            if (dim == 0) {
              it->nodes.push_back(node_of(n[0]));
              continue;
            }
            const Index a = node_of(n[0]), b = node_of(n[1]);
            const auto edge = a < mesh.num_vertices && b < mesh.num_vertices
                                  ? edge_node.find(edge_key(a, b))
                                  : edge_node.end();
            if (edge == edge_node.end()) {
              throw std::runtime_error(what + ": segment (element tag " +
                                       std::to_string(elements[i][e]) + ", node tags " +
                                       std::to_string(n[0]) + ", " + std::to_string(n[1]) +
                                       ") is not an edge of any tetrahedron");
            }
            it->nodes.insert(it->nodes.end(), {a, b, edge->second});
          }
        }
      }
      std::sort(it->nodes.begin(), it->nodes.end());
      it->nodes.erase(std::unique(it->nodes.begin(), it->nodes.end()), it->nodes.end());
      if (it->nodes.empty()) throw std::runtime_error(what + " has no mesh nodes");
    }
  }
  return sets;
}

// Physical volumes of the current model as regions of `mesh`, whose tet t is gmsh element
// tet_elements[t]. A physical volume without a name is named by its tag; groups of the same name
// are one region. No physical volume: no regions. A tet in two regions, or (when there are
// physical volumes) in none, is an error naming its element tag.
void extract_regions(Mesh& mesh, const std::vector<std::size_t>& tet_elements) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 3);
  if (groups.empty()) return;
  std::unordered_map<std::size_t, std::size_t> tet_of;
  tet_of.reserve(tet_elements.size());
  for (std::size_t t = 0; t < tet_elements.size(); ++t) tet_of.emplace(tet_elements[t], t);
  mesh.tet_region.assign(mesh.tets.size(), -1);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = std::to_string(tag);
    int region = mesh.find_region(name);
    if (region < 0) {
      region = static_cast<int>(mesh.region_names.size());
      mesh.region_names.push_back(name);
    }
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (const int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elements, nodes;
      gmsh::model::mesh::getElements(types, elements, nodes, dim, entity);
      for (const auto& list : elements)
        for (const std::size_t element : list) {
          const auto it = tet_of.find(element);
          if (it == tet_of.end()) continue;
          int& slot = mesh.tet_region[it->second];
          if (slot >= 0 && slot != region) {
            throw std::runtime_error("tetrahedron (element tag " + std::to_string(element) +
                                     ") is in two physical volumes, '" +
                                     mesh.region_names[static_cast<std::size_t>(slot)] + "' and '" +
                                     name + "'");
          }
          slot = region;
        }
    }
  }
  for (std::size_t t = 0; t < mesh.tet_region.size(); ++t) {
    if (mesh.tet_region[t] < 0) {
      throw std::runtime_error("tetrahedron (element tag " + std::to_string(tet_elements[t]) +
                               ") is in no physical volume, while others are (regions: " +
                               [&] {
                                 std::string names;
                                 for (const auto& n : mesh.region_names)
                                   names += (names.empty() ? "'" : ", '") + n + "'";
                                 return names;
                               }() +
                               "); put every volume in a physical group, or none");
    }
  }
  check_regions(mesh);
}

// Builds a Mesh from the current gmsh model: every 4- or 10-node tetrahedron, and one boundary
// per physical surface (merged by name). Nodes are renumbered corners first, each group in
// ascending gmsh tag order; nodes of no tet are dropped.
Mesh extract_current_model() {
  std::vector<int> volume_types;
  gmsh::model::mesh::getElementTypes(volume_types, 3, -1);
  bool has_linear = false, has_quadratic = false;
  for (const int type : volume_types) {
    if (type == kGmshTet4) {
      has_linear = true;
    } else if (type == kGmshTet10) {
      has_quadratic = true;
    } else {
      throw std::runtime_error("unsupported volume element type " + element_type_name(type) +
                               "; only 4-node and 10-node tetrahedra are supported");
    }
  }
  if (!has_linear && !has_quadratic) throw std::runtime_error("no tetrahedra");
  if (has_linear && has_quadratic) {
    throw std::runtime_error("mixed element orders: both 4-node and 10-node tetrahedra");
  }
  const bool quadratic = has_quadratic;
  const std::size_t tet_size = quadratic ? 10 : 4;
  const std::size_t tri_size = quadratic ? 6 : 3;
  const int tri_type = quadratic ? kGmshTri6 : kGmshTri3;
  const int other_tri_type = quadratic ? kGmshTri3 : kGmshTri6;

  std::vector<std::size_t> tet_elements, tet_nodes;
  gmsh::model::mesh::getElementsByType(quadratic ? kGmshTet10 : kGmshTet4, tet_elements, tet_nodes,
                                       -1);
  const std::size_t num_tets = tet_elements.size();
  if (tet_nodes.size() != num_tets * tet_size ||
      std::find(tet_nodes.begin(), tet_nodes.end(), std::size_t{0}) != tet_nodes.end()) {
    throw std::runtime_error("tetrahedra with missing nodes (mixed element orders?)");
  }

  // Boundary triangles as gmsh node tags, with their element tags for messages.
  struct RawBoundary {
    std::string name;
    std::vector<std::size_t> elements;
    std::vector<std::size_t> nodes;
  };
  std::vector<RawBoundary> raw_boundaries;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = std::to_string(tag);
    auto it = std::find_if(raw_boundaries.begin(), raw_boundaries.end(),
                           [&](const RawBoundary& b) { return b.name == name; });
    if (it == raw_boundaries.end()) {
      raw_boundaries.push_back({name, {}, {}});
      it = std::prev(raw_boundaries.end());
    }
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (const int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elements, nodes;
      gmsh::model::mesh::getElements(types, elements, nodes, dim, entity);
      for (std::size_t i = 0; i < types.size(); ++i) {
        if (types[i] == tri_type) {
          if (nodes[i].size() != elements[i].size() * tri_size) {
            throw std::runtime_error("physical surface '" + name +
                                     "' has triangles with missing nodes");
          }
          it->elements.insert(it->elements.end(), elements[i].begin(), elements[i].end());
          it->nodes.insert(it->nodes.end(), nodes[i].begin(), nodes[i].end());
        } else if (types[i] == other_tri_type) {
          throw std::runtime_error("mixed element orders: physical surface '" + name + "' has " +
                                   (quadratic ? "3" : "6") +
                                   "-node triangles but the tetrahedra have " +
                                   (quadratic ? "10" : "4") + " nodes");
        } else {
          throw std::runtime_error("physical surface '" + name +
                                   "' contains unsupported element type " +
                                   element_type_name(types[i]) + "; only triangles are supported");
        }
      }
    }
  }

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> node_position;
  node_position.reserve(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i) node_position.emplace(node_tags[i], i);
  const auto coordinates = [&](std::size_t tag) -> Point {
    const auto it = node_position.find(tag);
    if (it == node_position.end()) {
      throw std::runtime_error("an element uses node tag " + std::to_string(tag) +
                               " which has no coordinates");
    }
    const std::size_t p = 3 * it->second;
    return {coords[p], coords[p + 1], coords[p + 2]};
  };

  // Renumbering: tet corners first, then (quadratic) tet edge nodes, each by ascending tag.
  std::vector<std::size_t> corner_tags, edge_tags;
  corner_tags.reserve(4 * num_tets);
  for (std::size_t t = 0; t < num_tets; ++t) {
    for (std::size_t k = 0; k < tet_size; ++k) {
      (k < 4 ? corner_tags : edge_tags).push_back(tet_nodes[t * tet_size + k]);
    }
  }
  for (auto* tags : {&corner_tags, &edge_tags}) {
    std::sort(tags->begin(), tags->end());
    tags->erase(std::unique(tags->begin(), tags->end()), tags->end());
  }
  std::unordered_map<std::size_t, Index> new_index;
  new_index.reserve(corner_tags.size() + edge_tags.size());
  for (const std::size_t tag : corner_tags) {
    new_index.emplace(tag, static_cast<Index>(new_index.size()));
  }
  const Index num_vertices = static_cast<Index>(corner_tags.size());
  for (const std::size_t tag : edge_tags) {
    if (!new_index.emplace(tag, static_cast<Index>(new_index.size())).second) {
      throw std::runtime_error("node tag " + std::to_string(tag) +
                               " is both a tetrahedron corner and an edge node");
    }
  }
  const auto boundary_node = [&](const RawBoundary& b, std::size_t face, std::size_t k) {
    const std::size_t tag = b.nodes[face * tri_size + k];
    const auto it = new_index.find(tag);
    const bool is_corner = k < 3;
    if (it == new_index.end() || (it->second < num_vertices) != is_corner) {
      throw std::runtime_error("physical surface '" + b.name + "' triangle (element tag " +
                               std::to_string(b.elements[face]) + "): node tag " +
                               std::to_string(tag) + " is not a tetrahedron " +
                               (is_corner ? "corner" : "edge node"));
    }
    return it->second;
  };

  Mesh mesh;
  if (!quadratic) {
    std::vector<Point> vertices;
    vertices.reserve(corner_tags.size());
    for (const std::size_t tag : corner_tags) vertices.push_back(coordinates(tag));
    std::vector<std::array<Index, 4>> tets(num_tets);
    for (std::size_t t = 0; t < num_tets; ++t) {
      for (std::size_t k = 0; k < 4; ++k) tets[t][k] = new_index.at(tet_nodes[t * 4 + k]);
    }
    std::vector<std::pair<std::string, std::vector<std::array<Index, 3>>>> boundaries;
    for (const RawBoundary& b : raw_boundaries) {
      std::vector<std::array<Index, 3>> faces(b.elements.size());
      for (std::size_t f = 0; f < faces.size(); ++f) {
        for (std::size_t k = 0; k < 3; ++k) faces[f][k] = boundary_node(b, f, k);
      }
      boundaries.emplace_back(b.name, std::move(faces));
    }
    mesh = make_p2_from_linear(std::move(vertices), tets, boundaries);
  } else {
    mesh.nodes.reserve(new_index.size());
    for (const std::size_t tag : corner_tags) mesh.nodes.push_back(coordinates(tag));
    for (const std::size_t tag : edge_tags) mesh.nodes.push_back(coordinates(tag));
    mesh.num_vertices = num_vertices;
    mesh.tets.resize(num_tets);
    for (std::size_t t = 0; t < num_tets; ++t) {
      for (std::size_t k = 0; k < 10; ++k) {
        mesh.tets[t][k] = new_index.at(tet_nodes[t * 10 + kFromGmshTet10[k]]);
      }
    }
    for (const RawBoundary& b : raw_boundaries) {
      Boundary boundary{b.name, std::vector<Tri6>(b.elements.size())};
      for (std::size_t f = 0; f < boundary.faces.size(); ++f) {
        for (std::size_t k = 0; k < 6; ++k) boundary.faces[f][k] = boundary_node(b, f, k);
      }
      mesh.boundaries.push_back(std::move(boundary));
    }
    orient_tets(mesh);
    orient_boundary_faces(mesh);
  }
  check_mesh(mesh);  // before the node sets are looked up on the tets' edges
  // File tags: corners keep their order in both branches; a linear mesh's edge nodes are new.
  mesh.file_tags.assign(static_cast<std::size_t>(mesh.num_nodes()), -1);
  for (std::size_t i = 0; i < corner_tags.size(); ++i)
    mesh.file_tags[i] = static_cast<Index>(corner_tags[i]);
  if (quadratic) {
    for (std::size_t i = 0; i < edge_tags.size(); ++i)
      mesh.file_tags[corner_tags.size() + i] = static_cast<Index>(edge_tags[i]);
  }
  mesh.node_sets = extract_node_sets(mesh, new_index, coordinates);
  check_node_sets(mesh);
  extract_regions(mesh, tet_elements);
  return mesh;
}

/// The z of the layer interfaces of a swept quarter cylinder (column_layer_z's grading).
std::vector<double> cylinder_layer_z(const QuarterCylinderSpec& spec) {
  ColumnSpec column;
  column.height = spec.height;
  column.nz = spec.layers;
  column.grading_faces = spec.layer_grading_faces;
  column.grading_ratio = spec.layer_grading_ratio;
  return column_layer_z(column);
}

// Surface tags of the quarter cylinder, indexed like kCylinderFaces, found from bounding boxes.
std::vector<int> classify_cylinder_faces(const QuarterCylinderSpec& spec) {
  const double tol = 1e-6 * std::max(spec.radius, spec.height);
  return detail::classify_surfaces(kCylinderFaces, "quarter-cylinder", [&](int tag) {
    double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
    gmsh::model::getBoundingBox(2, tag, x0, y0, z0, x1, y1, z1);
    std::size_t face = 2;  // lateral unless flat in one coordinate
    if (z1 - z0 < tol) {
      face = std::abs(z0) < tol ? 0 : (std::abs(z0 - spec.height) < tol ? 1 : 5);
    } else if (x1 - x0 < tol) {
      face = std::abs(x0) < tol ? 3 : 5;
    } else if (y1 - y0 < tol) {
      face = std::abs(y0) < tol ? 4 : 5;
    }
    return face;
  });
}

}  // namespace

namespace detail {

Mesh mesh_with_gmsh(const GmshSizing& sizing, const std::string& write_msh,
                    const std::function<std::vector<int>()>& build) {
  GmshSession session;
  const std::vector<int> graded_surfaces = build();
  const bool graded = !graded_surfaces.empty() && sizing.grading_ratio > 1.0;
  const double fine = graded ? sizing.lc / sizing.grading_ratio : sizing.lc;
  session.set_number("General.NumThreads", 1);
  session.set_number("Mesh.MaxNumThreads1D", 1);
  session.set_number("Mesh.MaxNumThreads2D", 1);
  session.set_number("Mesh.MaxNumThreads3D", 1);
  session.set_number("Mesh.Algorithm", 6);    // Frontal-Delaunay on surfaces
  session.set_number("Mesh.Algorithm3D", 1);  // Delaunay in the volume
  session.set_number("Mesh.RandomSeed", 1);
  session.set_number("Mesh.Optimize", 1);
  session.set_number("Mesh.OptimizeNetgen", 0);
  session.set_number("Mesh.ElementOrder", 1);
  session.set_number("Mesh.SecondOrderLinear", 0);
  session.set_number("Mesh.HighOrderOptimize", 0);
  session.set_number("Mesh.MeshSizeFactor", 1);
  session.set_number("Mesh.MeshSizeFromCurvature", 0);
  session.set_number("Mesh.MeshSizeFromPoints", 0);
  // gmsh's default (sizes interpolated from the surface mesh into the volume) for uniform
  // meshes; off when graded, where it would spread the fine face size through the volume.
  session.set_number("Mesh.MeshSizeExtendFromBoundary", graded ? 0 : 1);
  session.set_number("Mesh.MeshSizeMin", fine);
  session.set_number("Mesh.MeshSizeMax", sizing.lc);

  if (graded) {
    // Sample each surface densely enough (half the fine size along its longest side) for the
    // distance to be accurate where the size matters.
    const double samples = std::ceil(2.0 * sizing.longest_side / fine) + 1.0;
    const int distance = gmsh::model::mesh::field::add("Distance");
    gmsh::model::mesh::field::setNumbers(
        distance, "SurfacesList",
        std::vector<double>(graded_surfaces.begin(), graded_surfaces.end()));
    gmsh::model::mesh::field::setNumber(distance, "NumPointsPerCurve", samples);
    const int threshold = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMin", fine);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMax", sizing.lc);
    gmsh::model::mesh::field::setNumber(threshold, "DistMin", 0.0);
    gmsh::model::mesh::field::setNumber(threshold, "DistMax", sizing.grading_distance);
    gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
  }

  gmsh::model::mesh::generate(3);
  gmsh::model::mesh::setOrder(2);

  if (!write_msh.empty()) {
    session.set_number("Mesh.MshFileVersion", 4.1);
    session.set_number("Mesh.Binary", 0);
    session.set_number("Mesh.SaveAll", 0);
    std::error_code ec;
    std::filesystem::remove(write_msh, ec);
    gmsh::write(write_msh);
    if (!std::filesystem::is_regular_file(write_msh, ec)) {
      throw std::runtime_error("could not write '" + write_msh + "'");
    }
  }
  // A generated mesh has no file whose node tags messages could refer to (and the mesh cache
  // would not keep them).
  Mesh mesh = extract_current_model();
  mesh.file_tags.clear();
  return mesh;
}

std::vector<int> classify_surfaces(std::span<const char* const> names, const std::string& geometry,
                                   const std::function<std::size_t(int)>& face_of) {
  std::vector<int> tags(names.size(), -1);
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    const std::size_t face = face_of(tag);
    if (face >= tags.size() || tags[face] != -1) {
      throw std::runtime_error("unexpected surface " + std::to_string(tag) + " in the " + geometry +
                               " geometry");
    }
    tags[face] = tag;
  }
  for (std::size_t f = 0; f < tags.size(); ++f) {
    if (tags[f] == -1) {
      throw std::runtime_error(std::string("face '") + names[f] + "' not found");
    }
  }
  return tags;
}

void add_physical_groups(int volume, std::span<const int> surfaces,
                         std::span<const char* const> names) {
  for (std::size_t f = 0; f < surfaces.size(); ++f) {
    const int group = static_cast<int>(f) + 1;
    gmsh::model::addPhysicalGroup(2, {surfaces[f]}, group);
    gmsh::model::setPhysicalName(2, group, names[f]);
  }
  gmsh::model::addPhysicalGroup(3, {volume}, 1);
  gmsh::model::setPhysicalName(3, 1, "domain");
}

Mesh gmsh_quarter_cylinder(const QuarterCylinderSpec& spec) {
  return detail::with_context("generate_quarter_cylinder", [&] {
    const detail::GmshSizing sizing{spec.lc, spec.grading_ratio, spec.grading_distance,
                                    std::max(spec.radius * std::numbers::pi / 2, spec.height)};
    const std::vector<double> layer_z =
        spec.layers > 0 ? cylinder_layer_z(spec) : std::vector<double>{};
    return detail::mesh_with_gmsh(sizing, spec.write_msh, [&] {
      int volume = -1;
      if (layer_z.empty()) {
        volume = gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, spec.height, spec.radius, -1,
                                               std::numbers::pi / 2);
      } else {
        namespace occ = gmsh::model::occ;
        const int centre = occ::addPoint(0, 0, 0);
        const int on_x = occ::addPoint(spec.radius, 0, 0);
        const int on_y = occ::addPoint(0, spec.radius, 0);
        const int loop =
            occ::addCurveLoop({occ::addLine(centre, on_x), occ::addCircleArc(on_x, centre, on_y),
                               occ::addLine(on_y, centre)});
        const int disc = occ::addPlaneSurface({loop});
        // One element per layer; the layer tops as fractions of the height.
        std::vector<int> per_layer(static_cast<std::size_t>(spec.layers), 1);
        std::vector<double> tops(layer_z.begin() + 1, layer_z.end());
        for (double& z : tops) z /= spec.height;
        tops.back() = 1.0;
        gmsh::vectorpair swept;
        occ::extrude({{2, disc}}, 0, 0, spec.height, swept, per_layer, tops, false);
        for (const auto& [dim, tag] : swept)
          if (dim == 3) volume = tag;
      }
      gmsh::model::occ::synchronize();
      const std::vector<int> faces = classify_cylinder_faces(spec);
      detail::add_physical_groups(volume, faces, kCylinderFaces);
      std::vector<int> graded;
      for (const std::string& name : spec.grading_faces) {
        const auto f = std::find(kCylinderFaces.begin(), kCylinderFaces.end(), name);
        graded.push_back(faces[static_cast<std::size_t>(f - kCylinderFaces.begin())]);
      }
      return graded;
    });
  });
}

void with_msh_file(const std::string& path, const std::function<void()>& body) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw std::runtime_error("file does not exist");
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("not a regular file");
  if (!std::ifstream(path)) throw std::runtime_error("file cannot be opened for reading");
  GmshSession session;
  prescan_msh(path);
  gmsh::merge(path);
  body();
}

Mesh gmsh_read(const std::string& path) {
  return detail::with_context("read_gmsh: '" + path + "'", [&] {
    Mesh mesh;
    with_msh_file(path, [&] { mesh = extract_current_model(); });
    return mesh;
  });
}

}  // namespace detail

}  // namespace biphasic
