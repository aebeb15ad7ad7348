// The fill-reducing order (nested dissection of the vertex graph, edge nodes after the first of
// their ends): a permutation keeping each node's unknowns together, and as little fill in a
// symbolic factorisation as METIS nested dissection of the whole node graph.
#include <gtest/gtest.h>
#include <metis.h>

#include <algorithm>
#include <set>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/assembly/sparsity.hpp"

namespace biphasic {
namespace {

/// Nodes in elimination order, from an order of the unknowns that keeps nodes together.
std::vector<Index> node_sequence(const SparsityPattern& pattern, const std::vector<Index>& order) {
  std::vector<Index> nodes;
  for (Index u : order)
    if (u < pattern.num_u() && u % 3 == 0) nodes.push_back(u / 3);
  return nodes;
}

/// Entries of the Cholesky factor of the node graph's matrix (each node a dense block of its
/// 3 or 4 unknowns) eliminated in `nodes` order: symbolic elimination by the quotient rule
/// (struct L_j = adj(j) ∪ struct of the children of j in the elimination tree, beyond j).
double factor_entries(const SparsityPattern& pattern, const std::vector<Index>& nodes) {
  const Index n = pattern.num_nodes();
  std::vector<Index> position(n);
  for (Index k = 0; k < n; ++k) position[nodes[k]] = k;
  auto weight = [&](Index node) { return node < pattern.num_vertices() ? 4.0 : 3.0; };
  std::vector<std::vector<Index>> children(n);  // by position
  std::vector<std::vector<Index>> structure(n);
  double entries = 0.0;
  for (Index k = 0; k < n; ++k) {
    std::set<Index> s;
    const auto [begin, end] = pattern.node_neighbours(nodes[k]);
    for (const Index* q = begin; q != end; ++q)
      if (position[*q] > k) s.insert(position[*q]);
    for (Index c : children[k])
      for (Index i : structure[c])
        if (i > k) s.insert(i);
    for (Index c : children[k]) std::vector<Index>().swap(structure[c]);
    structure[k].assign(s.begin(), s.end());
    const double w = weight(nodes[k]);
    entries += w * (w + 1) / 2;
    for (Index i : structure[k]) entries += w * weight(nodes[i]);
    if (!structure[k].empty()) children[structure[k].front()].push_back(k);
  }
  return entries;
}

/// METIS nested dissection of the whole node graph, for comparison.
std::vector<Index> node_graph_dissection(const SparsityPattern& pattern) {
  std::vector<idx_t> xadj{0}, adjncy;
  for (Index n = 0; n < pattern.num_nodes(); ++n) {
    const auto [begin, end] = pattern.node_neighbours(n);
    for (const Index* q = begin; q != end; ++q)
      if (*q != n) adjncy.push_back(static_cast<idx_t>(*q));
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
  idx_t nv = static_cast<idx_t>(pattern.num_nodes());
  std::vector<idx_t> perm(nv), iperm(nv);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  EXPECT_EQ(
      METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data()),
      METIS_OK);
  return std::vector<Index>(perm.begin(), perm.end());
}

TEST(FillOrder, IsAPermutationKeepingEachNodesUnknownsTogether) {
  const Mesh mesh = test::box_mesh({3, 4, 5}, {1.0, 1.0, 1.0});
  const SparsityPattern pattern(mesh);
  const std::vector<Index> order = pattern.nested_dissection_order();
  ASSERT_EQ(static_cast<Index>(order.size()), pattern.size());
  std::vector<Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (Index i = 0; i < pattern.size(); ++i) ASSERT_EQ(sorted[i], i);
  std::size_t k = 0;
  while (k < order.size()) {
    const Index node = order[k] / 3;
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(order[k + c], pattern.u_dof(node, c)) << "at " << k;
    }
    k += 3;
    if (node < pattern.num_vertices()) {
      ASSERT_EQ(order[k++], pattern.p_dof(node));
    }
  }
}

TEST(FillOrder, EdgeNodesFollowTheFirstOfTheirEndsDirectly) {
  const Mesh mesh = test::box_mesh({3, 4, 5}, {1.0, 1.0, 1.0});
  const SparsityPattern pattern(mesh);
  const std::vector<Index> nodes = node_sequence(pattern, pattern.nested_dissection_order());
  std::vector<Index> position(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) position[nodes[k]] = static_cast<Index>(k);
  for (const Tet10& t : mesh.tets)
    for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
      const Index first = std::min(position[t[kTetEdges[e][0]]], position[t[kTetEdges[e][1]]]);
      const Index here = position[t[4 + e]];
      ASSERT_GT(here, first) << "edge node " << t[4 + e];
      for (Index k = first + 1; k < here; ++k) {  // only edge nodes in between
        ASSERT_GE(nodes[k], pattern.num_vertices()) << "edge node " << t[4 + e];
      }
    }
}

TEST(FillOrder, FillAsSmallAsDissectingTheWholeNodeGraph) {
  const Mesh mesh = test::box_mesh({8, 8, 8}, {1.0, 1.0, 1.0});
  const SparsityPattern pattern(mesh);
  const double ours =
      factor_entries(pattern, node_sequence(pattern, pattern.nested_dissection_order()));
  const double metis_nodes = factor_entries(pattern, node_graph_dissection(pattern));
  std::vector<Index> natural(pattern.num_nodes());
  for (Index n = 0; n < pattern.num_nodes(); ++n) natural[n] = n;
  const double natural_entries = factor_entries(pattern, natural);
  RecordProperty("ours", std::to_string(ours));
  RecordProperty("metis_node_graph", std::to_string(metis_nodes));
  EXPECT_LT(ours, 1.15 * metis_nodes) << ours << " vs " << metis_nodes;
  EXPECT_LT(ours, 0.5 * natural_entries) << ours << " vs natural " << natural_entries;
}

}  // namespace
}  // namespace biphasic
