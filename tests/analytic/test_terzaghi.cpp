// Terzaghi consolidation: the verification notes' tabulated values, the short-time form against
// a plain Fourier sum, the diffusion equation by finite differences, and U as the integral of
// the pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "biphasic/analytic/terzaghi.hpp"

namespace biphasic::analytic {
namespace {

/// The Fourier series summed plainly with a fixed, generous number of terms.
double fourier_pressure(double x, double T, int terms) {
  double sum = 0.0;
  for (int m = 0; m < terms; ++m) {
    const double M = (2 * m + 1) * std::numbers::pi / 2.0;
    sum += 2.0 / M * std::sin(M * x) * std::exp(-M * M * T);
  }
  return sum;
}

TEST(Terzaghi, TabulatedPressureAndDegreeOfConsolidation) {
  const double zeta[] = {0.1, 0.25, 0.5, 0.75, 1.0};
  struct Row {
    double T, p[5], U;
  };
  const Row table[] = {
      {0.01, {0.5204999, 0.9229001, 0.9995930, 0.9999999, 1.0000000}, 0.1128379},
      {0.05, {0.2481704, 0.5708047, 0.8861516, 0.9822167, 0.9968692}, 0.2523133},
      {0.1, {0.1769179, 0.4237593, 0.7356513, 0.9012789, 0.9493054}, 0.3568234},
      {0.2, {0.1238687, 0.3020839, 0.5531759, 0.7162273, 0.7723116}, 0.5040878},
      {0.5, {0.0580063, 0.1418987, 0.2621883, 0.3425571, 0.3707774}, 0.7639503},
      {1.0, {0.0168913, 0.0413210, 0.0763513, 0.0997578, 0.1079770}, 0.9312597},
  };
  for (const Row& row : table) {
    for (int i = 0; i < 5; ++i) {
      EXPECT_NEAR(terzaghi_pressure(zeta[i], row.T), row.p[i], 5.1e-8)
          << "ζ/H = " << zeta[i] << ", T = " << row.T;
    }
    EXPECT_NEAR(terzaghi_degree_of_consolidation(row.T), row.U, 5.1e-8) << "T = " << row.T;
  }
}

TEST(Terzaghi, LimitsAndBoundaryValues) {
  EXPECT_EQ(terzaghi_pressure(0.3, 0.0), 1.0);
  EXPECT_EQ(terzaghi_degree_of_consolidation(0.0), 0.0);
  for (double T : {1e-6, 0.05, 0.1, 0.3, 2.0}) EXPECT_EQ(terzaghi_pressure(0.0, T), 0.0);
  EXPECT_NEAR(terzaghi_pressure(1.0, 20.0), 0.0, 1e-15);
  EXPECT_NEAR(terzaghi_degree_of_consolidation(20.0), 1.0, 1e-15);
  EXPECT_THROW(terzaghi_pressure(1.5, 0.1), std::domain_error);
  EXPECT_THROW(terzaghi_pressure(0.5, -1.0), std::domain_error);
}

TEST(Terzaghi, ShortTimeFormAgreesWithTheFourierSeries) {
  // Below T = 0.1 the erfc images are used; 4000 Fourier terms converge down to T = 1e-4.
  for (double T : {1e-4, 1e-3, 0.01, 0.0999, 0.1, 0.1001, 0.5}) {
    for (double x : {0.005, 0.01, 0.05, 0.1, 0.3, 0.5, 0.9, 1.0}) {
      EXPECT_NEAR(terzaghi_pressure(x, T), fourier_pressure(x, T, 4000), 1e-12)
          << "ζ/H = " << x << ", T = " << T;
    }
  }
  // At very early times only the drained face's image matters: p/q = erf(ζ/(2√T)).
  EXPECT_NEAR(terzaghi_pressure(0.01, 1e-4), std::erf(0.5), 1e-12);
  EXPECT_NEAR(terzaghi_degree_of_consolidation(1e-4), 2.0 * std::sqrt(1e-4 / std::numbers::pi),
              1e-15);
}

TEST(Terzaghi, SatisfiesTheDiffusionEquation) {
  // ∂p/∂T = ∂²p/∂(ζ/H)² by central differences (error O(h²) ≈ 1e-6 of the derivatives).
  const double h = 1e-3;
  for (double T : {0.01, 0.05, 0.1, 0.2, 0.5}) {
    for (double x : {0.1, 0.3, 0.5, 0.8}) {
      const double dpdT =
          (terzaghi_pressure(x, T + h * T) - terzaghi_pressure(x, T - h * T)) / (2 * h * T);
      const double d2p = (terzaghi_pressure(x + h, T) - 2 * terzaghi_pressure(x, T) +
                          terzaghi_pressure(x - h, T)) /
                         (h * h);
      EXPECT_NEAR(dpdT, d2p, 2e-5 * (1.0 + std::abs(d2p))) << "ζ/H = " << x << ", T = " << T;
    }
  }
}

TEST(Terzaghi, DegreeOfConsolidationIsTheLostPressure) {
  // U = 1 − ∫₀¹ p/q d(ζ/H), composite Simpson with 2000 intervals.
  for (double T : {0.01, 0.05, 0.1, 0.3, 1.0}) {
    const int n = 2000;
    double integral = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      integral += w * terzaghi_pressure(static_cast<double>(i) / n, T);
    }
    integral /= 3.0 * n;
    EXPECT_NEAR(terzaghi_degree_of_consolidation(T), 1.0 - integral, 1e-10) << "T = " << T;
  }
}

}  // namespace
}  // namespace biphasic::analytic
