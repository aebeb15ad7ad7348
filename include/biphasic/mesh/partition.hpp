// Splitting a mesh among processes (docs/parallel.md): which part owns each element and node,
// the rank-major numbering of the unknowns across parts, and each part's own view of the mesh
// (its elements plus one layer of neighbours). Tetrahedral meshes (Mesh) and the triangular
// meshes of the two-dimensional models (SectionMesh) split alike.
//
// Ownership. Elements go to parts by METIS's dual-graph partitioning (elements adjacent through
// a face, or an edge of triangles; corners only), which balances element counts and keeps the
// shared surfaces small. A node belongs to the lowest-numbered part among the elements that
// contain it, so its owner always assembles some of its rows.
//
// Unknowns across parts. Part r owns one contiguous range of the unknowns: the displacements of
// its nodes, interlaced per node (3 per node on tetrahedra, 2 on triangles: the displacement
// block's block size), then the pressures of its vertices; the ranges follow in part order.
// Within a part, nodes keep their order in the mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// Elements and nodes of a mesh assigned to `parts` parts.
struct MeshPartition {
  int parts = 1;
  std::vector<int> element_part;  ///< per element (tetrahedron or triangle), its part
  std::vector<int> node_owner;    ///< per node, the lowest part among the elements containing it
};

/// Sets `partition.node_owner` from its `element_part`: each node's lowest part among the
/// elements containing it. Throws std::runtime_error for a node in no element.
void assign_node_owners(const Mesh& mesh, MeshPartition& partition);
void assign_node_owners(const SectionMesh& mesh, MeshPartition& partition);

/// Partitions the elements into `parts` parts with METIS_PartMeshDual (corners only, parts
/// sharing faces of tetrahedra or edges of triangles; 1 part: every element in part 0). Throws
/// std::invalid_argument if parts < 1 or parts exceeds the number of elements,
/// std::runtime_error if METIS fails or leaves a part empty.
MeshPartition partition_mesh(const Mesh& mesh, int parts);
MeshPartition partition_mesh(const SectionMesh& mesh, int parts);

/// The unknowns of the partitioned mesh, numbered rank-major (see above).
struct PartitionedNumbering {
  int components = 3;                 ///< displacement unknowns per node (3, or 2 on triangles)
  std::vector<Index> offset;          ///< first unknown of each part; offset[parts] = total
  std::vector<Index> u_base;          ///< per node: the unknown of its first displacement (the
                                      ///< others follow)
  std::vector<Index> p_index;         ///< per node: the unknown of its pressure (−1: edge node)
  std::vector<Index> owned_nodes;     ///< per part, how many nodes it owns
  std::vector<Index> owned_vertices;  ///< per part, how many vertices it owns
  Index size() const { return offset.back(); }
};

/// The rank-major numbering of `partition` on `mesh` (3 displacement unknowns per node of a
/// tetrahedral mesh, 2 per node of a triangular one, and one pressure per vertex).
PartitionedNumbering number_unknowns(const Mesh& mesh, const MeshPartition& partition);
PartitionedNumbering number_unknowns(const SectionMesh& mesh, const MeshPartition& partition);

/// For each unknown of the one-process layout (u of node n at d·n + c with d = 3 or 2
/// components, then p of vertex v at d·num_nodes + v), its unknown in the rank-major numbering
/// (`num_vertices` vertices, as many nodes as `numbering` has).
std::vector<Index> rank_major_of_whole(Index num_vertices, const PartitionedNumbering& numbering);

/// The unknowns of `numbering` in the elimination order of `node_order` (a permutation of the
/// nodes, such as nested_dissection_node_order gives): each node's displacements, then its
/// pressure if it has one.
std::vector<Index> unknown_order(const PartitionedNumbering& numbering,
                                 const std::vector<Index>& node_order);

/// What one part's view of a mesh knows of the whole, whatever its element type.
struct SubdomainMap {
  int part = 0;
  std::vector<Index> global_node;     ///< per node of the part's mesh, its node in the whole mesh
  std::vector<Index> global_element;  ///< per element of the part's mesh, its index in the whole
  std::vector<char> element_owned;    ///< per element: in this part (assembled here)
  std::vector<char> node_owned;       ///< per node: owned by this part
  std::vector<char> node_touched;     ///< per node: a corner or edge node of an owned element
};

/// One part's view of the mesh. Its mesh holds the part's own elements and every element
/// sharing a node with one of them (the ghost layer), so that each node an owned element
/// touches has every element and boundary face (or segment) around it here: its Dirichlet
/// conditions and face loads are known in full. Boundaries keep the faces (segments) of these
/// elements, node sets their nodes here (possibly none), regions their names. Vertices come
/// first, as the meshes require.
struct Subdomain : SubdomainMap {
  Mesh mesh;
};
struct SectionSubdomain : SubdomainMap {
  SectionMesh mesh;
};

/// Part `part`'s view of `mesh` under `partition`.
Subdomain extract_subdomain(const Mesh& mesh, const MeshPartition& partition, int part);
SectionSubdomain extract_subdomain(const SectionMesh& mesh, const MeshPartition& partition,
                                   int part);

}  // namespace biphasic
