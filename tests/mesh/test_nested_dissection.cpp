// The nested-dissection node order handed to the parallel MUMPS (mesh/nested_dissection.hpp):
// a permutation of the nodes, edge nodes placed after the earlier of their ends, deterministic,
// and fill-reducing — its elimination of the vertex graph fills less than the mesh's own
// lexicographic numbering, counted by the elimination game.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/mesh/nested_dissection.hpp"

namespace biphasic {
namespace {

/// Fill edges created by eliminating the vertex graph's vertices in `order` (vertices only).
long fill_of(const Mesh& mesh, const std::vector<Index>& order) {
  const auto nv = static_cast<std::size_t>(mesh.num_vertices);
  std::vector<std::set<Index>> adjacent(nv);
  for (const Tet10& t : mesh.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) adjacent[static_cast<std::size_t>(t[a])].insert(t[b]);
  std::vector<char> gone(nv, 0);
  long fill = 0;
  for (const Index v : order) {
    if (v >= mesh.num_vertices) continue;
    std::vector<Index> rest;
    for (const Index w : adjacent[static_cast<std::size_t>(v)])
      if (!gone[static_cast<std::size_t>(w)]) rest.push_back(w);
    for (std::size_t i = 0; i < rest.size(); ++i)
      for (std::size_t j = i + 1; j < rest.size(); ++j)
        if (adjacent[static_cast<std::size_t>(rest[i])].insert(rest[j]).second) {
          adjacent[static_cast<std::size_t>(rest[j])].insert(rest[i]);
          ++fill;
        }
    gone[static_cast<std::size_t>(v)] = 1;
  }
  return fill;
}

TEST(NestedDissection, OrdersEveryNodeOnceWithEdgeNodesAfterTheirEarlierEnd) {
  const Mesh mesh = test::box_mesh({3, 4, 5}, {1.0, 1.2, 1.5});
  const std::vector<Index> order = nested_dissection_node_order(mesh);
  ASSERT_EQ(order.size(), mesh.nodes.size());
  std::vector<Index> position(order.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) {
    ASSERT_EQ(position.at(static_cast<std::size_t>(order[k])), -1) << "node twice";
    position[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
  }
  // The vertex last placed before each edge node is the earlier of the edge's two ends.
  std::vector<Index> vertex_before(order.size(), -1);
  Index last_vertex = -1;
  for (const Index n : order) {
    if (n < mesh.num_vertices) last_vertex = n;
    vertex_before[static_cast<std::size_t>(n)] = last_vertex;
  }
  for (const Tet10& t : mesh.tets)
    for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
      const Index a = t[kTetEdges[e][0]], b = t[kTetEdges[e][1]];
      const Index earlier =
          position[static_cast<std::size_t>(a)] < position[static_cast<std::size_t>(b)] ? a : b;
      EXPECT_EQ(vertex_before[static_cast<std::size_t>(t[4 + e])], earlier);
    }
  EXPECT_EQ(nested_dissection_node_order(mesh), order) << "not deterministic";
}

TEST(NestedDissection, FillsLessThanTheLexicographicNumbering) {
  const Mesh mesh = test::box_mesh({8, 8, 8}, {1.0, 1.0, 1.0});
  std::vector<Index> lexicographic(static_cast<std::size_t>(mesh.num_vertices));
  for (Index v = 0; v < mesh.num_vertices; ++v) lexicographic[static_cast<std::size_t>(v)] = v;
  const long natural = fill_of(mesh, lexicographic);
  const long dissected = fill_of(mesh, nested_dissection_node_order(mesh));
  RecordProperty("fill_lexicographic", std::to_string(natural));
  RecordProperty("fill_nested_dissection", std::to_string(dissected));
  EXPECT_LT(static_cast<double>(dissected), 0.7 * static_cast<double>(natural))
      << "lexicographic " << natural << ", nested dissection " << dissected;
}

}  // namespace
}  // namespace biphasic
