// Cryer's sphere: roots, the notes' centre pressures and peaks, the undrained start, and the
// derived p(r, T) checked against the diffusion equation and its centre limit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../common/peak.hpp"
#include "biphasic/analytic/cryer.hpp"

namespace biphasic::analytic {
namespace {

TEST(Cryer, RootsSolveTheirEquation) {
  for (double nu : {-0.5, 0.0, 0.2, 0.45, 0.499}) {
    const double eta = (1.0 - nu) / (2.0 * (1.0 - 2.0 * nu));
    const std::vector<double> roots = cryer_roots(nu, 200);
    ASSERT_EQ(roots.size(), 200u);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const double x = roots[i];
      // (1 − η ξ²) sin ξ − ξ cos ξ = 0, relative to the size of its terms.
      EXPECT_NEAR((1.0 - eta * x * x) * std::sin(x) - x * std::cos(x), 0.0,
                  1e-12 * (1.0 + eta * x * x))
          << "ν = " << nu << ", root " << i;
      if (i > 0) {  // one root per branch of tan, about π apart
        EXPECT_GT(roots[i] - roots[i - 1], 2.0);
        EXPECT_LT(roots[i] - roots[i - 1], 5.0);
      }
    }
    // Large roots approach nπ from below (tan ξ ≈ −1/(η ξ)).
    EXPECT_NEAR(roots.back(), 200.0 * std::numbers::pi, 1.0 / (eta * roots.back()) * 1.01);
  }
}

TEST(Cryer, TabulatedCentrePressure) {
  EXPECT_NEAR(cryer_center_pressure(0.2, 0.01), 1.1757625, 5.1e-8);
  EXPECT_NEAR(cryer_center_pressure(0.2, 0.1), 1.1941033, 5.1e-8);
  EXPECT_NEAR(cryer_center_pressure(0.2, 0.2), 0.6817272, 5.1e-8);
}

TEST(Cryer, TabulatedPeaks) {
  const auto [T2, p2] =
      testing::maximise([](double T) { return cryer_center_pressure(0.2, T); }, 0.01, 0.2);
  EXPECT_NEAR(p2, 1.364269, 5.1e-7);
  EXPECT_NEAR(T2, 0.052, 0.0005);
  const auto [T0, p0] =
      testing::maximise([](double T) { return cryer_center_pressure(0.0, T); }, 0.01, 0.2);
  EXPECT_NEAR(p0, 1.575425, 5.1e-7);
  EXPECT_NEAR(T0, 0.0627, 0.0001);
}

TEST(Cryer, UndrainedStartAndBoundaries) {
  EXPECT_EQ(cryer_pressure(0.2, 0.5, 0.0), 1.0);
  EXPECT_NEAR(cryer_center_pressure(0.2, 1e-6), 1.0, 1e-2);
  EXPECT_NEAR(cryer_center_pressure(0.2, 1e-8), 1.0, 1e-3);
  for (double T : {1e-3, 0.1, 1.0}) {
    EXPECT_EQ(cryer_pressure(0.2, 1.0, T), 0.0);
    EXPECT_NEAR(cryer_pressure(0.2, 0.999999, T), 0.0, 1e-4);
    EXPECT_NEAR(cryer_pressure(0.2, 1e-7, T), cryer_center_pressure(0.2, T), 1e-12);
  }
  EXPECT_NEAR(cryer_center_pressure(0.2, 10.0), 0.0, 1e-12);
  EXPECT_THROW(cryer_pressure(0.2, -0.1, 0.1), std::domain_error);
}

TEST(Cryer, SatisfiesTheDiffusionEquationUpToAUniformTerm) {
  // p = H_A (e − e(R)) with e diffusing, so ∂p/∂T − ∇²p (∇² = ∂²/∂ρ² + (2/ρ) ∂/∂ρ) is uniform.
  const double h = 1e-3;
  for (double nu : {0.0, 0.2}) {
    for (double T : {0.02, 0.1, 0.4}) {
      auto p = [&](double r, double TT) { return cryer_pressure(nu, r, TT); };
      double first = 0.0;
      for (double r : {0.2, 0.5, 0.8}) {
        const double lap = (p(r + h, T) - 2 * p(r, T) + p(r - h, T)) / (h * h) +
                           (p(r + h, T) - p(r - h, T)) / (h * r);
        const double source = (p(r, T * (1 + h)) - p(r, T * (1 - h))) / (2 * h * T) - lap;
        if (r == 0.2) first = source;
        EXPECT_NEAR(source, first, 1e-4) << "ν = " << nu << ", r/R = " << r << ", T = " << T;
      }
    }
  }
}

}  // namespace
}  // namespace biphasic::analytic
