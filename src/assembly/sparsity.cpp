#include "biphasic/assembly/sparsity.hpp"

#include <metis.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace biphasic {

SparsityPattern::SparsityPattern(const Mesh& mesh, const std::vector<NodeCoupling>& couplings)
    : components_(3),
      num_nodes_(mesh.num_nodes()),
      num_vertices_(mesh.num_vertices),
      num_dofs_(3 * mesh.num_nodes() + mesh.num_vertices) {
  build(mesh.tets, kTetEdges, couplings);
}

SparsityPattern::SparsityPattern(const SectionMesh& mesh,
                                 const std::vector<NodeCoupling>& couplings)
    : components_(2),
      num_nodes_(mesh.num_nodes()),
      num_vertices_(mesh.num_vertices),
      num_dofs_(2 * mesh.num_nodes() + mesh.num_vertices) {
  build(mesh.triangles, kTriEdges, couplings);
}

template <class Element, std::size_t NumEdges>
void SparsityPattern::build(const std::vector<Element>& elements,
                            const std::array<std::array<int, 2>, NumEdges>& edges,
                            const std::vector<NodeCoupling>& couplings) {
  constexpr int kNodes = static_cast<int>(std::tuple_size_v<Element>);
  constexpr int kCorners = kNodes - static_cast<int>(NumEdges);
  const Index d = components_;
  // Node neighbourhoods through shared elements (each node is its own neighbour).
  std::vector<std::vector<Index>> adj(num_nodes_);
  for (const Element& t : elements)
    for (Index a : t)
      for (Index b : t) adj[a].push_back(b);
  for (const NodeCoupling& c : couplings) {
    if (c.node < 0 || c.node >= num_nodes_)
      throw std::invalid_argument("SparsityPattern: coupled node " + std::to_string(c.node) +
                                  " is not a node of the mesh");
    for (Index n : c.nodes) {
      if (n < 0 || n >= num_nodes_)
        throw std::invalid_argument("SparsityPattern: coupled node " + std::to_string(n) +
                                    " is not a node of the mesh");
      adj[c.node].push_back(n);
      adj[n].push_back(c.node);
    }
    adj[c.node].push_back(c.node);
    late_nodes_.push_back(c.node);
  }
  adj_ptr_.assign(num_nodes_ + 1, 0);
  for (Index n = 0; n < num_nodes_; ++n) {
    auto& list = adj[n];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    adj_ptr_[n + 1] = adj_ptr_[n] + static_cast<Index>(list.size());
  }
  adj_.reserve(adj_ptr_.back());
  for (auto& list : adj) {
    adj_.insert(adj_.end(), list.begin(), list.end());
    std::vector<Index>().swap(list);
  }

  // Column of a node's unknowns: u rows of every neighbour, then p rows of neighbour vertices.
  // Vertices are numbered first, so they are a prefix of each sorted neighbourhood.
  auto column_length = [&](Index n) {
    const Index deg = adj_ptr_[n + 1] - adj_ptr_[n];
    const Index* begin = adj_.data() + adj_ptr_[n];
    const Index nv = std::lower_bound(begin, begin + deg, num_vertices_) - begin;
    return d * deg + nv;
  };
  colptr_.assign(num_dofs_ + 1, 0);
  for (Index n = 0; n < num_nodes_; ++n)
    for (Index c = 0; c < d; ++c) colptr_[d * n + c + 1] = column_length(n);
  for (Index v = 0; v < num_vertices_; ++v) colptr_[d * num_nodes_ + v + 1] = column_length(v);
  for (Index j = 0; j < num_dofs_; ++j) colptr_[j + 1] += colptr_[j];
  rowind_.resize(colptr_.back());
  auto fill_column = [&](Index col, Index n) {
    Index pos = colptr_[col];
    for (Index q = adj_ptr_[n]; q < adj_ptr_[n + 1]; ++q)
      for (Index c = 0; c < d; ++c) rowind_[pos++] = d * adj_[q] + c;
    for (Index q = adj_ptr_[n]; q < adj_ptr_[n + 1] && adj_[q] < num_vertices_; ++q)
      rowind_[pos++] = d * num_nodes_ + adj_[q];
  };
  for (Index n = 0; n < num_nodes_; ++n)
    for (Index c = 0; c < d; ++c) fill_column(d * n + c, n);
  for (Index v = 0; v < num_vertices_; ++v) fill_column(d * num_nodes_ + v, v);

  edge_ends_.resize(static_cast<std::size_t>(num_nodes_ - num_vertices_));
  for (const Element& t : elements)
    for (std::size_t k = 0; k < NumEdges; ++k)
      edge_ends_[static_cast<std::size_t>(t[kCorners + k] - num_vertices_)] = {t[edges[k][0]],
                                                                               t[edges[k][1]]};

  local_pos_.resize(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Element& t = elements[e];
    for (int a = 0; a < kNodes; ++a) {
      const Index* begin = adj_.data() + adj_ptr_[t[a]];
      const Index* end = adj_.data() + adj_ptr_[t[a] + 1];
      for (int b = 0; b < kNodes; ++b)
        local_pos_[e][a * 10 + b] =
            static_cast<std::int32_t>(std::lower_bound(begin, end, t[b]) - begin);
    }
  }
}

SUNMatrix SparsityPattern::new_matrix(SUNContext ctx) const {
  SUNMatrix A = SUNSparseMatrix(num_dofs_, num_dofs_, nnz(), CSC_MAT, ctx);
  if (!A) throw std::runtime_error("SUNSparseMatrix failed");
  restore_into(A);
  return A;
}

void SparsityPattern::restore_into(SUNMatrix A) const {
  std::copy(colptr_.begin(), colptr_.end(), SUNSparseMatrix_IndexPointers(A));
  std::copy(rowind_.begin(), rowind_.end(), SUNSparseMatrix_IndexValues(A));
}

Index SparsityPattern::find(Index row, Index col) const {
  const Index* begin = rowind_.data() + colptr_[col];
  const Index* end = rowind_.data() + colptr_[col + 1];
  const Index* it = std::lower_bound(begin, end, row);
  return (it != end && *it == row) ? it - rowind_.data() : -1;
}

void SparsityPattern::scatter(Index element, const Tet10& tet, const ElementMatrix& A,
                              const ElementMatrix& B, double c, const std::vector<char>& skip_row,
                              double* values) const {
  const auto& pos = local_pos_[element];
  Index rows[kElementDofs];
  for (int r = 0; r < kElementDofs; ++r) rows[r] = global_dof(tet, r);
  for (int s = 0; s < kElementDofs; ++s) {
    const int a = s < 30 ? s / 3 : s - 30;
    const Index col = global_dof(tet, s);
    const Index base = colptr_[col];
    const Index deg = adj_ptr_[tet[a] + 1] - adj_ptr_[tet[a]];
    for (int r = 0; r < kElementDofs; ++r) {
      if (skip_row[rows[r]]) continue;
      const Index offset =
          r < 30 ? 3 * pos[a * 10 + r / 3] + r % 3 : 3 * deg + pos[a * 10 + r - 30];
      values[base + offset] += A(r, s) + c * B(r, s);
    }
  }
}

void SparsityPattern::scatter(Index element, const Tri6& tri, const SectionElementMatrix& A,
                              const SectionElementMatrix& B, double c,
                              const std::vector<char>& skip_row, double* values) const {
  const auto& pos = local_pos_[element];
  Index rows[kSectionElementDofs];
  for (int r = 0; r < kSectionElementDofs; ++r) rows[r] = global_dof(tri, r);
  for (int s = 0; s < kSectionElementDofs; ++s) {
    const int a = s < 12 ? s / 2 : s - 12;
    const Index base = colptr_[global_dof(tri, s)];
    const Index deg = adj_ptr_[tri[a] + 1] - adj_ptr_[tri[a]];
    for (int r = 0; r < kSectionElementDofs; ++r) {
      if (skip_row[rows[r]]) continue;
      const Index offset =
          r < 12 ? 2 * pos[a * 10 + r / 2] + r % 2 : 2 * deg + pos[a * 10 + r - 12];
      values[base + offset] += A(r, s) + c * B(r, s);
    }
  }
}

std::vector<Index> SparsityPattern::nested_dissection_order() const {
  // Vertex graph: the vertices among each vertex's node neighbours (they sort first).
  std::vector<idx_t> xadj(static_cast<std::size_t>(num_vertices_) + 1, 0), adjncy;
  for (Index v = 0; v < num_vertices_; ++v) {
    for (Index q = adj_ptr_[v]; q < adj_ptr_[v + 1] && adj_[q] < num_vertices_; ++q)
      if (adj_[q] != v) adjncy.push_back(static_cast<idx_t>(adj_[q]));
    xadj[v + 1] = static_cast<idx_t>(adjncy.size());
  }
  std::vector<idx_t> perm(static_cast<std::size_t>(num_vertices_)),
      iperm(static_cast<std::size_t>(num_vertices_));
  idx_t nv = static_cast<idx_t>(num_vertices_);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  if (num_vertices_ > 1 && METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, options,
                                        perm.data(), iperm.data()) != METIS_OK)
    throw std::runtime_error("METIS_NodeND failed on the vertex graph");
  if (num_vertices_ == 1) iperm[0] = 0;
  // Sort key: vertex at position k → 2k; an edge node → 2k + 1 with k the earlier position of
  // its ends (ties by node number, for a deterministic order).
  std::vector<std::pair<Index, Index>> keyed(static_cast<std::size_t>(num_nodes_));
  for (Index v = 0; v < num_vertices_; ++v) keyed[v] = {2 * Index{iperm[v]}, v};
  for (Index n = num_vertices_; n < num_nodes_; ++n) {
    const auto [a, b] = edge_ends_[static_cast<std::size_t>(n - num_vertices_)];
    keyed[n] = {2 * Index{std::min(iperm[a], iperm[b])} + 1, n};
  }
  // Coupled nodes last: their rows and columns are dense over a platen's neighbourhood, and
  // eliminating them early would fill the whole neighbourhood.
  const Index last = 2 * static_cast<Index>(num_vertices_) + 2;
  for (std::size_t k = 0; k < late_nodes_.size(); ++k)
    keyed[static_cast<std::size_t>(late_nodes_[k])].first = last + static_cast<Index>(k);
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> order;
  order.reserve(static_cast<std::size_t>(num_dofs_));
  for (const auto& [key, n] : keyed) {
    for (int c = 0; c < components_; ++c) order.push_back(u_dof(n, c));
    if (n < num_vertices_) order.push_back(p_dof(n));
  }
  return order;
}

}  // namespace biphasic
