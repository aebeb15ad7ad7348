#include "biphasic/mesh/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace biphasic {

namespace {

/// Sorted corner triple of a face: the key that identifies it whatever its orientation.
using FaceKey = std::array<Index, 3>;

FaceKey face_key(Index a, Index b, Index c) {
  FaceKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

MeshPartition partition_mesh(const Mesh& mesh, int parts) {
  const auto num_tets = static_cast<Index>(mesh.tets.size());
  if (parts < 1 || parts > num_tets)
    throw std::invalid_argument("partition: " + std::to_string(parts) + " parts for a mesh of " +
                                std::to_string(num_tets) + " tetrahedra (need 1 to " +
                                std::to_string(num_tets) + ")");
  MeshPartition p;
  p.parts = parts;
  p.tet_part.assign(mesh.tets.size(), 0);
  if (parts > 1) {
    std::vector<idx_t> eptr(mesh.tets.size() + 1), eind(4 * mesh.tets.size());
    for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
      eptr[e] = static_cast<idx_t>(4 * e);
      for (int a = 0; a < 4; ++a) eind[4 * e + a] = static_cast<idx_t>(mesh.tets[e][a]);
    }
    eptr.back() = static_cast<idx_t>(eind.size());
    idx_t ne = static_cast<idx_t>(num_tets), nn = static_cast<idx_t>(mesh.num_vertices);
    idx_t ncommon = 3, nparts = parts, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_SEED] = 1;  // the same split on every run and every process
    std::vector<idx_t> epart(mesh.tets.size()), npart(static_cast<std::size_t>(nn));
    const int status =
        METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts,
                           nullptr, options, &objval, epart.data(), npart.data());
    if (status != METIS_OK)
      throw std::runtime_error("partition: METIS_PartMeshDual failed (status " +
                               std::to_string(status) + ") for " + std::to_string(parts) +
                               " parts");
    for (std::size_t e = 0; e < mesh.tets.size(); ++e) p.tet_part[e] = static_cast<int>(epart[e]);
    std::vector<Index> count(static_cast<std::size_t>(parts), 0);
    for (int r : p.tet_part) ++count[static_cast<std::size_t>(r)];
    for (int r = 0; r < parts; ++r)
      if (count[static_cast<std::size_t>(r)] == 0)
        throw std::runtime_error("partition: splitting " + std::to_string(num_tets) +
                                 " tetrahedra into " + std::to_string(parts) + " parts left part " +
                                 std::to_string(r) + " empty; use fewer processes");
  }
  assign_node_owners(mesh, p);
  return p;
}

void assign_node_owners(const Mesh& mesh, MeshPartition& partition) {
  const int parts = partition.parts;
  partition.node_owner.assign(mesh.nodes.size(), parts);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e)
    for (Index n : mesh.tets[e]) {
      int& owner = partition.node_owner[static_cast<std::size_t>(n)];
      owner = std::min(owner, partition.tet_part[e]);
    }
  for (std::size_t n = 0; n < partition.node_owner.size(); ++n)
    if (partition.node_owner[n] == parts)
      throw std::runtime_error("partition: node " + std::to_string(n) +
                               " belongs to no tetrahedron");
}

std::vector<Index> rank_major_of_whole(const Mesh& mesh, const PartitionedNumbering& numbering) {
  std::vector<Index> map(static_cast<std::size_t>(3 * mesh.num_nodes() + mesh.num_vertices));
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    for (int c = 0; c < 3; ++c)
      map[static_cast<std::size_t>(3 * n + c)] = numbering.u_base[static_cast<std::size_t>(n)] + c;
  for (Index v = 0; v < mesh.num_vertices; ++v)
    map[static_cast<std::size_t>(3 * mesh.num_nodes() + v)] =
        numbering.p_index[static_cast<std::size_t>(v)];
  return map;
}

PartitionedNumbering number_unknowns(const Mesh& mesh, const MeshPartition& partition) {
  const auto parts = static_cast<std::size_t>(partition.parts);
  PartitionedNumbering num;
  num.owned_nodes.assign(parts, 0);
  num.owned_vertices.assign(parts, 0);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto r = static_cast<std::size_t>(partition.node_owner[static_cast<std::size_t>(n)]);
    ++num.owned_nodes[r];
    if (n < mesh.num_vertices) ++num.owned_vertices[r];
  }
  num.offset.assign(parts + 1, 0);
  for (std::size_t r = 0; r < parts; ++r)
    num.offset[r + 1] = num.offset[r] + 3 * num.owned_nodes[r] + num.owned_vertices[r];
  std::vector<Index> next_node(parts, 0), next_vertex(parts, 0);
  num.u_base.assign(mesh.nodes.size(), -1);
  num.p_index.assign(mesh.nodes.size(), -1);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto r = static_cast<std::size_t>(partition.node_owner[static_cast<std::size_t>(n)]);
    num.u_base[static_cast<std::size_t>(n)] = num.offset[r] + 3 * next_node[r]++;
    if (n < mesh.num_vertices)
      num.p_index[static_cast<std::size_t>(n)] =
          num.offset[r] + 3 * num.owned_nodes[r] + next_vertex[r]++;
  }
  return num;
}

Subdomain extract_subdomain(const Mesh& mesh, const MeshPartition& partition, int part) {
  if (part < 0 || part >= partition.parts)
    throw std::invalid_argument("subdomain: part " + std::to_string(part) + " of " +
                                std::to_string(partition.parts));
  Subdomain sub;
  sub.part = part;
  // Nodes of owned elements, then the elements touching any of them (owned or ghost).
  std::vector<char> touched(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e)
    if (partition.tet_part[e] == part)
      for (Index n : mesh.tets[e]) touched[static_cast<std::size_t>(n)] = 1;
  std::vector<char> node_here(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet10& t = mesh.tets[e];
    if (std::none_of(t.begin(), t.end(),
                     [&](Index n) { return touched[static_cast<std::size_t>(n)] != 0; }))
      continue;
    sub.global_tet.push_back(static_cast<Index>(e));
    for (Index n : t) node_here[static_cast<std::size_t>(n)] = 1;
  }
  // Local nodes: vertices first, each group in the whole mesh's order.
  std::vector<Index> local_of(mesh.nodes.size(), -1);
  for (int pass = 0; pass < 2; ++pass) {
    const Index begin = pass == 0 ? 0 : mesh.num_vertices;
    const Index end = pass == 0 ? mesh.num_vertices : mesh.num_nodes();
    for (Index n = begin; n < end; ++n)
      if (node_here[static_cast<std::size_t>(n)]) {
        local_of[static_cast<std::size_t>(n)] = static_cast<Index>(sub.global_node.size());
        sub.global_node.push_back(n);
      }
    if (pass == 0) sub.mesh.num_vertices = static_cast<Index>(sub.global_node.size());
  }
  auto local = [&](Index n) { return local_of[static_cast<std::size_t>(n)]; };
  for (Index g : sub.global_node) {
    const auto gi = static_cast<std::size_t>(g);
    sub.mesh.nodes.push_back(mesh.nodes[gi]);
    sub.node_owned.push_back(partition.node_owner[gi] == part ? 1 : 0);
    sub.node_touched.push_back(touched[gi]);
    if (!mesh.file_tags.empty()) sub.mesh.file_tags.push_back(mesh.file_tags[gi]);
  }
  std::vector<FaceKey> faces;
  for (Index e : sub.global_tet) {
    const Tet10& t = mesh.tets[static_cast<std::size_t>(e)];
    Tet10 lt{};
    for (int a = 0; a < 10; ++a) lt[a] = local(t[a]);
    sub.mesh.tets.push_back(lt);
    sub.tet_owned.push_back(partition.tet_part[static_cast<std::size_t>(e)] == part ? 1 : 0);
    if (!mesh.tet_region.empty())
      sub.mesh.tet_region.push_back(mesh.tet_region[static_cast<std::size_t>(e)]);
    for (int skip = 0; skip < 4; ++skip) {
      std::array<Index, 3> c{};
      for (int a = 0, m = 0; a < 4; ++a)
        if (a != skip) c[m++] = t[a];
      faces.push_back(face_key(c[0], c[1], c[2]));
    }
  }
  std::sort(faces.begin(), faces.end());
  sub.mesh.region_names = mesh.region_names;
  for (const Boundary& b : mesh.boundaries) {
    Boundary lb{b.name, {}};
    for (const Tri6& f : b.faces) {
      if (!std::binary_search(faces.begin(), faces.end(), face_key(f[0], f[1], f[2]))) continue;
      Tri6 lf{};
      for (int a = 0; a < 6; ++a) lf[a] = local(f[a]);
      lb.faces.push_back(lf);
    }
    sub.mesh.boundaries.push_back(std::move(lb));
  }
  for (const NodeSet& s : mesh.node_sets) {
    NodeSet ls{s.name, s.dimension, {}};
    for (Index n : s.nodes)
      if (local(n) >= 0) ls.nodes.push_back(local(n));
    sub.mesh.node_sets.push_back(std::move(ls));
  }
  return sub;
}

std::vector<Index> unknown_order(const PartitionedNumbering& numbering,
                                 const std::vector<Index>& node_order) {
  std::vector<Index> order;
  order.reserve(4 * node_order.size());
  for (const Index n : node_order) {
    const auto k = static_cast<std::size_t>(n);
    for (Index c = 0; c < 3; ++c) order.push_back(numbering.u_base.at(k) + c);
    if (numbering.p_index.at(k) >= 0) order.push_back(numbering.p_index[k]);
  }
  return order;
}

}  // namespace biphasic
