// Quadratic tetrahedral mesh with named boundary faces (mm).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace biphasic {

using Index = std::int64_t;
using Point = std::array<double, 3>;

/// Local node order of a 10-node tetrahedron (same as VTK / XDMF Tetrahedron_10):
/// 0–3 vertices, 4:(0,1) 5:(1,2) 6:(0,2) 7:(0,3) 8:(1,3) 9:(2,3) edge nodes.
/// gmsh's order differs only by swapping the last two nodes.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};

/// Local node order of a 6-node triangle (gmsh and VTK agree):
/// 0–2 vertices, 3:(0,1) 4:(1,2) 5:(2,0).
inline constexpr std::array<std::array<int, 2>, 3> kTriEdges{{{0, 1}, {1, 2}, {2, 0}}};

using Tet10 = std::array<Index, 10>;
using Tri6 = std::array<Index, 6>;

/// A named boundary (a gmsh physical surface) as a set of 6-node faces.
struct Boundary {
  std::string name;
  std::vector<Tri6> faces;
};

/// P2 tetrahedral mesh. Invariant: the first `num_vertices` entries of `nodes` are element
/// corners (they carry the P1 pressure); the rest are edge nodes. Every tetrahedron has a
/// positive volume in the local order above.
struct Mesh {
  std::vector<Point> nodes;  ///< node coordinates [mm]
  Index num_vertices = 0;    ///< corner nodes come first
  std::vector<Tet10> tets;
  std::vector<Boundary> boundaries;

  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  /// The boundary with this name, or nullptr.
  const Boundary* find_boundary(const std::string& name) const;
  /// Names of all boundaries, in stored order.
  std::vector<std::string> boundary_names() const;
};

}  // namespace biphasic
