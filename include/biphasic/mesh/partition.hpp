// Splitting a tetrahedral mesh among processes (docs/parallel.md): which part owns each
// element and node, the rank-major numbering of the unknowns across parts, and each part's own
// view of the mesh (its elements plus one layer of neighbours).
//
// Ownership. Elements go to parts by METIS's dual-graph partitioning (elements adjacent through
// a face, corners only), which balances element counts and keeps the shared surfaces small. A
// node belongs to the lowest-numbered part among the elements that contain it, so its owner
// always assembles some of its rows.
//
// Unknowns across parts. Part r owns one contiguous range of the unknowns: the displacements of
// its nodes, interlaced per node (3 per node, so the displacement block has block size 3), then
// the pressures of its vertices; the ranges follow in part order. Within a part, nodes keep
// their order in the mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// Elements and nodes of a mesh assigned to `parts` parts.
struct MeshPartition {
  int parts = 1;
  std::vector<int> tet_part;    ///< per tetrahedron, its part
  std::vector<int> node_owner;  ///< per node, the lowest part among the elements containing it
};

/// Sets `partition.node_owner` from its `tet_part`: each node's lowest part among the elements
/// containing it. Throws std::runtime_error for a node in no tetrahedron.
void assign_node_owners(const Mesh& mesh, MeshPartition& partition);

/// Partitions the tetrahedra into `parts` parts with METIS_PartMeshDual (corners only, parts
/// sharing faces; 1 part: every element in part 0). Throws std::invalid_argument if parts < 1
/// or parts exceeds the number of tetrahedra, std::runtime_error if METIS fails.
MeshPartition partition_mesh(const Mesh& mesh, int parts);

/// The unknowns of the partitioned mesh, numbered rank-major (see above).
struct PartitionedNumbering {
  std::vector<Index> offset;          ///< first unknown of each part; offset[parts] = total
  std::vector<Index> u_base;          ///< per node: the unknown of its x displacement (y, z follow)
  std::vector<Index> p_index;         ///< per node: the unknown of its pressure (−1: edge node)
  std::vector<Index> owned_nodes;     ///< per part, how many nodes it owns
  std::vector<Index> owned_vertices;  ///< per part, how many vertices it owns
  Index size() const { return offset.back(); }
};

/// The rank-major numbering of `partition` on `mesh` (3 displacement unknowns per node and one
/// pressure per vertex).
PartitionedNumbering number_unknowns(const Mesh& mesh, const MeshPartition& partition);

/// For each unknown of the one-process layout (u of node n at 3n + c, then p of vertex v at
/// 3 num_nodes + v), its unknown in the rank-major numbering.
std::vector<Index> rank_major_of_whole(const Mesh& mesh, const PartitionedNumbering& numbering);

/// The unknowns of `numbering` in the elimination order of `node_order` (a permutation of the
/// nodes, such as nested_dissection_node_order gives): each node's three displacements, then
/// its pressure if it has one.
std::vector<Index> unknown_order(const PartitionedNumbering& numbering,
                                 const std::vector<Index>& node_order);

/// One part's view of the mesh. Its mesh holds the part's own tetrahedra and every tetrahedron
/// sharing a node with one of them (the ghost layer), so that each node an owned element
/// touches has every element and boundary face around it here: its Dirichlet conditions and
/// face loads are known in full. Boundaries keep the faces of these tetrahedra, node sets their
/// nodes here (possibly none), regions their names. Vertices come first, as Mesh requires.
struct Subdomain {
  int part = 0;
  Mesh mesh;
  std::vector<Index> global_node;  ///< per node of `mesh`, its node in the whole mesh
  std::vector<Index> global_tet;   ///< per tetrahedron of `mesh`, its index in the whole mesh
  std::vector<char> tet_owned;     ///< per tetrahedron: in this part (assembled here)
  std::vector<char> node_owned;    ///< per node: owned by this part
  std::vector<char> node_touched;  ///< per node: a corner or edge node of an owned tetrahedron
};

/// Part `part`'s view of `mesh` under `partition`.
Subdomain extract_subdomain(const Mesh& mesh, const MeshPartition& partition, int part);

}  // namespace biphasic
