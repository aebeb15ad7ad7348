#include "biphasic/fe/quadrature.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace biphasic {

std::pair<std::vector<double>, std::vector<double>> gauss_jacobi(int n, double alpha) {
  // Golub–Welsch: eigenvalues of the symmetric Jacobi matrix of the monic polynomials
  // orthogonal for (1 − x)^α on [−1, 1] (β = 0); weights from the first eigenvector components.
  const double beta = 0.0;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    const double s = 2.0 * k + alpha + beta;
    T(k, k) = (k == 0) ? (beta - alpha) / (alpha + beta + 2.0)
                       : (beta * beta - alpha * alpha) / (s * (s + 2.0));
    if (k + 1 < n) {
      const double m = k + 1.0;
      const double sm = 2.0 * m + alpha + beta;
      const double b2 = 4.0 * m * (m + alpha) * (m + beta) * (m + alpha + beta) /
                        (sm * sm * (sm + 1.0) * (sm - 1.0));
      T(k, k + 1) = T(k + 1, k) = std::sqrt(b2);
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(T);
  const double mu0 = std::pow(2.0, alpha + beta + 1.0) * std::tgamma(alpha + 1.0) *
                     std::tgamma(beta + 1.0) / std::tgamma(alpha + beta + 2.0);
  std::vector<double> x(n), w(n);
  for (int i = 0; i < n; ++i) {
    x[i] = eig.eigenvalues()(i);
    const double v0 = eig.eigenvectors()(0, i);
    w[i] = mu0 * v0 * v0;
  }
  return {x, w};
}

namespace {

/// Conical product rule: ξ₃ = c, ξ₂ = b(1 − c), ξ₁ = a(1 − b)(1 − c), with
/// dξ = (1 − b)(1 − c)² da db dc; Gauss–Jacobi in b (α = 1) and c (α = 2) absorbs the factor.
QuadratureRule conical_rule(int n) {
  const auto [xa, wa] = gauss_jacobi(n, 0.0);
  const auto [xb, wb] = gauss_jacobi(n, 1.0);
  const auto [xc, wc] = gauss_jacobi(n, 2.0);
  QuadratureRule rule;
  rule.degree = 2 * n - 1;
  for (int i = 0; i < n; ++i) {
    const double a = 0.5 * (1.0 + xa[i]);
    for (int j = 0; j < n; ++j) {
      const double b = 0.5 * (1.0 + xb[j]);
      for (int k = 0; k < n; ++k) {
        const double c = 0.5 * (1.0 + xc[k]);
        // Map [−1,1] → [0,1]: dx/2 per direction and ((1 − x)/2)^α = (1 − b)^α.
        const double w = wa[i] / 2.0 * wb[j] / 4.0 * wc[k] / 8.0;
        rule.points.push_back({{a * (1.0 - b) * (1.0 - c), b * (1.0 - c), c}, w});
      }
    }
  }
  return rule;
}

/// Points symmetric under permutation of the four barycentric coordinates (a, b, b, b).
void add_orbit4(QuadratureRule& rule, double a, double b, double w) {
  const double bary[4][4] = {{a, b, b, b}, {b, a, b, b}, {b, b, a, b}, {b, b, b, a}};
  for (const auto& l : bary) rule.points.push_back({{l[1], l[2], l[3]}, w});
}

}  // namespace

const std::vector<int>& tet_quadrature_sizes() {
  static const std::vector<int> sizes{1, 4, 5, 8, 27, 64, 125};
  return sizes;
}

QuadratureRule tet_quadrature(int num_points) {
  QuadratureRule rule;
  switch (num_points) {
    case 1:
      rule.degree = 1;
      rule.points.push_back({{0.25, 0.25, 0.25}, 1.0 / 6.0});
      return rule;
    case 4: {
      // Degree 2: barycentric (a, b, b, b), a = (5 + 3√5)/20, b = (5 − √5)/20.
      rule.degree = 2;
      add_orbit4(rule, (5.0 + 3.0 * std::sqrt(5.0)) / 20.0, (5.0 - std::sqrt(5.0)) / 20.0,
                 1.0 / 24.0);
      return rule;
    }
    case 5:
      // Degree 3: centroid with weight −4/5 and (1/2, 1/6, 1/6, 1/6) with 9/20 (× volume 1/6).
      rule.degree = 3;
      rule.points.push_back({{0.25, 0.25, 0.25}, -0.8 / 6.0});
      add_orbit4(rule, 0.5, 1.0 / 6.0, 0.45 / 6.0);
      return rule;
    case 8:
      return conical_rule(2);
    case 27:
      return conical_rule(3);
    case 64:
      return conical_rule(4);
    case 125:
      return conical_rule(5);
    default:
      throw std::invalid_argument("no tetrahedron quadrature rule with " +
                                  std::to_string(num_points) +
                                  " points (choose 1, 4, 5, 8, 27, 64 or 125)");
  }
}

}  // namespace biphasic
