// Unconfined compression (Armstrong, Lai & Mow 1984): roots, the notes' force and centre
// pressure, the derived pressure series checked against the force (through the mean pressure)
// and the diffusion equation, and the ramp response against Duhamel's integral.
#include <gtest/gtest.h>

#include <cmath>

#include "biphasic/analytic/unconfined_compression.hpp"

namespace biphasic::analytic {
namespace {

const UnconfinedCompression& solution(double nu) {
  static const UnconfinedCompression nu01(0.1), nu03(0.3);
  return nu == 0.1 ? nu01 : nu03;
}

TEST(UnconfinedCompression, RootsSolveTheirEquation) {
  for (double nu : {-0.5, 0.0, 0.1, 0.3, 0.49}) {
    const double beta = (1.0 - nu) / (1.0 - 2.0 * nu);
    const std::vector<double> roots = unconfined_roots(nu, 50);
    ASSERT_EQ(roots.size(), 50u);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const double a = roots[i];
      EXPECT_NEAR(std::cyl_bessel_j(1.0, a) - beta * a * std::cyl_bessel_j(0.0, a), 0.0,
                  1e-13 * beta * a)
          << "ν = " << nu << ", root " << i;
      if (i > 0) {
        EXPECT_GT(a - roots[i - 1], 2.5);
      }
    }
  }
  EXPECT_NEAR(unconfined_roots(0.1, 1)[0], 1.9233059, 5.1e-8);
  const std::vector<double>& stored = solution(0.1).roots();
  EXPECT_GT(stored.size(), 390u);
  EXPECT_NEAR(stored[5], unconfined_roots(0.1, 6)[5], 1e-14);
}

TEST(UnconfinedCompression, TabulatedForceAndCentrePressure) {
  const UnconfinedCompression& u = solution(0.1);
  EXPECT_NEAR(u.force(0.0), 1.363636, 5.1e-7);
  EXPECT_NEAR(u.force(0.01), 1.316555, 5.1e-7);
  EXPECT_NEAR(u.force(0.1), 1.207546, 5.1e-7);
  EXPECT_NEAR(u.force(1.0), 1.007375, 5.1e-7);
  EXPECT_NEAR(u.pressure(0.0, 0.1), 1.168530, 5.1e-7);
}

TEST(UnconfinedCompression, LimitsAndBoundaries) {
  for (double nu : {0.1, 0.3}) {
    const UnconfinedCompression& u = solution(nu);
    // Undrained 3μ/E at 0⁺ (the series joins it), drained E at ∞.
    EXPECT_NEAR(u.force(1e-7), 3.0 / (2.0 * (1.0 + nu)), 2e-3);
    EXPECT_NEAR(u.force(50.0), 1.0, 1e-12);
    EXPECT_NEAR(u.pressure(0.0, 1e-7), 1.0, 2e-3);
    EXPECT_NEAR(u.pressure(0.5, 50.0), 0.0, 1e-12);
    EXPECT_EQ(u.pressure(1.0, 0.1), 0.0);
    EXPECT_NEAR(u.pressure(0.999999, 0.1), 0.0, 1e-4);
  }
  EXPECT_THROW(UnconfinedCompression(0.5), std::domain_error);
  EXPECT_THROW(solution(0.1).pressure(1.2, 0.1), std::domain_error);
  EXPECT_THROW(solution(0.1).ramp_force(0.1, 0.0), std::domain_error);
}

TEST(UnconfinedCompression, ForceFollowsFromTheMeanPressure) {
  // With p = H_A (e − e(a)) and σ_rr(a) = 0: F/(π a² ε₀ E) = [3 + (1 − 2ν)(p̄/(μ ε₀) − 1)]/(2(1 +
  // ν)), p̄ = 2 ∫₀¹ p ρ dρ (composite Simpson): ties the derived pressure series to the force
  // series.
  for (double nu : {0.1, 0.3}) {
    const UnconfinedCompression& u = solution(nu);
    for (double tau : {0.01, 0.1, 0.5}) {
      const int n = 2000;
      double mean = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double r = static_cast<double>(i) / n;
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        mean += w * 2.0 * r * u.pressure(r, tau);
      }
      mean /= 3.0 * n;
      EXPECT_NEAR(u.force(tau), (3.0 + (1.0 - 2.0 * nu) * (mean - 1.0)) / (2.0 * (1.0 + nu)), 1e-9)
          << "ν = " << nu << ", τ = " << tau;
    }
  }
}

TEST(UnconfinedCompression, PressureSatisfiesTheDiffusionEquationUpToAUniformTerm) {
  // ∂p/∂τ − (p'' + p'/ρ) is uniform in ρ.
  const UnconfinedCompression& u = solution(0.1);
  const double h = 1e-3;
  for (double tau : {0.02, 0.1, 0.4}) {
    auto p = [&](double r, double t) { return u.pressure(r, t); };
    double first = 0.0;
    for (double r : {0.2, 0.5, 0.8}) {
      const double lap = (p(r + h, tau) - 2 * p(r, tau) + p(r - h, tau)) / (h * h) +
                         (p(r + h, tau) - p(r - h, tau)) / (2 * h * r);
      const double source = (p(r, tau * (1 + h)) - p(r, tau * (1 - h))) / (2 * h * tau) - lap;
      if (r == 0.2) first = source;
      EXPECT_NEAR(source, first, 1e-4) << "r/a = " << r << ", τ = " << tau;
    }
  }
}

TEST(UnconfinedCompression, RampIsDuhamelsIntegralOfTheStep) {
  const UnconfinedCompression& u = solution(0.1);
  const double tau0 = 0.1;
  // During the ramp: d(τ₀ R)/dτ = S(τ).
  for (double tau : {0.02, 0.05, 0.09}) {
    const double h = 1e-4;
    EXPECT_NEAR((u.ramp_force(tau + h, tau0) - u.ramp_force(tau - h, tau0)) * tau0 / (2 * h),
                u.force(tau), 1e-6);
    EXPECT_NEAR((u.ramp_pressure(0.3, tau + h, tau0) - u.ramp_pressure(0.3, tau - h, tau0)) * tau0 /
                    (2 * h),
                u.pressure(0.3, tau), 1e-6);
  }
  // During the hold: R(τ) = (1/τ₀) ∫_{τ−τ₀}^{τ} S(v) dv (composite Simpson).
  for (double tau : {0.15, 0.3, 1.0}) {
    const int n = 200;
    double force = 0.0, pressure = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double v = tau - tau0 + tau0 * i / n;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      force += w * u.force(v);
      pressure += w * u.pressure(0.0, v);
    }
    EXPECT_NEAR(u.ramp_force(tau, tau0), force / (3.0 * n), 1e-9) << "τ = " << tau;
    EXPECT_NEAR(u.ramp_pressure(0.0, tau, tau0), pressure / (3.0 * n), 1e-9) << "τ = " << tau;
  }
  // Continuous at τ₀, zero at the start, drained at the end, and a short ramp is a step.
  EXPECT_NEAR(u.ramp_force(tau0, tau0), u.ramp_force(tau0 * (1 + 1e-12), tau0), 1e-10);
  EXPECT_NEAR(u.ramp_pressure(0.3, tau0, tau0), u.ramp_pressure(0.3, tau0 * (1 + 1e-12), tau0),
              1e-10);
  EXPECT_EQ(u.ramp_force(0.0, tau0), 0.0);
  EXPECT_NEAR(u.ramp_force(50.0, tau0), 1.0, 1e-12);
  EXPECT_NEAR(u.ramp_force(0.1, 1e-8), u.force(0.1 - 0.5e-8), 1e-10);
  EXPECT_NEAR(u.ramp_pressure(0.0, 0.1, 1e-8), u.pressure(0.0, 0.1 - 0.5e-8), 1e-10);
}

}  // namespace
}  // namespace biphasic::analytic
