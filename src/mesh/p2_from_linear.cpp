// Quadratic (P2) mesh from linear tetrahedra: one straight-midpoint node per unique edge.
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace biphasic {

namespace {

std::uint64_t pair_key(Index a, Index b, Index num_vertices) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo * static_cast<std::uint64_t>(num_vertices) + hi;
}

std::string corner_list(const Index* corners, int count) {
  std::string s;
  for (int i = 0; i < count; ++i) s += (i ? ", " : "") + std::to_string(corners[i]);
  return s;
}

}  // namespace

Mesh make_p2_from_linear(
    std::vector<Point> vertices, const std::vector<std::array<Index, 4>>& tets,
    const std::vector<std::pair<std::string, std::vector<std::array<Index, 3>>>>& boundaries) {
  const Index num_input = static_cast<Index>(vertices.size());

  // Keep only vertices that are tet corners, in their input order.
  std::vector<Index> new_index(vertices.size(), -1);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (const Index v : tets[t]) {
      if (v < 0 || v >= num_input) {
        throw std::runtime_error("make_p2_from_linear: tetrahedron " + std::to_string(t) +
                                 " has corner " + std::to_string(v) + " outside [0, " +
                                 std::to_string(num_input) + ")");
      }
      new_index[v] = 0;
    }
  }
  Mesh mesh;
  for (Index v = 0; v < num_input; ++v) {
    if (new_index[v] < 0) continue;
    new_index[v] = static_cast<Index>(mesh.nodes.size());
    mesh.nodes.push_back(vertices[v]);
  }
  mesh.num_vertices = mesh.num_nodes();
  const Index nv = mesh.num_vertices;

  // One edge node per unique vertex pair, numbered in order of first use.
  std::unordered_map<std::uint64_t, Index> edge_node;
  edge_node.reserve(tets.size() * 2);
  mesh.tets.reserve(tets.size());
  for (const auto& corners : tets) {
    Tet10 tet{};
    for (int c = 0; c < 4; ++c) tet[c] = new_index[corners[c]];
    for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
      const Index a = tet[kTetEdges[e][0]];
      const Index b = tet[kTetEdges[e][1]];
      const auto [it, inserted] = edge_node.emplace(pair_key(a, b, nv), mesh.num_nodes());
      if (inserted) {
        const Point& pa = mesh.nodes[a];
        const Point& pb = mesh.nodes[b];
        mesh.nodes.push_back({0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])});
      }
      tet[4 + e] = it->second;
    }
    mesh.tets.push_back(tet);
  }

  for (const auto& [name, faces] : boundaries) {
    Boundary boundary{name, {}};
    boundary.faces.reserve(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const auto& corners = faces[i];
      const std::string where = "make_p2_from_linear: boundary '" + name + "' face " +
                                std::to_string(i) + " (vertices " + corner_list(corners.data(), 3) +
                                ")";
      Tri6 face{};
      for (int c = 0; c < 3; ++c) {
        const Index v = corners[c];
        if (v < 0 || v >= num_input || new_index[v] < 0) {
          throw std::runtime_error(where + ": vertex " + std::to_string(v) +
                                   " is not a corner of any tetrahedron");
        }
        face[c] = new_index[v];
      }
      for (std::size_t e = 0; e < kTriEdges.size(); ++e) {
        const Index a = face[kTriEdges[e][0]];
        const Index b = face[kTriEdges[e][1]];
        const auto it = edge_node.find(pair_key(a, b, nv));
        if (a == b || it == edge_node.end()) {
          throw std::runtime_error(where + ": edge (" + std::to_string(corners[kTriEdges[e][0]]) +
                                   ", " + std::to_string(corners[kTriEdges[e][1]]) +
                                   ") is not an edge of any tetrahedron");
        }
        face[3 + e] = it->second;
      }
      boundary.faces.push_back(face);
    }
    mesh.boundaries.push_back(std::move(boundary));
  }

  orient_tets(mesh);
  orient_boundary_faces(mesh);
  return mesh;
}

}  // namespace biphasic
