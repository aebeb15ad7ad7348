// Quadrature rules on the reference tetrahedron {ξ ≥ 0, ξ₁ + ξ₂ + ξ₃ ≤ 1} (volume 1/6).
#pragma once

#include <array>
#include <vector>

namespace biphasic {

struct QuadraturePoint {
  std::array<double, 3> xi;  ///< reference coordinates
  double weight;             ///< weights sum to 1/6
};

struct QuadratureRule {
  std::vector<QuadraturePoint> points;
  int degree = 0;  ///< polynomials of total degree ≤ degree are integrated exactly
};

/// The rule with this number of points: 1 (degree 1), 4 (degree 2, the paper's rule),
/// 5 (degree 3), or a collapsed Gauss–Jacobi product rule with n³ points for
/// n = 2, 3, 4, 5 (8, 27, 64, 125 points; degree 2n − 1). Throws for other counts.
QuadratureRule tet_quadrature(int num_points);

/// Point counts accepted by tet_quadrature.
const std::vector<int>& tet_quadrature_sizes();

/// Gauss–Jacobi rule with n points on [−1, 1] for the weight (1 − x)^α (Golub–Welsch).
/// Returns (nodes, weights).
std::pair<std::vector<double>, std::vector<double>> gauss_jacobi(int n, double alpha);

}  // namespace biphasic
