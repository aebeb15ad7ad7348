// Coincident nodes by spatial hashing: each node goes into the cell floor(X / tolerance); a
// pair closer than the tolerance lies in the same or in neighbouring cells.
#include "biphasic/mesh/coincident_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace biphasic {

namespace {

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

double distance2(const Point& a, const Point& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace

double coincidence_tolerance(const Mesh& mesh) {
  double shortest2 = std::numeric_limits<double>::infinity();
  for (const Tet10& t : mesh.tets)
    for (const auto& [a, b] : kTetEdges)
      shortest2 = std::min(shortest2, distance2(mesh.nodes[t[a]], mesh.nodes[t[b]]));
  return std::isfinite(shortest2) ? 1e-6 * std::sqrt(shortest2) : 0.0;
}

std::vector<std::pair<Index, Index>> coincident_nodes(const Mesh& mesh, double tolerance) {
  std::vector<std::pair<Index, Index>> pairs;
  if (!(tolerance > 0.0)) return pairs;
  const auto cell_of = [tolerance](const Point& x) {
    return Cell{static_cast<std::int64_t>(std::floor(x[0] / tolerance)),
                static_cast<std::int64_t>(std::floor(x[1] / tolerance)),
                static_cast<std::int64_t>(std::floor(x[2] / tolerance))};
  };
  std::unordered_map<Cell, std::vector<Index>, CellHash> cells;
  cells.reserve(mesh.nodes.size());
  for (Index n = 0; n < mesh.num_nodes(); ++n) cells[cell_of(mesh.nodes[n])].push_back(n);
  const double tol2 = tolerance * tolerance;
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Cell c = cell_of(mesh.nodes[n]);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (Index m : it->second)
            if (m > n && distance2(mesh.nodes[n], mesh.nodes[m]) < tol2) pairs.emplace_back(n, m);
        }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace biphasic
