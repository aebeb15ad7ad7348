// Mandel's problem: roots, the notes' centre pressures and peaks (the Mandel–Cryer effect),
// the undrained start and the boundary values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../common/peak.hpp"
#include "biphasic/analytic/mandel.hpp"

namespace biphasic::analytic {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Mandel, RootsSolveTheirEquationInTheirBrackets) {
  for (double nu : {-0.5, 0.0, 0.2, 0.45, 0.499}) {
    const double r = (1.0 - nu) / (0.5 - nu);
    const std::vector<double> roots = mandel_roots(nu, 200);
    ASSERT_EQ(roots.size(), 200u);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const double a = roots[i];
      EXPECT_NEAR(std::sin(a) - r * a * std::cos(a), 0.0, 1e-13 * r * a) << "ν = " << nu;
      const double lo = i == 0 ? 0.0 : static_cast<double>(i) * kPi;
      EXPECT_GT(a, lo);
      EXPECT_LT(a, lo + kPi / 2.0);
    }
  }
  EXPECT_THROW(mandel_roots(0.5, 3), std::domain_error);
}

TEST(Mandel, TabulatedCentrePressure) {
  EXPECT_NEAR(mandel_pressure(0.2, 0.0, 0.01), 0.5218806, 5.1e-8);
  EXPECT_NEAR(mandel_pressure(0.2, 0.0, 0.1), 0.5477069, 5.1e-8);
  EXPECT_NEAR(mandel_pressure(0.2, 0.0, 0.5), 0.2963927, 5.1e-8);
}

TEST(Mandel, TabulatedPeaks) {
  const auto [T2, p2] =
      testing::maximise([](double T) { return mandel_pressure(0.2, 0.0, T); }, 0.01, 0.3);
  EXPECT_NEAR(p2, 0.553448, 5.1e-7);
  EXPECT_NEAR(T2, 0.072, 0.0005);
  const auto [T0, p0] =
      testing::maximise([](double T) { return mandel_pressure(0.0, 0.0, T); }, 0.01, 0.3);
  EXPECT_NEAR(p0, 0.577776, 5.1e-7);
  EXPECT_NEAR(T0, 0.083, 0.0005);
}

TEST(Mandel, UndrainedStartAndBoundaries) {
  EXPECT_EQ(mandel_pressure(0.2, 0.3, 0.0), 0.5);
  // Approaching p = σ₀/2 as T → 0 (the rise above it grows like √T inside the slab).
  EXPECT_NEAR(mandel_pressure(0.2, 0.0, 1e-7), 0.5, 1e-3);
  EXPECT_NEAR(mandel_pressure(0.2, 0.5, 1e-5), 0.5, 2e-3);
  for (double T : {1e-3, 0.1, 1.0}) {
    EXPECT_EQ(mandel_pressure(0.2, 1.0, T), 0.0);
    EXPECT_EQ(mandel_pressure(0.2, -1.0, T), 0.0);
    EXPECT_NEAR(mandel_pressure(0.2, 0.999999, T), 0.0, 1e-4);
    EXPECT_DOUBLE_EQ(mandel_pressure(0.2, 0.4, T), mandel_pressure(0.2, -0.4, T));
  }
  EXPECT_NEAR(mandel_pressure(0.2, 0.0, 40.0), 0.0, 1e-12);  // e^{−α₁² T}, α₁ ≈ 1.29
  EXPECT_THROW(mandel_pressure(0.2, 1.1, 0.1), std::domain_error);
}

TEST(Mandel, SatisfiesTheDiffusionEquationUpToAUniformTerm) {
  // p = H_A e − f(T) with e diffusing, so ∂p/∂T − ∂²p/∂x² is uniform in x.
  const double h = 1e-3;
  for (double T : {0.02, 0.1, 0.4}) {
    double first = 0.0;
    for (double x : {0.0, 0.3, 0.6, 0.9}) {
      auto p = [&](double xx, double TT) { return mandel_pressure(0.2, xx, TT); };
      const double source = (p(x, T * (1 + h)) - p(x, T * (1 - h))) / (2 * h * T) -
                            (p(x + h, T) - 2 * p(x, T) + p(x - h, T)) / (h * h);
      if (x == 0.0) first = source;
      EXPECT_NEAR(source, first, 1e-4) << "x/a = " << x << ", T = " << T;
    }
  }
}

}  // namespace
}  // namespace biphasic::analytic
