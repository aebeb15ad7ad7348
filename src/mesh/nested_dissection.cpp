#include "biphasic/mesh/nested_dissection.hpp"

#include <metis.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace biphasic {

namespace {

/// The order over the elements (4 corners and kTetEdges, or 3 corners and kTriEdges).
template <class Element, std::size_t NumEdges>
std::vector<Index> node_order(const std::vector<Element>& elements, Index num_vertices,
                              std::size_t num_nodes, int corners,
                              const std::array<std::array<int, 2>, NumEdges>& edges) {
  const auto nv = static_cast<std::size_t>(num_vertices);
  // Vertex graph in CSR form: each vertex's distinct neighbours through the elements.
  std::vector<std::vector<idx_t>> neighbours(nv);
  for (const Element& el : elements)
    for (int a = 0; a < corners; ++a)
      for (int b = 0; b < corners; ++b)
        if (a != b)
          neighbours[static_cast<std::size_t>(el[a])].push_back(static_cast<idx_t>(el[b]));
  std::vector<idx_t> xadj(nv + 1, 0), adjncy;
  for (std::size_t v = 0; v < nv; ++v) {
    auto& list = neighbours[v];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    adjncy.insert(adjncy.end(), list.begin(), list.end());
    xadj[v + 1] = static_cast<idx_t>(adjncy.size());
    std::vector<idx_t>().swap(list);
  }
  std::vector<idx_t> perm(nv), iperm(nv, 0);
  if (nv > 1) {
    idx_t n = static_cast<idx_t>(nv);
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    if (METIS_NodeND(&n, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data()) !=
        METIS_OK)
      throw std::runtime_error("METIS_NodeND failed on the mesh's vertex graph");
  }
  // Sort key: the vertex at position k → 2k; an edge node → 2k + 1, k the earlier of its ends.
  std::vector<std::pair<Index, Index>> keyed(num_nodes, {-1, -1});
  for (std::size_t v = 0; v < nv; ++v) keyed[v] = {2 * Index{iperm[v]}, static_cast<Index>(v)};
  for (const Element& el : elements)
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto node = static_cast<std::size_t>(el[static_cast<std::size_t>(corners) + e]);
      const Index first = std::min(Index{iperm[static_cast<std::size_t>(el[edges[e][0]])]},
                                   Index{iperm[static_cast<std::size_t>(el[edges[e][1]])]});
      keyed[node] = {2 * first + 1, static_cast<Index>(node)};
    }
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> order;
  order.reserve(num_nodes);
  for (const auto& [key, node] : keyed)
    if (key >= 0) order.push_back(node);
  if (order.size() != num_nodes)
    throw std::runtime_error("nested dissection: a node belongs to no element");
  return order;
}

}  // namespace

std::vector<Index> nested_dissection_node_order(const Mesh& mesh) {
  return node_order(mesh.tets, mesh.num_vertices, mesh.nodes.size(), 4, kTetEdges);
}

std::vector<Index> nested_dissection_node_order(const SectionMesh& mesh) {
  return node_order(mesh.triangles, mesh.num_vertices, mesh.nodes.size(), 3, kTriEdges);
}

}  // namespace biphasic
