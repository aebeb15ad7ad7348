#include "biphasic/fe/tet_geometry.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

double tet_volume(const TetCorners& x) {
  return (x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]) / 6.0;
}

double tet_circumradius(const TetCorners& x) {
  // Centre c: 2 (xᵢ − x₀)·c = |xᵢ|² − |x₀|², i = 1..3; radius |c − x₀|.
  Mat3 A;
  Vec3 rhs;
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = x[i + 1] - x[0];
    A.row(i) = 2.0 * d.transpose();
    rhs(i) = x[i + 1].squaredNorm() - x[0].squaredNorm();
  }
  const Vec3 c = A.partialPivLu().solve(rhs);
  return (c - x[0]).norm();
}

double tet_shortest_edge(const TetCorners& x) {
  double h = INFINITY;
  for (const auto& e : kTetEdges) h = std::min(h, (x[e[0]] - x[e[1]]).norm());
  return h;
}

double tet_longest_edge(const TetCorners& x) {
  double h = 0.0;
  for (const auto& e : kTetEdges) h = std::max(h, (x[e[0]] - x[e[1]]).norm());
  return h;
}

double tet_volume_diameter(const TetCorners& x) {
  return std::cbrt(6.0 * std::abs(tet_volume(x)) / std::numbers::pi);
}

}  // namespace biphasic
