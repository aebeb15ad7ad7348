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

/// Sorted ends of a triangle's edge or a boundary segment.
using EdgeKey = std::array<Index, 2>;

EdgeKey edge_key(Index a, Index b) { return {std::min(a, b), std::max(a, b)}; }

// The element arrays of each mesh type, and what the code below needs to know of them.
const std::vector<Tet10>& elements_of(const Mesh& mesh) { return mesh.tets; }
const std::vector<Tri6>& elements_of(const SectionMesh& mesh) { return mesh.triangles; }
std::vector<Tet10>& elements_of(Mesh& mesh) { return mesh.tets; }
std::vector<Tri6>& elements_of(SectionMesh& mesh) { return mesh.triangles; }
constexpr int corners_of(const Mesh&) { return 4; }
constexpr int corners_of(const SectionMesh&) { return 3; }
constexpr int components_of(const Mesh&) { return 3; }
constexpr int components_of(const SectionMesh&) { return 2; }
const char* noun_of(const Mesh&) { return "tetrahedra"; }
const char* noun_of(const SectionMesh&) { return "triangles"; }

template <class AnyMesh>
MeshPartition partition_any(const AnyMesh& mesh, int parts) {
  const auto& elements = elements_of(mesh);
  const auto num_elements = static_cast<Index>(elements.size());
  const int corners = corners_of(mesh);
  if (parts < 1 || parts > num_elements)
    throw std::invalid_argument("partition: " + std::to_string(parts) + " parts for a mesh of " +
                                std::to_string(num_elements) + " " + noun_of(mesh) +
                                " (need 1 to " + std::to_string(num_elements) + ")");
  MeshPartition p;
  p.parts = parts;
  p.element_part.assign(elements.size(), 0);
  if (parts > 1) {
    const auto nc = static_cast<std::size_t>(corners);
    std::vector<idx_t> eptr(elements.size() + 1), eind(nc * elements.size());
    for (std::size_t e = 0; e < elements.size(); ++e) {
      eptr[e] = static_cast<idx_t>(nc * e);
      for (std::size_t a = 0; a < nc; ++a) eind[nc * e + a] = static_cast<idx_t>(elements[e][a]);
    }
    eptr.back() = static_cast<idx_t>(eind.size());
    idx_t ne = static_cast<idx_t>(num_elements), nn = static_cast<idx_t>(mesh.num_vertices);
    // Neighbours share a face (3 corners) of a tetrahedron, an edge (2) of a triangle.
    idx_t ncommon = corners - 1, nparts = parts, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_SEED] = 1;  // the same split on every run and every process
    std::vector<idx_t> epart(elements.size()), npart(static_cast<std::size_t>(nn));
    const int status =
        METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts,
                           nullptr, options, &objval, epart.data(), npart.data());
    if (status != METIS_OK)
      throw std::runtime_error("partition: METIS_PartMeshDual failed (status " +
                               std::to_string(status) + ") for " + std::to_string(parts) +
                               " parts");
    for (std::size_t e = 0; e < elements.size(); ++e)
      p.element_part[e] = static_cast<int>(epart[e]);
    std::vector<Index> count(static_cast<std::size_t>(parts), 0);
    for (int r : p.element_part) ++count[static_cast<std::size_t>(r)];
    for (int r = 0; r < parts; ++r)
      if (count[static_cast<std::size_t>(r)] == 0)
        throw std::runtime_error("partition: splitting " + std::to_string(num_elements) + " " +
                                 noun_of(mesh) + " into " + std::to_string(parts) +
                                 " parts left part " + std::to_string(r) +
                                 " empty; use fewer processes");
  }
  assign_node_owners(mesh, p);
  return p;
}

template <class AnyMesh>
void assign_owners_any(const AnyMesh& mesh, MeshPartition& partition) {
  const int parts = partition.parts;
  const auto& elements = elements_of(mesh);
  partition.node_owner.assign(mesh.nodes.size(), parts);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (Index n : elements[e]) {
      int& owner = partition.node_owner[static_cast<std::size_t>(n)];
      owner = std::min(owner, partition.element_part[e]);
    }
  for (std::size_t n = 0; n < partition.node_owner.size(); ++n)
    if (partition.node_owner[n] == parts)
      throw std::runtime_error("partition: node " + std::to_string(n) + " belongs to no element");
}

template <class AnyMesh>
PartitionedNumbering number_any(const AnyMesh& mesh, const MeshPartition& partition) {
  const auto parts = static_cast<std::size_t>(partition.parts);
  const Index d = components_of(mesh);
  PartitionedNumbering num;
  num.components = static_cast<int>(d);
  num.owned_nodes.assign(parts, 0);
  num.owned_vertices.assign(parts, 0);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto r = static_cast<std::size_t>(partition.node_owner[static_cast<std::size_t>(n)]);
    ++num.owned_nodes[r];
    if (n < mesh.num_vertices) ++num.owned_vertices[r];
  }
  num.offset.assign(parts + 1, 0);
  for (std::size_t r = 0; r < parts; ++r)
    num.offset[r + 1] = num.offset[r] + d * num.owned_nodes[r] + num.owned_vertices[r];
  std::vector<Index> next_node(parts, 0), next_vertex(parts, 0);
  num.u_base.assign(mesh.nodes.size(), -1);
  num.p_index.assign(mesh.nodes.size(), -1);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto r = static_cast<std::size_t>(partition.node_owner[static_cast<std::size_t>(n)]);
    num.u_base[static_cast<std::size_t>(n)] = num.offset[r] + d * next_node[r]++;
    if (n < mesh.num_vertices)
      num.p_index[static_cast<std::size_t>(n)] =
          num.offset[r] + d * num.owned_nodes[r] + next_vertex[r]++;
  }
  return num;
}

/// The part-independent half of extract_subdomain: the part's elements (owned ones and the
/// ghost layer) and nodes, renumbered, into `sub` and `sub.mesh` (nodes, vertices, elements,
/// regions, file tags, node sets); returns the local number of each node of the whole mesh (−1:
/// not here). Boundaries are the caller's.
template <class AnyMesh, class Part>
std::vector<Index> extract_elements(const AnyMesh& mesh, const MeshPartition& partition, int part,
                                    Part& sub) {
  if (part < 0 || part >= partition.parts)
    throw std::invalid_argument("subdomain: part " + std::to_string(part) + " of " +
                                std::to_string(partition.parts));
  const auto& elements = elements_of(mesh);
  sub.part = part;
  // Nodes of owned elements, then the elements touching any of them (owned or ghost).
  std::vector<char> touched(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (partition.element_part[e] == part)
      for (Index n : elements[e]) touched[static_cast<std::size_t>(n)] = 1;
  std::vector<char> node_here(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& el = elements[e];
    if (std::none_of(el.begin(), el.end(),
                     [&](Index n) { return touched[static_cast<std::size_t>(n)] != 0; }))
      continue;
    sub.global_element.push_back(static_cast<Index>(e));
    for (Index n : el) node_here[static_cast<std::size_t>(n)] = 1;
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
  for (Index g : sub.global_node) {
    const auto gi = static_cast<std::size_t>(g);
    sub.mesh.nodes.push_back(mesh.nodes[gi]);
    sub.node_owned.push_back(partition.node_owner[gi] == part ? 1 : 0);
    sub.node_touched.push_back(touched[gi]);
    if (!mesh.file_tags.empty()) sub.mesh.file_tags.push_back(mesh.file_tags[gi]);
  }
  auto& local_elements = elements_of(sub.mesh);
  for (Index e : sub.global_element) {
    auto local = elements[static_cast<std::size_t>(e)];
    for (Index& n : local) n = local_of[static_cast<std::size_t>(n)];
    local_elements.push_back(local);
    sub.element_owned.push_back(partition.element_part[static_cast<std::size_t>(e)] == part ? 1
                                                                                            : 0);
  }
  sub.mesh.region_names = mesh.region_names;
  for (const NodeSet& s : mesh.node_sets) {
    NodeSet ls{s.name, s.dimension, {}};
    for (Index n : s.nodes)
      if (local_of[static_cast<std::size_t>(n)] >= 0)
        ls.nodes.push_back(local_of[static_cast<std::size_t>(n)]);
    sub.mesh.node_sets.push_back(std::move(ls));
  }
  return local_of;
}

}  // namespace

MeshPartition partition_mesh(const Mesh& mesh, int parts) { return partition_any(mesh, parts); }
MeshPartition partition_mesh(const SectionMesh& mesh, int parts) {
  return partition_any(mesh, parts);
}

void assign_node_owners(const Mesh& mesh, MeshPartition& partition) {
  assign_owners_any(mesh, partition);
}
void assign_node_owners(const SectionMesh& mesh, MeshPartition& partition) {
  assign_owners_any(mesh, partition);
}

PartitionedNumbering number_unknowns(const Mesh& mesh, const MeshPartition& partition) {
  return number_any(mesh, partition);
}
PartitionedNumbering number_unknowns(const SectionMesh& mesh, const MeshPartition& partition) {
  return number_any(mesh, partition);
}

std::vector<Index> rank_major_of_whole(Index num_vertices, const PartitionedNumbering& numbering) {
  const Index d = numbering.components;
  const auto num_nodes = static_cast<Index>(numbering.u_base.size());
  std::vector<Index> map(static_cast<std::size_t>(d * num_nodes + num_vertices));
  for (Index n = 0; n < num_nodes; ++n)
    for (Index c = 0; c < d; ++c)
      map[static_cast<std::size_t>(d * n + c)] = numbering.u_base[static_cast<std::size_t>(n)] + c;
  for (Index v = 0; v < num_vertices; ++v)
    map[static_cast<std::size_t>(d * num_nodes + v)] =
        numbering.p_index[static_cast<std::size_t>(v)];
  return map;
}

Subdomain extract_subdomain(const Mesh& mesh, const MeshPartition& partition, int part) {
  Subdomain sub;
  const std::vector<Index> local_of = extract_elements(mesh, partition, part, sub);
  for (std::size_t e = 0; e < sub.global_element.size(); ++e)
    if (!mesh.tet_region.empty())
      sub.mesh.tet_region.push_back(
          mesh.tet_region[static_cast<std::size_t>(sub.global_element[e])]);
  // Boundary faces: those of the part's tetrahedra.
  std::vector<FaceKey> faces;
  for (Index e : sub.global_element) {
    const Tet10& t = mesh.tets[static_cast<std::size_t>(e)];
    for (int skip = 0; skip < 4; ++skip) {
      std::array<Index, 3> c{};
      for (int a = 0, m = 0; a < 4; ++a)
        if (a != skip) c[m++] = t[a];
      faces.push_back(face_key(c[0], c[1], c[2]));
    }
  }
  std::sort(faces.begin(), faces.end());
  for (const Boundary& b : mesh.boundaries) {
    Boundary lb{b.name, {}};
    for (const Tri6& f : b.faces) {
      if (!std::binary_search(faces.begin(), faces.end(), face_key(f[0], f[1], f[2]))) continue;
      Tri6 lf{};
      for (int a = 0; a < 6; ++a) lf[a] = local_of[static_cast<std::size_t>(f[a])];
      lb.faces.push_back(lf);
    }
    sub.mesh.boundaries.push_back(std::move(lb));
  }
  return sub;
}

SectionSubdomain extract_subdomain(const SectionMesh& mesh, const MeshPartition& partition,
                                   int part) {
  SectionSubdomain sub;
  const std::vector<Index> local_of = extract_elements(mesh, partition, part, sub);
  for (std::size_t e = 0; e < sub.global_element.size(); ++e)
    if (!mesh.triangle_region.empty())
      sub.mesh.triangle_region.push_back(
          mesh.triangle_region[static_cast<std::size_t>(sub.global_element[e])]);
  // Boundary segments: those on an edge of the part's triangles.
  std::vector<EdgeKey> edges;
  for (Index e : sub.global_element) {
    const Tri6& t = mesh.triangles[static_cast<std::size_t>(e)];
    for (const auto& [a, b] : kTriEdges) edges.push_back(edge_key(t[a], t[b]));
  }
  std::sort(edges.begin(), edges.end());
  for (const SectionBoundary& b : mesh.boundaries) {
    SectionBoundary lb{b.name, {}};
    for (const Line3& s : b.segments) {
      if (!std::binary_search(edges.begin(), edges.end(), edge_key(s[0], s[1]))) continue;
      Line3 ls{};
      for (int a = 0; a < 3; ++a) ls[a] = local_of[static_cast<std::size_t>(s[a])];
      lb.segments.push_back(ls);
    }
    sub.mesh.boundaries.push_back(std::move(lb));
  }
  return sub;
}

std::vector<Index> unknown_order(const PartitionedNumbering& numbering,
                                 const std::vector<Index>& node_order) {
  std::vector<Index> order;
  order.reserve(static_cast<std::size_t>(numbering.components + 1) * node_order.size());
  for (const Index n : node_order) {
    const auto k = static_cast<std::size_t>(n);
    for (Index c = 0; c < numbering.components; ++c) order.push_back(numbering.u_base.at(k) + c);
    if (numbering.p_index.at(k) >= 0) order.push_back(numbering.p_index[k]);
  }
  return order;
}

}  // namespace biphasic
