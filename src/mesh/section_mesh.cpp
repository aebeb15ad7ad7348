// Section-mesh queries, orientation fixes and invariant checks (the 2-D counterpart of mesh.cpp).
#include "biphasic/mesh/section_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "section_support.hpp"

namespace biphasic {

namespace {

// Key of the unordered vertex pair {a, b}; vertex indices are below `num_vertices`.
std::uint64_t pair_key(Index a, Index b, Index num_vertices) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo * static_cast<std::uint64_t>(num_vertices) + hi;
}

// Key of the directed vertex pair a → b.
std::uint64_t directed_key(Index a, Index b, Index num_vertices) {
  return static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(num_vertices) +
         static_cast<std::uint64_t>(b);
}

double cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double distance2(const Point2& a, const Point2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  return dx * dx + dy * dy;
}

std::string segment_name(const SectionBoundary& b, std::size_t i) {
  const Line3& s = b.segments[i];
  return "boundary '" + b.name + "' segment " + std::to_string(i) + " (vertices " +
         std::to_string(s[0]) + ", " + std::to_string(s[1]) + ")";
}

// Throws naming `who` and the triangle if one of its corners is not a node index.
void require_corners_in_range(const SectionMesh& mesh, const char* who) {
  const Index nn = mesh.num_nodes();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      if (mesh.triangles[t][c] < 0 || mesh.triangles[t][c] >= nn)
        throw std::runtime_error(std::string(who) + ": triangle " + std::to_string(t) +
                                 " has corner " + std::to_string(mesh.triangles[t][c]) +
                                 " outside [0, " + std::to_string(nn) + ")");
}

[[noreturn]] void fail(const std::string& message) {
  throw std::runtime_error("check_section_mesh: " + message);
}

}  // namespace

const SectionBoundary* SectionMesh::find_boundary(const std::string& name) const {
  const auto it = std::find_if(boundaries.begin(), boundaries.end(),
                               [&](const SectionBoundary& b) { return b.name == name; });
  return it == boundaries.end() ? nullptr : &*it;
}

std::vector<std::string> SectionMesh::boundary_names() const {
  std::vector<std::string> names;
  names.reserve(boundaries.size());
  for (const SectionBoundary& b : boundaries) names.push_back(b.name);
  return names;
}

const NodeSet* SectionMesh::find_node_set(const std::string& name) const {
  const auto it = std::find_if(node_sets.begin(), node_sets.end(),
                               [&](const NodeSet& s) { return s.name == name; });
  return it == node_sets.end() ? nullptr : &*it;
}

std::string SectionMesh::describe_node(Index n) const {
  std::ostringstream s;
  s << "node " << n;
  if (n >= 0 && static_cast<std::size_t>(n) < file_tags.size() && file_tags[n] >= 0)
    s << " (file tag " << file_tags[n] << ")";
  if (n >= 0 && n < num_nodes()) {
    const Point2& x = nodes[static_cast<std::size_t>(n)];
    s << " at (" << x[0] << ", " << x[1] << ") mm";
  }
  return s.str();
}

double triangle_signed_area(const Point2& a, const Point2& b, const Point2& c) {
  return 0.5 * cross(a, b, c);
}

void orient_triangles(SectionMesh& mesh) {
  require_corners_in_range(mesh, "orient_triangles");
  const auto& x = mesh.nodes;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Tri6& tri = mesh.triangles[t];
    const double area = triangle_signed_area(x[tri[0]], x[tri[1]], x[tri[2]]);
    double longest2 = 0.0;
    for (const auto& [a, b] : kTriEdges)
      longest2 = std::max(longest2, distance2(x[tri[a]], x[tri[b]]));
    if (!(std::abs(area) > 1e-12 * longest2)) {
      std::ostringstream msg;
      msg << "orient_triangles: triangle " << t << " is degenerate (area " << area
          << " mm^2, longest edge " << std::sqrt(longest2) << " mm)";
      throw std::runtime_error(msg.str());
    }
    if (area < 0.0) {
      std::swap(tri[1], tri[2]);
      std::swap(tri[3], tri[5]);
    }
  }
}

void orient_boundary_segments(SectionMesh& mesh) {
  require_corners_in_range(mesh, "orient_boundary_segments");
  // For each segment's vertex pair: the third corner of the first triangle having that edge.
  std::map<std::pair<Index, Index>, Index> opposite;
  const auto key = [](Index a, Index b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (const SectionBoundary& b : mesh.boundaries)
    for (const Line3& s : b.segments) opposite.emplace(key(s[0], s[1]), Index{-1});
  if (opposite.empty()) return;
  for (const Tri6& tri : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const auto it = opposite.find(key(tri[kTriEdges[e][0]], tri[kTriEdges[e][1]]));
      if (it != opposite.end() && it->second < 0) it->second = tri[(e + 2) % 3];
    }
  }
  for (SectionBoundary& b : mesh.boundaries) {
    for (std::size_t i = 0; i < b.segments.size(); ++i) {
      Line3& s = b.segments[i];
      const Index opp = opposite.at(key(s[0], s[1]));
      if (opp < 0 || s[0] == s[1]) {
        throw std::runtime_error("orient_boundary_segments: " + segment_name(b, i) +
                                 " is not an edge of any triangle");
      }
      // The triangle's third corner lies on the body's side: it must be left of end 0 → end 1.
      if (cross(mesh.nodes[s[0]], mesh.nodes[s[1]], mesh.nodes[opp]) < 0.0) std::swap(s[0], s[1]);
    }
  }
}

void check_section_mesh(const SectionMesh& mesh) {
  const Index nn = mesh.num_nodes();
  const Index nv = mesh.num_vertices;
  if (nv < 0 || nv > nn) {
    fail("num_vertices " + std::to_string(nv) + " outside [0, " + std::to_string(nn) + "]");
  }
  for (Index n = 0; n < nn; ++n) {
    const Point2& x = mesh.nodes[static_cast<std::size_t>(n)];
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]))
      fail(mesh.describe_node(n) + " has a non-finite coordinate");
  }
  if (!mesh.file_tags.empty() && static_cast<Index>(mesh.file_tags.size()) != nn) {
    fail(std::to_string(mesh.file_tags.size()) + " file tags for " + std::to_string(nn) + " nodes");
  }
  std::vector<char> vertex_used(static_cast<std::size_t>(nv), 0);
  std::vector<char> edge_node_used(static_cast<std::size_t>(nn - nv), 0);
  std::vector<std::uint64_t> edge_node_pair(static_cast<std::size_t>(nn - nv), 0);
  std::unordered_map<std::uint64_t, Index> edge_node;
  std::unordered_set<std::uint64_t> directed;  // edges a → b traversed counter-clockwise
  edge_node.reserve(mesh.triangles.size() * 2);
  directed.reserve(mesh.triangles.size() * 3);

  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Tri6& tri = mesh.triangles[t];
    const std::string where = "triangle " + std::to_string(t);
    for (int c = 0; c < 3; ++c) {
      if (tri[c] < 0 || tri[c] >= nv) {
        fail(where + ": corner " + std::to_string(tri[c]) + " is not a vertex index (0 to " +
             std::to_string(nv - 1) + ")");
      }
      vertex_used[tri[c]] = 1;
      for (int d = 0; d < c; ++d) {
        if (tri[c] == tri[d]) fail(where + ": repeated corner " + std::to_string(tri[c]));
      }
    }
    for (std::size_t e = 0; e < kTriEdges.size(); ++e) {
      const Index n = tri[3 + e];
      if (n < nv || n >= nn) {
        fail(where + ": edge node " + std::to_string(n) + " is not an edge-node index (" +
             std::to_string(nv) + " to " + std::to_string(nn - 1) + ")");
      }
      const Index a = tri[kTriEdges[e][0]], b = tri[kTriEdges[e][1]];
      const std::uint64_t key = pair_key(a, b, nv);
      const auto [it, inserted] = edge_node.emplace(key, n);
      if (!inserted && it->second != n) {
        fail(where + ": edge node " + std::to_string(n) + " differs from node " +
             std::to_string(it->second) + " used by another triangle on the same edge");
      }
      const std::size_t slot = static_cast<std::size_t>(n - nv);
      if (edge_node_used[slot] && edge_node_pair[slot] != key) {
        fail(where + ": edge node " + std::to_string(n) + " sits on two different edges");
      }
      edge_node_used[slot] = 1;
      edge_node_pair[slot] = key;
      directed.insert(directed_key(a, b, nv));
    }
    const double area =
        triangle_signed_area(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]);
    if (!(area > 0.0)) {
      std::ostringstream msg;
      msg << where << ": non-positive area " << area << " mm^2 (clockwise or degenerate corners "
          << tri[0] << ", " << tri[1] << ", " << tri[2] << ")";
      fail(msg.str());
    }
  }
  for (Index v = 0; v < nv; ++v) {
    if (!vertex_used[v]) fail("vertex " + std::to_string(v) + " is a corner of no triangle");
  }
  for (Index n = nv; n < nn; ++n) {
    if (!edge_node_used[n - nv]) fail("edge node " + std::to_string(n) + " belongs to no triangle");
  }

  for (std::size_t k = 0; k < mesh.boundaries.size(); ++k) {
    const SectionBoundary& b = mesh.boundaries[k];
    if (b.name.empty()) fail("boundary " + std::to_string(k) + " has an empty name");
    for (std::size_t j = 0; j < k; ++j)
      if (mesh.boundaries[j].name == b.name) fail("two boundaries are named '" + b.name + "'");
    for (std::size_t i = 0; i < b.segments.size(); ++i) {
      const Line3& s = b.segments[i];
      const std::string where = segment_name(b, i);
      for (int c = 0; c < 2; ++c) {
        if (s[c] < 0 || s[c] >= nv) {
          fail(where + ": end " + std::to_string(s[c]) + " is not a vertex index");
        }
      }
      const auto it = edge_node.find(pair_key(s[0], s[1], nv));
      if (s[0] == s[1] || it == edge_node.end()) fail(where + " is not an edge of any triangle");
      if (it->second != s[2]) {
        fail(where + ": midside node " + std::to_string(s[2]) + " differs from the triangles' " +
             std::to_string(it->second));
      }
      if (!directed.count(directed_key(s[0], s[1], nv))) {
        fail(where + " has the body on its right (its ends are swapped)");
      }
    }
  }

  // Boundary conditions name a curve or a point: a name given to two of them would be resolved
  // silently to one.
  for (std::size_t i = 0; i < mesh.node_sets.size(); ++i) {
    const NodeSet& s = mesh.node_sets[i];
    const std::string where = "node set '" + s.name + "'";
    if (s.name.empty()) fail("node set " + std::to_string(i) + " has an empty name");
    for (const Index n : s.nodes)
      if (n < 0 || n >= nn) fail(where + ": node " + std::to_string(n) + " is not a node index");
    if (mesh.find_boundary(s.name)) {
      fail("the name '" + s.name +
           "' is given to a boundary curve and a node set; rename one of them");
    }
    for (std::size_t j = 0; j < i; ++j)
      if (mesh.node_sets[j].name == s.name) fail("two node sets are named '" + s.name + "'");
  }

  if (mesh.triangle_region.empty()) {
    if (mesh.region_names.size() > 1)
      fail(std::to_string(mesh.region_names.size()) + " region names but no region per triangle");
  } else {
    if (mesh.triangle_region.size() != mesh.triangles.size())
      fail(std::to_string(mesh.triangle_region.size()) + " region entries for " +
           std::to_string(mesh.triangles.size()) + " triangles");
    const auto count = static_cast<int>(mesh.region_names.size());
    for (std::size_t t = 0; t < mesh.triangle_region.size(); ++t)
      if (mesh.triangle_region[t] < 0 || mesh.triangle_region[t] >= count)
        fail("triangle " + std::to_string(t) + ": region " +
             std::to_string(mesh.triangle_region[t]) + " is not below the number of regions, " +
             std::to_string(count));
  }
  for (std::size_t a = 0; a < mesh.region_names.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
      if (mesh.region_names[a] == mesh.region_names[b])
        fail("two regions are named '" + mesh.region_names[a] + "'");
}

namespace detail {

SectionMesh section_p2_from_linear(std::vector<Point2> vertices,
                                   const std::vector<std::array<Index, 3>>& triangles,
                                   const std::vector<LinearCurve>& curves) {
  SectionMesh mesh;
  mesh.nodes = std::move(vertices);
  mesh.num_vertices = mesh.num_nodes();
  const Index nv = mesh.num_vertices;

  // One edge node per unique vertex pair, numbered in order of first use.
  std::unordered_map<std::uint64_t, Index> edge_node;
  edge_node.reserve(triangles.size() * 2);
  mesh.triangles.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Tri6 tri{};
    for (int c = 0; c < 3; ++c) {
      const Index v = triangles[t][c];
      if (v < 0 || v >= nv) {
        throw std::runtime_error("triangle " + std::to_string(t) + " has corner " +
                                 std::to_string(v) + " outside [0, " + std::to_string(nv) + ")");
      }
      tri[c] = v;
    }
    for (std::size_t e = 0; e < kTriEdges.size(); ++e) {
      const Index a = tri[kTriEdges[e][0]], b = tri[kTriEdges[e][1]];
      const auto [it, inserted] = edge_node.emplace(pair_key(a, b, nv), mesh.num_nodes());
      if (inserted) {
        const Point2& pa = mesh.nodes[a];
        const Point2& pb = mesh.nodes[b];
        mesh.nodes.push_back({0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])});
      }
      tri[3 + e] = it->second;
    }
    mesh.triangles.push_back(tri);
  }

  for (const auto& [name, segments] : curves) {
    SectionBoundary boundary{name, {}};
    boundary.segments.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Index a = segments[i][0], b = segments[i][1];
      const auto it = a >= 0 && a < nv && b >= 0 && b < nv && a != b
                          ? edge_node.find(pair_key(a, b, nv))
                          : edge_node.end();
      if (it == edge_node.end()) {
        throw std::runtime_error("curve '" + name + "' segment " + std::to_string(i) +
                                 " (vertices " + std::to_string(a) + ", " + std::to_string(b) +
                                 ") is not an edge of any triangle");
      }
      boundary.segments.push_back({a, b, it->second});
    }
    mesh.boundaries.push_back(std::move(boundary));
  }
  orient_triangles(mesh);
  orient_boundary_segments(mesh);
  return mesh;
}

}  // namespace detail

}  // namespace biphasic
