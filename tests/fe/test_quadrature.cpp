// Quadrature rules integrate polynomials of their degree exactly on a distorted tetrahedron.
// Truth: for a linear form ℓ, ∫_T ℓ(x)^d dx = d! 3! V / (d+3)! · h_d(ℓ(v₀), …, ℓ(v₃)),
// h_d the complete homogeneous symmetric polynomial of degree d; powers of linear forms span
// all polynomials of degree d.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "biphasic/fe/quadrature.hpp"
#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {
namespace {

double factorial(int n) { return std::tgamma(n + 1.0); }

/// h_d(a₀, …, a₃) = Σ_{|k| = d} Π a_i^{k_i}.
double complete_homogeneous(const std::array<double, 4>& a, int d) {
  double sum = 0.0;
  for (int k0 = 0; k0 <= d; ++k0)
    for (int k1 = 0; k0 + k1 <= d; ++k1)
      for (int k2 = 0; k0 + k1 + k2 <= d; ++k2) {
        const int k3 = d - k0 - k1 - k2;
        sum += std::pow(a[0], k0) * std::pow(a[1], k1) * std::pow(a[2], k2) * std::pow(a[3], k3);
      }
  return sum;
}

const Eigen::Matrix<double, 4, 3> kCorners =
    (Eigen::Matrix<double, 4, 3>() << 0.2, -0.1, 0.3, 1.7, 0.2, -0.2, 0.4, 1.3, 0.1, -0.3, 0.5, 1.1)
        .finished();

double integrate(const QuadratureRule& rule, const std::function<double(const Vec3&)>& f) {
  const Mat3 A = (Mat3() << (kCorners.row(1) - kCorners.row(0)).transpose(),
                  (kCorners.row(2) - kCorners.row(0)).transpose(),
                  (kCorners.row(3) - kCorners.row(0)).transpose())
                     .finished();  // columns: edge vectors
  double sum = 0.0;
  for (const auto& q : rule.points) {
    const Vec3 x = kCorners.row(0).transpose() + A * Vec3(q.xi[0], q.xi[1], q.xi[2]);
    sum += q.weight * f(x);
  }
  return sum * std::abs(A.determinant());
}

class Quadrature : public ::testing::TestWithParam<int> {};

TEST_P(Quadrature, ExactUpToItsDegree) {
  const QuadratureRule rule = tet_quadrature(GetParam());
  ASSERT_EQ(static_cast<int>(rule.points.size()), GetParam());
  const Mat3 E = (Mat3() << (kCorners.row(1) - kCorners.row(0)).transpose(),
                  (kCorners.row(2) - kCorners.row(0)).transpose(),
                  (kCorners.row(3) - kCorners.row(0)).transpose())
                     .finished();
  const double V = std::abs(E.determinant()) / 6.0;
  const Vec3 forms[] = {{0.7, -1.1, 0.4}, {-0.3, 0.5, 1.2}, {1.0, 0.9, -0.6}};
  for (const Vec3& l : forms) {
    for (int d = 0; d <= rule.degree; ++d) {
      std::array<double, 4> a{};
      for (int i = 0; i < 4; ++i) a[i] = l.dot(kCorners.row(i).transpose());
      const double exact = factorial(d) * 6.0 * V / factorial(d + 3) * complete_homogeneous(a, d);
      const double approx = integrate(rule, [&](const Vec3& x) { return std::pow(l.dot(x), d); });
      EXPECT_NEAR(approx, exact, 1e-13 * std::max(1.0, std::abs(exact)))
          << GetParam() << "-point rule, degree " << d;
    }
  }
}

TEST_P(Quadrature, DegreeIsSharp) {
  // Some polynomial of degree + 1 is not integrated exactly (so the stated degree is honest).
  const QuadratureRule rule = tet_quadrature(GetParam());
  const int d = rule.degree + 1;
  double worst = 0.0;
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j) {
      const int k = d - i - j;
      // ∫ ξ^i η^j ζ^k over the reference tetrahedron = i! j! k! / (d + 3)!.
      const double exact = factorial(i) * factorial(j) * factorial(k) / factorial(d + 3);
      double approx = 0.0;
      for (const auto& q : rule.points)
        approx += q.weight * std::pow(q.xi[0], i) * std::pow(q.xi[1], j) * std::pow(q.xi[2], k);
      worst = std::max(worst, std::abs(approx - exact) / exact);
    }
  EXPECT_GT(worst, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(AllRules, Quadrature, ::testing::ValuesIn(tet_quadrature_sizes()));

TEST(Quadrature, UnknownSizeIsRejected) { EXPECT_THROW(tet_quadrature(7), std::invalid_argument); }

TEST(TriangleQuadrature, ExactToDegreeFour) {
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j) {
      double approx = 0.0;
      for (const auto& q : triangle_quadrature())
        approx += q.weight * std::pow(q.eta[0], i) * std::pow(q.eta[1], j);
      EXPECT_NEAR(approx, factorial(i) * factorial(j) / factorial(i + j + 2), 1e-14);
    }
}

}  // namespace
}  // namespace biphasic
