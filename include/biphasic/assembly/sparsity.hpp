// Degrees of freedom and the fixed CSC pattern of the P2/P1 system, built once per mesh.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_matrix.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/biphasic_element.hpp"
#include "biphasic/physics/section_element.hpp"

namespace biphasic {

/// Extra coupling beyond the elements: every unknown of `node` couples with every unknown of
/// each of `nodes` (both ways). A rigid platen's master node couples so with the nodes next to
/// the platen (physics/rigid_platen.hpp). The fill-reducing order places `node` last.
struct NodeCoupling {
  Index node;
  std::vector<Index> nodes;
};

/// Unknowns y = (u of every node, node-major: dn + c; then p of every vertex: dN + v), with
/// d = components() displacement components per node (3 on a tetrahedral mesh, 2 on a section
/// mesh). The CSC pattern couples every pair of unknowns that share an element (all four blocks
/// u–u, u–p, p–u, p–p); row indices are sorted within each column.
class SparsityPattern {
 public:
  explicit SparsityPattern(const Mesh& mesh, const std::vector<NodeCoupling>& couplings = {});
  /// The pattern of a two-dimensional model: two displacement components per node.
  explicit SparsityPattern(const SectionMesh& mesh,
                           const std::vector<NodeCoupling>& couplings = {});

  Index size() const { return num_dofs_; }
  /// Displacement components per node (3 or 2).
  int components() const { return components_; }
  Index num_u() const { return components_ * num_nodes_; }
  Index nnz() const { return static_cast<Index>(rowind_.size()); }
  Index u_dof(Index node, int c) const { return components_ * node + c; }
  Index p_dof(Index vertex) const { return components_ * num_nodes_ + vertex; }
  /// Global unknown of local element dof s (0–29: u of node s/3, component s%3; 30–33: p).
  Index global_dof(const Tet10& tet, int s) const {
    return s < 30 ? 3 * tet[s / 3] + s % 3 : 3 * num_nodes_ + tet[s - 30];
  }
  /// Global unknown of local dof s of a triangle (0–11: u of node s/2, component s%2; 12–14: p).
  Index global_dof(const Tri6& tri, int s) const {
    return s < 12 ? 2 * tri[s / 2] + s % 2 : 2 * num_nodes_ + tri[s - 12];
  }
  const std::vector<Index>& colptr() const { return colptr_; }
  const std::vector<Index>& rowind() const { return rowind_; }
  /// Nodes sharing an element with node n (n included), sorted; vertices come first.
  std::pair<const Index*, const Index*> node_neighbours(Index n) const {
    return {adj_.data() + adj_ptr_[n], adj_.data() + adj_ptr_[n + 1]};
  }
  Index num_nodes() const { return num_nodes_; }
  Index num_vertices() const { return num_vertices_; }
  /// Fill-reducing order of the unknowns: METIS nested dissection of the vertex graph (the
  /// P1 mesh, ~7 times smaller than the P2 node graph and ~30 times smaller than the matrix
  /// graph), each edge node placed right after the first-eliminated of its two end vertices,
  /// each node's unknowns kept together. Every edge node then lies in the subdomain or
  /// separator of that vertex, so the order is a nested dissection of the node graph too: as
  /// little fill as METIS on the node graph (within ±7 % in flops on the paper's meshes), at a
  /// tenth of the ordering time. The nodes of extra couplings (NodeCoupling) come last.
  /// order[k] = unknown placed k-th.
  std::vector<Index> nested_dissection_order() const;

  /// A new SUNSparseMatrix (CSC) holding this pattern, values zero; the caller destroys it.
  SUNMatrix new_matrix(SUNContext ctx) const;
  /// Writes the pattern's index arrays into A (KINSOL and IDA zero them with the values
  /// before every Jacobian call).
  void restore_into(SUNMatrix A) const;

  /// Position in the value array of entry (row, col); −1 if outside the pattern.
  Index find(Index row, Index col) const;

  /// Adds A + c·B of an element into `values` (the CSC value array), skipping rows flagged
  /// in `skip_row` (Dirichlet rows).
  void scatter(Index element, const Tet10& tet, const ElementMatrix& A, const ElementMatrix& B,
               double c, const std::vector<char>& skip_row, double* values) const;
  /// The same for a triangle of a section mesh.
  void scatter(Index element, const Tri6& tri, const SectionElementMatrix& A,
               const SectionElementMatrix& B, double c, const std::vector<char>& skip_row,
               double* values) const;

 private:
  /// Neighbourhoods, columns, edge ends and local positions of a P2 mesh whose elements list
  /// their corners first, then one node per edge of `edges`.
  template <class Element, std::size_t NumEdges>
  void build(const std::vector<Element>& elements,
             const std::array<std::array<int, 2>, NumEdges>& edges,
             const std::vector<NodeCoupling>& couplings);

  int components_ = 3;
  Index num_nodes_ = 0, num_vertices_ = 0, num_dofs_ = 0;
  std::vector<Index> adj_ptr_, adj_;  ///< sorted node neighbourhoods (vertices sort first)
  std::vector<Index> colptr_, rowind_;
  std::vector<std::array<std::int32_t, 100>> local_pos_;  ///< [a·10+b] = index of b in adj(a)
  std::vector<std::array<Index, 2>> edge_ends_;  ///< end vertices of edge node num_vertices_ + i
  std::vector<Index> late_nodes_;                ///< coupled nodes, ordered last
};

}  // namespace biphasic
