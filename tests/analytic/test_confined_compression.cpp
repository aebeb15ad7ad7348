// Ramp confined compression: Mow et al.'s linear solution and the finite-strain Neo-Hookean
// reference against the verification notes' table, plus independent checks (the plain series,
// the energy of the uniaxial stress, agreement of the two at small strain).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "biphasic/analytic/confined_compression.hpp"

namespace biphasic::analytic {
namespace {

const std::vector<double> kTimes = {10, 25, 50, 75, 100, 150, 200, 300, 500, 1000};
const std::vector<double> kLinear = {-0.11283792, -0.17841241, -0.25231325, -0.30901940,
                                     -0.35682625, -0.18477553, -0.14833894, -0.11767632,
                                     -0.10245288, -0.10001764};
const std::vector<double> kFinite = {-0.11155918, -0.17533683, -0.24642583, -0.30048056,
                                     -0.34576140, -0.17653116, -0.14259997, -0.11646558,
                                     -0.10650098, -0.10555762};

/// E = 1 and ν as Lamé parameters.
ConfinedRamp with_poisson(double nu) {
  ConfinedRamp c;
  c.mu = 1.0 / (2.0 * (1.0 + nu));
  c.lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  return c;
}

/// Mow's series summed plainly: σ_ramp with the constant h²/(3 H_A k) and 20000 terms.
double plain_ramp(const ConfinedRamp& c, double t) {
  if (t <= 0.0) return 0.0;
  const double HA = c.lambda + 2.0 * c.mu, k = c.permeability, h = c.thickness;
  const double V0 = c.strain * h / c.ramp_time, pi2 = std::numbers::pi * std::numbers::pi;
  double sum = 0.0;
  for (int n = 20000; n >= 1; --n) sum += std::exp(-HA * k * n * n * pi2 * t / (h * h)) / (n * n);
  return -(HA * V0 / h) * (t + h * h / (3.0 * HA * k) - 2.0 * h * h / (pi2 * HA * k) * sum);
}

TEST(ConfinedRampLinear, Tabulated) {
  const ConfinedRamp c;  // μ = 0.5, λ = 0, k = 1e-3, h = 1, 10 % over 100 s
  for (std::size_t i = 0; i < kTimes.size(); ++i) {
    EXPECT_NEAR(confined_ramp_stress_linear(c, kTimes[i]), kLinear[i], 5.1e-9)
        << "t = " << kTimes[i];
  }
  EXPECT_NEAR(confined_ramp_stress_linear(c, 1e5), -0.1, 1e-12);
  EXPECT_EQ(confined_ramp_stress_linear(c, 0.0), 0.0);
}

TEST(ConfinedRampLinear, ShortTimeFormAgreesWithThePlainSeries) {
  // c t/h² < 0.1 (t < 100 s here) uses the erfc form; 20000 terms converge from t ≈ 0.1 s.
  ConfinedRamp c = with_poisson(0.3);
  for (double t : {0.5, 3.0, 10.0, 40.0, 99.9, 100.0, 120.0, 350.0, 2000.0}) {
    const double expected =
        t <= c.ramp_time ? plain_ramp(c, t) : plain_ramp(c, t) - plain_ramp(c, t - c.ramp_time);
    EXPECT_NEAR(confined_ramp_stress_linear(c, t), expected, 1e-12) << "t = " << t;
  }
}

TEST(ConfinedRampFiniteStrain, UniaxialStressIsTheEnergyDerivative) {
  // Ψ(λ_z) = μ/2 (λ_z² − 1) − μ ln λ_z + λ/2 (ln λ_z)² in uniaxial strain; P_eff = dΨ/dλ_z.
  const double mu = 0.4, lambda = 0.7;
  auto psi = [&](double s) {
    return 0.5 * mu * (s * s - 1.0) - mu * std::log(s) + 0.5 * lambda * std::log(s) * std::log(s);
  };
  for (double s : {0.5, 0.8, 0.9, 1.0, 1.2}) {
    const double e = 1e-5;
    EXPECT_NEAR(neo_hookean_uniaxial_stress(mu, lambda, s), (psi(s + e) - psi(s - e)) / (2 * e),
                1e-9);
  }
  // λ = 0: μ (λ_z² − 1)/λ_z; the notes' equilibrium values.
  EXPECT_NEAR(neo_hookean_uniaxial_stress(0.5, 0.0, 0.9), 0.5 * (0.81 - 1.0) / 0.9, 1e-16);
  EXPECT_NEAR(neo_hookean_uniaxial_stress(0.5, 0.0, 0.9), -0.1055556, 5.1e-8);
  const ConfinedRamp c = with_poisson(0.3);
  EXPECT_NEAR(neo_hookean_uniaxial_stress(c.mu, c.lambda, 0.9), -0.14873537, 5.1e-9);
  EXPECT_THROW(neo_hookean_uniaxial_stress(0.5, 0.0, 0.0), std::domain_error);
}

TEST(ConfinedRampFiniteStrain, Tabulated) {
  const ConfinedRamp c;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> sigma = confined_ramp_stress_neo_hookean(c, kTimes);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("seconds", std::to_string(seconds));
  ASSERT_EQ(sigma.size(), kTimes.size());
  for (std::size_t i = 0; i < kTimes.size(); ++i) {
    // The converged values agree with the table to 1.4e−6 (t = 10 s) and 4e−7 (25 s), and to
    // the table's 8 decimals from 50 s on.
    EXPECT_NEAR(sigma[i], kFinite[i], 2e-6 * std::abs(kFinite[i])) << "t = " << kTimes[i];
  }
  // Long hold: the equilibrium μ (λ_z² − 1)/λ_z at λ_z = 0.9.
  const double tail[] = {20000.0};
  EXPECT_NEAR(confined_ramp_stress_neo_hookean(c, tail)[0],
              neo_hookean_uniaxial_stress(c.mu, c.lambda, 0.9), 1e-9);
}

TEST(ConfinedRampFiniteStrain, TabulatedWithPoissonRatio) {
  const ConfinedRamp c = with_poisson(0.3);  // E = 1, ν = 0.3
  const double times[] = {100.0, 20000.0};
  const std::vector<double> sigma = confined_ramp_stress_neo_hookean(c, times);
  EXPECT_NEAR(sigma[0], -0.42305259, 2e-6 * 0.42305259);
  EXPECT_NEAR(sigma[1], -0.14873537, 1e-8);
}

TEST(ConfinedRampFiniteStrain, ResolutionIndependent) {
  // The default resolution against twice as fine, and the order of the requested times.
  const ConfinedRamp c;
  const std::vector<double> times = {1000, 5, 100, 37.5, 100.5};
  const std::vector<double> a = confined_ramp_stress_neo_hookean(c, times);
  const std::vector<double> b = confined_ramp_stress_neo_hookean(c, times, {400, 400, true});
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_NEAR(a[i], b[i], 1e-6 * std::abs(b[i])) << "t = " << times[i];
  }
  const std::vector<double> coarse = confined_ramp_stress_neo_hookean(c, times, {200, 200, false});
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_NEAR(coarse[i], b[i], 1e-3 * std::abs(b[i])) << "t = " << times[i];
  }
}

TEST(ConfinedRampFiniteStrain, AgreesWithLinearTheoryAtSmallStrain) {
  // A 0.1 % ramp: finite strain and linear theory differ by O(strain), i.e. < 0.1 %.
  for (double nu : {0.0, 0.3}) {
    ConfinedRamp c = with_poisson(nu);
    c.strain = 1e-3;
    const std::vector<double> times = {1, 10, 50, 100, 101, 150, 300, 1000, 3000};
    const std::vector<double> sigma = confined_ramp_stress_neo_hookean(c, times);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const double linear = confined_ramp_stress_linear(c, times[i]);
      EXPECT_LT(std::abs(sigma[i] / linear - 1.0), 1e-3) << "ν = " << nu << ", t = " << times[i];
    }
  }
  // At a strain of 1e−6 the difference is only O(1e−6): the discretisation error is below that.
  ConfinedRamp c;
  c.strain = 1e-6;
  const std::vector<double> sigma = confined_ramp_stress_neo_hookean(c, kTimes);
  for (std::size_t i = 0; i < kTimes.size(); ++i) {
    EXPECT_LT(std::abs(sigma[i] / confined_ramp_stress_linear(c, kTimes[i]) - 1.0), 1e-6)
        << "t = " << kTimes[i];
  }
}

/// FEBio's column with a Holmes–Mow permeability, φ₀ = 0.2, κ = 1, M = 4: at λ_z = 0.9 the
/// permeability is (0.7/0.8) e^{−0.38} = 60 % of k₀.
ConfinedRamp holmes_mow() {
  ConfinedRamp c;
  c.solid_fraction = 0.2;
  c.permeability_kappa = 1.0;
  c.permeability_M = 4.0;
  return c;
}

TEST(ConfinedRampHolmesMow, PermeabilityFollowsTheLaw) {
  const ConfinedRamp c = holmes_mow();
  EXPECT_DOUBLE_EQ(confined_permeability(c, 1.0), 1e-3);
  EXPECT_NEAR(confined_permeability(c, 0.9), 1e-3 * 0.875 * std::exp(-0.38), 1e-18);
  EXPECT_THROW(confined_permeability(c, 0.2), std::domain_error);
  EXPECT_EQ(confined_permeability(ConfinedRamp{}, 0.5), 1e-3);
}

// M = 1e−12 takes the numerically integrated potential with k(s) = k₀ (1 + O(1e−12)): it must
// give the closed-form potential's answer, which checks the quadrature of Φ.
TEST(ConfinedRampHolmesMow, NumericalPotentialMatchesTheClosedForm) {
  ConfinedRamp c = with_poisson(0.3);
  const std::vector<double> constant = confined_ramp_stress_neo_hookean(c, kTimes);
  c.solid_fraction = 0.2;
  c.permeability_M = 1e-12;
  const std::vector<double> numeric = confined_ramp_stress_neo_hookean(c, kTimes);
  for (std::size_t i = 0; i < kTimes.size(); ++i)
    EXPECT_NEAR(numeric[i], constant[i], 1e-10 * std::abs(constant[i])) << "t = " << kTimes[i];
}

// A permeability falling with compression drains the column more slowly: the ramp's stress is
// higher, the relaxation slower, and equilibrium, which does not depend on k, the same
// P_eff(0.9) = μ (0.9 − 1/0.9).
TEST(ConfinedRampHolmesMow, SlowerDrainageSameEquilibrium) {
  const std::vector<double> times = {10, 50, 100, 200, 500, 1e5};
  const std::vector<double> constant = confined_ramp_stress_neo_hookean(ConfinedRamp{}, times);
  const std::vector<double> hm = confined_ramp_stress_neo_hookean(holmes_mow(), times);
  for (std::size_t i = 0; i + 1 < times.size(); ++i)
    EXPECT_LT(hm[i], constant[i] - 0.01 * std::abs(constant[i])) << "t = " << times[i];
  const double equilibrium = 0.5 * (0.9 - 1.0 / 0.9);
  EXPECT_NEAR(hm.back(), equilibrium, 1e-9);
  EXPECT_NEAR(constant.back(), equilibrium, 1e-9);
}

TEST(ConfinedRampHolmesMow, ResolutionIndependent) {
  const ConfinedRamp c = holmes_mow();
  const std::vector<double> a = confined_ramp_stress_neo_hookean(c, kTimes);
  const std::vector<double> b = confined_ramp_stress_neo_hookean(c, kTimes, {400, 400, true});
  for (std::size_t i = 0; i < kTimes.size(); ++i)
    EXPECT_NEAR(a[i], b[i], 2e-6 * std::abs(b[i])) << "t = " << kTimes[i];
}

// At a strain of 1e−6, k(λ_z) = k₀ (1 + O(1e−5)) and the column is linear: the series holds.
TEST(ConfinedRampHolmesMow, AgreesWithLinearTheoryAtSmallStrain) {
  ConfinedRamp c = holmes_mow();
  c.strain = 1e-6;
  const std::vector<double> sigma = confined_ramp_stress_neo_hookean(c, kTimes);
  for (std::size_t i = 0; i < kTimes.size(); ++i) {
    EXPECT_LT(std::abs(sigma[i] / confined_ramp_stress_linear(c, kTimes[i]) - 1.0), 2e-5)
        << "t = " << kTimes[i];
  }
}

// ---- layered permeability ----------------------------------------------------------------

/// FEBio's column (μ = 0.5, λ = 0, h = 1, 10 % over 100 s) with two layers of k₀ given.
ConfinedRamp two_layers(double lower_fraction, double k_lower, double k_upper) {
  ConfinedRamp c;
  c.permeability = k_lower;
  c.layers = {{lower_fraction, k_lower}, {1.0 - lower_fraction, k_upper}};
  return c;
}

TEST(ConfinedRampLayers, EqualLayersReproduceTheSingleLayer) {
  // Two layers of the same k: only the grid differs (one node moved onto the interface), so the
  // answer agrees to the reference's accuracy; an interface on a grid node changes nothing.
  const ConfinedRamp single;
  const std::vector<double> a = confined_ramp_stress_neo_hookean(single, kTimes);
  const std::vector<double> b =
      confined_ramp_stress_neo_hookean(two_layers(0.5, 1e-3, 1e-3), kTimes);
  for (std::size_t i = 0; i < kTimes.size(); ++i)
    EXPECT_NEAR(b[i], a[i], 2e-6 * std::abs(a[i])) << "t = " << kTimes[i];
  ConfinedRamp one_layer = single;
  one_layer.layers = {{1.0, 1e-3}};
  const std::vector<double> c = confined_ramp_stress_neo_hookean(one_layer, kTimes);
  for (std::size_t i = 0; i < kTimes.size(); ++i) EXPECT_EQ(c[i], a[i]) << "t = " << kTimes[i];
}

TEST(ConfinedRampLayers, EquilibriumStressIsIndependentOfThePermeability) {
  const double times[] = {100.0, 40000.0};
  const double equilibrium = neo_hookean_uniaxial_stress(0.5, 0.0, 0.9);
  for (const ConfinedRamp& c : {two_layers(0.5, 1e-3, 2.5e-4), two_layers(0.3, 2.5e-4, 1e-3)}) {
    const std::vector<double> sigma = confined_ramp_stress_neo_hookean(c, times);
    EXPECT_NEAR(sigma[1], equilibrium, 1e-7);
    EXPECT_LT(sigma[0], equilibrium);  // not yet relaxed at the end of the ramp
  }
}

TEST(ConfinedRampLayers, LieBetweenTheUniformColumnsAndAreResolutionIndependent) {
  // A less permeable upper half: drains slower than the column of k₁ everywhere and faster than
  // that of k₂ = k₁/4 everywhere, so |σ| at the end of the ramp lies between theirs.
  const ConfinedRamp layered = two_layers(0.5, 1e-3, 2.5e-4);
  const std::vector<double> a = confined_ramp_stress_neo_hookean(layered, kTimes);
  ConfinedRamp fast, slow;
  slow.permeability = 2.5e-4;
  const double t0[] = {100.0};
  const double sigma_fast = confined_ramp_stress_neo_hookean(fast, t0)[0];
  const double sigma_slow = confined_ramp_stress_neo_hookean(slow, t0)[0];
  EXPECT_LT(a[4], sigma_fast);
  EXPECT_GT(a[4], sigma_slow);
  const std::vector<double> fine = confined_ramp_stress_neo_hookean(layered, kTimes, {400, 400});
  for (std::size_t i = 0; i < kTimes.size(); ++i)
    EXPECT_NEAR(a[i], fine[i], 1e-5 * std::abs(fine[i])) << "t = " << kTimes[i];
  std::cout << "[ layered column ] sigma(100 s) = " << a[4] << " MPa (k1 column " << sigma_fast
            << ", k1/4 column " << sigma_slow << ")\n";
}

TEST(ConfinedRampLayers, RefusesBadLayers) {
  ConfinedRamp c = two_layers(0.5, 1e-3, 2.5e-4);
  c.layers[1].fraction = 0.4;
  EXPECT_THROW(confined_ramp_stress_neo_hookean(c, kTimes), std::domain_error);
  c.layers[1] = {0.5, 0.0};
  EXPECT_THROW(confined_ramp_stress_neo_hookean(c, kTimes), std::domain_error);
  EXPECT_THROW(confined_ramp_stress_linear(two_layers(0.5, 1e-3, 2.5e-4), 10.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace biphasic::analytic
