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

/// A named set of mesh nodes from a gmsh physical point (dimension 0) or physical curve
/// (dimension 1): every node on it, edge nodes of the curve's segments included. Displacement
/// conditions may act on it (to pin a point or hold a line).
struct NodeSet {
  std::string name;
  int dimension = 0;  ///< 0: physical point, 1: physical curve
  std::vector<Index> nodes;
};

/// P2 tetrahedral mesh. Invariant: the first `num_vertices` entries of `nodes` are element
/// corners (they carry the P1 pressure); the rest are edge nodes. Every tetrahedron has a
/// positive volume in the local order above.
struct Mesh {
  std::vector<Point> nodes;  ///< node coordinates [mm]
  Index num_vertices = 0;    ///< corner nodes come first
  std::vector<Tet10> tets;
  std::vector<Boundary> boundaries;
  /// Physical points and curves of a .msh file (generated meshes have none; the mesh cache
  /// does not store them).
  std::vector<NodeSet> node_sets;
  /// Per node, its tag in the .msh file it was read from (−1 for an edge node made here);
  /// empty for generated meshes. Messages name nodes by this tag when there is one.
  std::vector<Index> file_tags;
  /// Material regions: per tetrahedron, an index into `region_names`. Both empty: one unnamed
  /// region. A .msh file's physical volumes become regions (docs/model_layer.md, *Regions*);
  /// the column generator makes them from mesh.column.regions.
  std::vector<int> tet_region;
  std::vector<std::string> region_names;

  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  /// The boundary with this name, or nullptr.
  const Boundary* find_boundary(const std::string& name) const;
  /// Names of all boundaries, in stored order.
  std::vector<std::string> boundary_names() const;
  /// Region index of tetrahedron t (0 when the mesh has no regions).
  int region_of(Index t) const { return tet_region.empty() ? 0 : tet_region[t]; }
  /// The index of the region with this name, or −1.
  int find_region(const std::string& name) const;
  /// The node set with this name, or nullptr.
  const NodeSet* find_node_set(const std::string& name) const;
  /// "node 12 (file tag 40) at (1, 2, 3) mm": how messages name node n.
  std::string describe_node(Index n) const;
};

/// Signed volume [mm³] of the straight tetrahedron (a, b, c, d): positive when
/// (b − a, c − a, d − a) is a right-handed triple.
double tet_signed_volume(const Point& a, const Point& b, const Point& c, const Point& d);

/// Signed volume [mm³] of tetrahedron `t` of `mesh` computed from its four corners.
double tet_signed_volume(const Mesh& mesh, Index t);

/// Gives every tetrahedron a positive volume in the local order above: where the corner
/// volume is negative, swaps local vertices 1 and 2 together with edge nodes 4↔6 and 8↔9.
/// Throws std::runtime_error naming the tetrahedron index and its volume if it is
/// degenerate (|volume| ≤ 1e-12 · longest edge³).
void orient_tets(Mesh& mesh);

/// Orients every boundary face so that its normal (right-hand rule on corners 0, 1, 2)
/// points out of a tetrahedron having that face; swaps corners 1 and 2 and edge nodes
/// 3↔5 where needed. Node indices must be in range. Throws std::runtime_error naming the
/// boundary and the face if a face belongs to no tetrahedron.
void orient_boundary_faces(Mesh& mesh);

/// Checks every Mesh invariant: indices in range, corners < num_vertices ≤ edge nodes, every
/// vertex is a corner of some tet, one edge node per vertex pair shared by all tets and
/// boundary faces using that edge, boundary corners are vertices, positive tet volumes, node
/// sets' nodes in range, no name shared by two sets (surface, point or curve), and regions
/// consistent (one index per tet below the number of names, names distinct). Throws
/// std::runtime_error describing the first violation found.
void check_mesh(const Mesh& mesh);

/// The node-set part of check_mesh alone: nodes in range, no name shared by a surface, point
/// or curve. For a mesh whose other invariants check_mesh has already confirmed.
void check_node_sets(const Mesh& mesh);

/// The region part of check_mesh alone: tet_region empty or one entry per tet, each an index
/// into region_names, names distinct.
void check_regions(const Mesh& mesh);

}  // namespace biphasic
