// A fill-reducing elimination order of a mesh's nodes (tetrahedra or triangles), for direct solvers
// that are handed an order instead of computing one (the parallel MUMPS here has no METIS of its
// own).
#pragma once

#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// The nodes of `mesh` in elimination order: the vertices by METIS nested dissection of the
/// vertex graph (two vertices adjacent when a tetrahedron has both), each edge node right
/// after the earlier of its two end vertices (ties by node number). Deterministic: the same
/// mesh gives the same order on every process. The graph has one vertex per pressure node, so
/// ordering it costs a fraction of ordering the matrix (4 unknowns per vertex, about 10 per
/// vertex with the edge nodes' displacements) and gives the same separators.
std::vector<Index> nested_dissection_node_order(const Mesh& mesh);
/// The same over the triangles of a section mesh.
std::vector<Index> nested_dissection_node_order(const SectionMesh& mesh);

}  // namespace biphasic
