// Mesh queries, orientation fixes and invariant checks.
#include "biphasic/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace biphasic {

namespace {

Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Key of the unordered vertex pair {a, b}; vertex indices are below `num_vertices`.
std::uint64_t pair_key(Index a, Index b, Index num_vertices) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo * static_cast<std::uint64_t>(num_vertices) + hi;
}

std::array<Index, 3> sorted_corners(const Tri6& face) {
  std::array<Index, 3> key{face[0], face[1], face[2]};
  std::sort(key.begin(), key.end());
  return key;
}

[[noreturn]] void fail(const std::string& message) {
  throw std::runtime_error("check_mesh: " + message);
}

}  // namespace

const Boundary* Mesh::find_boundary(const std::string& name) const {
  const auto it = std::find_if(boundaries.begin(), boundaries.end(),
                               [&](const Boundary& b) { return b.name == name; });
  return it == boundaries.end() ? nullptr : &*it;
}

std::vector<std::string> Mesh::boundary_names() const {
  std::vector<std::string> names;
  names.reserve(boundaries.size());
  for (const Boundary& b : boundaries) names.push_back(b.name);
  return names;
}

const NodeSet* Mesh::find_node_set(const std::string& name) const {
  const auto it = std::find_if(node_sets.begin(), node_sets.end(),
                               [&](const NodeSet& s) { return s.name == name; });
  return it == node_sets.end() ? nullptr : &*it;
}

std::string Mesh::describe_node(Index n) const {
  std::ostringstream s;
  s << "node " << n;
  if (n >= 0 && static_cast<std::size_t>(n) < file_tags.size() && file_tags[n] >= 0)
    s << " (file tag " << file_tags[n] << ")";
  if (n >= 0 && n < num_nodes()) {
    const Point& x = nodes[static_cast<std::size_t>(n)];
    s << " at (" << x[0] << ", " << x[1] << ", " << x[2] << ") mm";
  }
  return s.str();
}

double tet_signed_volume(const Point& a, const Point& b, const Point& c, const Point& d) {
  return dot(sub(b, a), cross(sub(c, a), sub(d, a))) / 6.0;
}

double tet_signed_volume(const Mesh& mesh, Index t) {
  const Tet10& tet = mesh.tets.at(static_cast<std::size_t>(t));
  const auto& x = mesh.nodes;
  return tet_signed_volume(x.at(tet[0]), x.at(tet[1]), x.at(tet[2]), x.at(tet[3]));
}

void orient_tets(Mesh& mesh) {
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    Tet10& tet = mesh.tets[t];
    const double volume = tet_signed_volume(mesh, static_cast<Index>(t));
    double longest2 = 0.0;
    for (const auto& [a, b] : kTetEdges) {
      const Point e = sub(mesh.nodes[tet[a]], mesh.nodes[tet[b]]);
      longest2 = std::max(longest2, dot(e, e));
    }
    const double longest = std::sqrt(longest2);
    if (!(std::abs(volume) > 1e-12 * longest * longest * longest)) {
      std::ostringstream msg;
      msg << "orient_tets: tetrahedron " << t << " is degenerate (volume " << volume
          << " mm^3, longest edge " << longest << " mm)";
      throw std::runtime_error(msg.str());
    }
    if (volume < 0.0) {
      std::swap(tet[1], tet[2]);
      std::swap(tet[4], tet[6]);
      std::swap(tet[8], tet[9]);
    }
  }
}

void orient_boundary_faces(Mesh& mesh) {
  // For each boundary face: the corner of a tet having that face, opposite to it.
  std::map<std::array<Index, 3>, Index> opposite;
  for (const Boundary& b : mesh.boundaries) {
    for (const Tri6& f : b.faces) opposite.emplace(sorted_corners(f), Index{-1});
  }
  if (opposite.empty()) return;
  for (const Tet10& tet : mesh.tets) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<Index, 3> key{};
      int k = 0;
      for (int c = 0; c < 4; ++c) {
        if (c != skip) key[k++] = tet[c];
      }
      std::sort(key.begin(), key.end());
      const auto it = opposite.find(key);
      if (it != opposite.end() && it->second < 0) it->second = tet[skip];
    }
  }
  for (Boundary& b : mesh.boundaries) {
    for (std::size_t i = 0; i < b.faces.size(); ++i) {
      Tri6& f = b.faces[i];
      const Index opp = opposite.at(sorted_corners(f));
      if (opp < 0) {
        std::ostringstream msg;
        msg << "orient_boundary_faces: boundary '" << b.name << "' face " << i << " (vertices "
            << f[0] << ", " << f[1] << ", " << f[2] << ") is not a face of any tetrahedron";
        throw std::runtime_error(msg.str());
      }
      const auto& x = mesh.nodes;
      const Point normal = cross(sub(x[f[1]], x[f[0]]), sub(x[f[2]], x[f[0]]));
      if (dot(normal, sub(x[opp], x[f[0]])) > 0.0) {
        std::swap(f[1], f[2]);
        std::swap(f[3], f[5]);
      }
    }
  }
}

int Mesh::find_region(const std::string& name) const {
  for (std::size_t r = 0; r < region_names.size(); ++r)
    if (region_names[r] == name) return static_cast<int>(r);
  return -1;
}

void check_mesh(const Mesh& mesh) {
  const Index nn = mesh.num_nodes();
  const Index nv = mesh.num_vertices;
  if (nv < 0 || nv > nn) {
    fail("num_vertices " + std::to_string(nv) + " outside [0, " + std::to_string(nn) + "]");
  }
  std::vector<char> vertex_used(static_cast<std::size_t>(nv), 0);
  std::vector<char> edge_node_used(static_cast<std::size_t>(nn - nv), 0);
  std::vector<std::uint64_t> edge_node_pair(static_cast<std::size_t>(nn - nv), 0);
  std::unordered_map<std::uint64_t, Index> edge_node;
  edge_node.reserve(mesh.tets.size() * 2);

  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const Tet10& tet = mesh.tets[t];
    const std::string where = "tetrahedron " + std::to_string(t);
    for (int c = 0; c < 4; ++c) {
      if (tet[c] < 0 || tet[c] >= nv) {
        fail(where + ": corner " + std::to_string(tet[c]) + " is not a vertex index");
      }
      vertex_used[tet[c]] = 1;
      for (int d = 0; d < c; ++d) {
        if (tet[c] == tet[d]) fail(where + ": repeated corner " + std::to_string(tet[c]));
      }
    }
    for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
      const Index n = tet[4 + e];
      if (n < nv || n >= nn) {
        fail(where + ": edge node " + std::to_string(n) + " is not an edge-node index");
      }
      const std::uint64_t key = pair_key(tet[kTetEdges[e][0]], tet[kTetEdges[e][1]], nv);
      const auto [it, inserted] = edge_node.emplace(key, n);
      if (!inserted && it->second != n) {
        fail(where + ": edge node " + std::to_string(n) + " differs from node " +
             std::to_string(it->second) + " used by another tet on the same edge");
      }
      const std::size_t slot = static_cast<std::size_t>(n - nv);
      if (edge_node_used[slot] && edge_node_pair[slot] != key) {
        fail(where + ": edge node " + std::to_string(n) + " sits on two different edges");
      }
      edge_node_used[slot] = 1;
      edge_node_pair[slot] = key;
    }
    const double volume = tet_signed_volume(mesh, static_cast<Index>(t));
    if (!(volume > 0.0)) {
      std::ostringstream msg;
      msg << where << ": non-positive volume " << volume << " mm^3";
      fail(msg.str());
    }
  }
  for (Index v = 0; v < nv; ++v) {
    if (!vertex_used[v]) fail("vertex " + std::to_string(v) + " is a corner of no tetrahedron");
  }
  for (Index n = nv; n < nn; ++n) {
    if (!edge_node_used[n - nv]) {
      fail("edge node " + std::to_string(n) + " belongs to no tetrahedron");
    }
  }
  for (const Boundary& b : mesh.boundaries) {
    for (std::size_t i = 0; i < b.faces.size(); ++i) {
      const Tri6& f = b.faces[i];
      const std::string where = "boundary '" + b.name + "' face " + std::to_string(i);
      for (int c = 0; c < 3; ++c) {
        if (f[c] < 0 || f[c] >= nv) {
          fail(where + ": corner " + std::to_string(f[c]) + " is not a vertex index");
        }
      }
      for (std::size_t e = 0; e < kTriEdges.size(); ++e) {
        const auto it = edge_node.find(pair_key(f[kTriEdges[e][0]], f[kTriEdges[e][1]], nv));
        if (it == edge_node.end()) fail(where + ": edge " + std::to_string(e) + " is no tet edge");
        if (it->second != f[3 + e]) {
          fail(where + ": edge node " + std::to_string(f[3 + e]) + " differs from the tets' " +
               std::to_string(it->second));
        }
      }
    }
  }
  check_node_sets(mesh);
  check_regions(mesh);
}

void check_regions(const Mesh& mesh) {
  if (mesh.tet_region.empty()) {
    if (!mesh.region_names.empty() && mesh.region_names.size() != 1)
      fail(std::to_string(mesh.region_names.size()) +
           " region names but no region per tetrahedron");
    return;
  }
  if (mesh.tet_region.size() != mesh.tets.size())
    fail(std::to_string(mesh.tet_region.size()) + " region entries for " +
         std::to_string(mesh.tets.size()) + " tetrahedra");
  const auto count = static_cast<int>(mesh.region_names.size());
  for (std::size_t t = 0; t < mesh.tet_region.size(); ++t)
    if (mesh.tet_region[t] < 0 || mesh.tet_region[t] >= count)
      fail("tetrahedron " + std::to_string(t) + ": region " + std::to_string(mesh.tet_region[t]) +
           " is not below the number of regions, " + std::to_string(count));
  for (int a = 0; a < count; ++a)
    for (int b = 0; b < a; ++b)
      if (mesh.region_names[a] == mesh.region_names[b])
        fail("two regions are named '" + mesh.region_names[a] + "'");
}

void check_node_sets(const Mesh& mesh) {
  const Index nn = mesh.num_nodes();
  // Boundary conditions name a set: a name given to a surface and a point or curve, or to a
  // point and a curve, would be resolved silently to one of them.
  auto kind = [](int dimension) {
    return dimension == 0 ? std::string("physical point") : std::string("physical curve");
  };
  for (std::size_t i = 0; i < mesh.node_sets.size(); ++i) {
    const NodeSet& s = mesh.node_sets[i];
    const std::string where = kind(s.dimension) + " '" + s.name + "'";
    for (const Index n : s.nodes)
      if (n < 0 || n >= nn) fail(where + ": node " + std::to_string(n) + " is not a node index");
    if (mesh.find_boundary(s.name)) {
      fail("the name '" + s.name + "' is given to a physical surface and a " + kind(s.dimension) +
           ": a boundary condition naming it would apply to the surface alone; rename one of "
           "them");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (mesh.node_sets[j].name == s.name) {
        fail("the name '" + s.name + "' is given to a " + kind(mesh.node_sets[j].dimension) +
             " and a " + kind(s.dimension) +
             ": a boundary condition naming it would apply to one of them alone; rename one of "
             "them");
      }
    }
  }
}

}  // namespace biphasic
