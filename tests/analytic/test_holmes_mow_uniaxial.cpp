// The Holmes–Mow uniaxial references: the lateral stretch of uniaxial stress against the
// quadratic formula, the confined closed form against the general principal-stretch stress,
// and the small-strain moduli E and H_A.
#include <gtest/gtest.h>

#include <cmath>

#include "biphasic/analytic/holmes_mow_uniaxial.hpp"

namespace biphasic::analytic {
namespace {

const HolmesMowParameters kCases[] = {
    {0.8, 0.3, 0.6}, {1.0, 0.0, 0.0}, {2.0, -0.4, 1.5}, {0.5, 0.49, 0.35}};

// x = λ₂² solves λ x² + s x − H_A = 0, s = 2μ + λ(λ₁² − 1): x = 2 H_A/(s + √(s² + 4 λ H_A)).
TEST(HolmesMowUniaxial, LateralStretchIsTheQuadraticRoot) {
  for (const HolmesMowParameters& m : kCases) {
    const double lam = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)), mu = m.E / (2 * (1 + m.nu));
    const double Ha = lam + 2 * mu;
    EXPECT_NEAR(holmes_mow_uniaxial_lateral_stretch(m, 1.0), 1.0, 1e-15);
    for (double stretch : {0.5, 0.8, 0.95, 1.1, 1.3}) {
      const double s = 2 * mu + lam * (stretch * stretch - 1);
      const double x = 2 * Ha / (s + std::sqrt(s * s + 4 * lam * Ha));
      EXPECT_NEAR(holmes_mow_uniaxial_lateral_stretch(m, stretch), std::sqrt(x), 1e-14)
          << m.nu << " " << stretch;
    }
    // ν = 0: no lateral expansion at all.
    if (m.nu == 0.0) {
      EXPECT_NEAR(holmes_mow_uniaxial_lateral_stretch(m, 0.7), 1.0, 1e-15);
    }
  }
}

// Confined: the closed form equals the principal-stretch stress with λ₂ = 1; both stresses
// vanish at λ₁ = 1 and have slopes E (uniaxial) and H_A (confined) there.
TEST(HolmesMowUniaxial, ConfinedFormAndSmallStrainModuli) {
  for (const HolmesMowParameters& m : kCases) {
    const double Ha = m.E * (1 - m.nu) / ((1 + m.nu) * (1 - 2 * m.nu));
    for (double stretch : {0.6, 0.8, 1.0, 1.2})
      EXPECT_NEAR(holmes_mow_confined_stress(m, stretch),
                  holmes_mow_nominal_stress(m, stretch, 1.0), 1e-14 * Ha);
    EXPECT_NEAR(holmes_mow_uniaxial_stress(m, 1.0), 0.0, 1e-14 * Ha);
    const double h = 1e-6;
    const double slope_u =
        (holmes_mow_uniaxial_stress(m, 1 + h) - holmes_mow_uniaxial_stress(m, 1 - h)) / (2 * h);
    const double slope_c =
        (holmes_mow_confined_stress(m, 1 + h) - holmes_mow_confined_stress(m, 1 - h)) / (2 * h);
    EXPECT_NEAR(slope_u / m.E, 1.0, 1e-7);
    EXPECT_NEAR(slope_c / Ha, 1.0, 1e-7);
  }
}

// β stiffens: at 20 % compression the confined stress grows with β by exp(β(λ² − 1)) λ^(−2β).
TEST(HolmesMowUniaxial, BetaStiffensByTheExponentialFactor) {
  const double stretch = 0.8;
  const HolmesMowParameters soft{1.0, 0.2, 0.0}, stiff{1.0, 0.2, 2.0};
  EXPECT_NEAR(
      holmes_mow_confined_stress(stiff, stretch) / holmes_mow_confined_stress(soft, stretch),
      std::exp(2.0 * (0.64 - 1.0)) * std::pow(0.8, -4.0), 1e-13);
}

}  // namespace
}  // namespace biphasic::analytic
