// Neo-Hookean skeleton: stress from the energy, tangent from the stress, objectivity.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "biphasic/material/neo_hookean.hpp"

namespace biphasic {
namespace {

Mat3 sample_F() {
  Mat3 F;
  F << 1.1, 0.2, -0.05, 0.03, 0.92, 0.1, -0.08, 0.04, 1.05;
  return F;
}

TEST(NeoHookean, StressFreeInTheReferenceState) {
  const NeoHookean m{0.2, 0.5};
  EXPECT_LT(m.first_piola(Mat3::Identity()).norm(), 1e-15);
  EXPECT_NEAR(m.energy(Mat3::Identity()), 0.0, 1e-15);
}

TEST(NeoHookean, StressIsTheDerivativeOfTheEnergy) {
  const NeoHookean m{0.2, 0.5};
  const Mat3 F = sample_F();
  const Mat3 P = m.first_piola(F);
  const double eps = 1e-6;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Mat3 Fp = F, Fm = F;
      Fp(i, j) += eps;
      Fm(i, j) -= eps;
      EXPECT_NEAR((m.energy(Fp) - m.energy(Fm)) / (2 * eps), P(i, j), 1e-9);
    }
}

TEST(NeoHookean, TangentIsTheDerivativeOfTheStress) {
  const NeoHookean m{0.2, 0.5};
  const Mat3 F = sample_F();
  Mat3 H;
  H << 0.3, -0.1, 0.2, 0.05, 0.4, -0.3, 0.1, 0.2, -0.2;
  const Mat3 exact = m.tangent_apply(F, H);
  double previous = 0.0;
  for (double eps : {1e-3, 5e-4}) {
    const Mat3 fd = (m.first_piola(F + eps * H) - m.first_piola(F - eps * H)) / (2 * eps);
    const double err = (fd - exact).norm();
    if (previous > 0.0) {
      EXPECT_NEAR(previous / err, 4.0, 0.3);  // O(ε²)
    }
    previous = err;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(NeoHookean, FrameIndifferent) {
  const NeoHookean m{0.2, 0.5};
  const Mat3 F = sample_F();
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  EXPECT_LT((m.first_piola(Q * F) - Q * m.first_piola(F)).norm(), 1e-14);
  EXPECT_NEAR(m.energy(Q * F), m.energy(F), 1e-14);
}

TEST(NeoHookean, RefusesInvertedDeformation) {
  const NeoHookean m{0.2, 0.5};
  Mat3 F = Mat3::Identity();
  F(2, 2) = -0.5;
  EXPECT_THROW(m.first_piola(F), std::domain_error);
}

}  // namespace
}  // namespace biphasic
