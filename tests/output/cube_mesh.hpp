// Hand-built P2 test mesh: a cube of edge length L [mm] cut into 6 tetrahedra around the
// diagonal from (0,0,0) to (L,L,L), with edge nodes at the edge midpoints (27 nodes in all).
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <utility>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic::test {

/// Vertex v = i + 2j + 4k sits at (iL, jL, kL). Edge nodes are numbered in order of first use.
inline Mesh make_cube_mesh(double edge_length) {
  Mesh mesh;
  for (int v = 0; v < 8; ++v) {
    mesh.nodes.push_back(
        {edge_length * (v & 1), edge_length * ((v >> 1) & 1), edge_length * ((v >> 2) & 1)});
  }
  mesh.num_vertices = 8;

  std::map<std::pair<Index, Index>, Index> edge_node;
  std::array<int, 3> axes{0, 1, 2};
  do {
    // Path 0 -> +e_a0 -> +e_a1 -> 7 through the cube corners.
    const Index v1 = Index{1} << axes[0];
    const Index v2 = v1 + (Index{1} << axes[1]);
    Tet10 tet{};
    tet[0] = 0;
    tet[1] = v1;
    tet[2] = v2;
    tet[3] = 7;
    const auto& x0 = mesh.nodes[0];
    auto vec = [&](Index v) {
      const auto& x = mesh.nodes[static_cast<std::size_t>(v)];
      return std::array<double, 3>{x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    };
    const auto a = vec(tet[1]), b = vec(tet[2]), c = vec(tet[3]);
    const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0]);
    if (det < 0) std::swap(tet[1], tet[2]);
    for (std::size_t k = 0; k < kTetEdges.size(); ++k) {
      Index p = tet[kTetEdges[k][0]], q = tet[kTetEdges[k][1]];
      if (q < p) std::swap(p, q);
      auto [it, inserted] = edge_node.try_emplace({p, q}, static_cast<Index>(mesh.nodes.size()));
      if (inserted) {
        const auto& xp = mesh.nodes[static_cast<std::size_t>(p)];
        const auto& xq = mesh.nodes[static_cast<std::size_t>(q)];
        mesh.nodes.push_back({0.5 * (xp[0] + xq[0]), 0.5 * (xp[1] + xq[1]), 0.5 * (xp[2] + xq[2])});
      }
      tet[4 + k] = it->second;
    }
    mesh.tets.push_back(tet);
  } while (std::next_permutation(axes.begin(), axes.end()));
  return mesh;
}

}  // namespace biphasic::test
