// The Holmes–Mow solid at one point: stress against differences of the energy, tangent against
// differences of the stress (also with the pore pressure), the contracted stiffness the kernel
// uses, the stress-free reference state, the small-strain limit and β = 0.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <variant>

#include "biphasic/material/holmes_mow_solid.hpp"
#include "biphasic/material/material_laws.hpp"

namespace biphasic {
namespace {

using Tangent4 = std::array<Mat3, 9>;  ///< A[3i + k](J, L) = ∂P_iJ/∂F_kL

const HolmesMowSolid kLaws[] = {
    {1.0, 0.3, 0.8}, {0.7, 0.0, 0.0}, {2.0, -0.3, 1.5}, {0.5, 0.45, 0.35}};

std::string name_of(const HolmesMowSolid& m) {
  return "E=" + std::to_string(m.E) + " nu=" + std::to_string(m.nu) +
         " beta=" + std::to_string(m.beta);
}

/// Random deformation gradients F = R U-like with det F spread over [0.6, 1.5].
std::vector<Mat3> random_gradients(unsigned seed, int count) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> entry(-0.25, 0.25), volume(0.6, 1.5);
  std::vector<Mat3> out;
  while (static_cast<int>(out.size()) < count) {
    Mat3 F = Mat3::Identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F(i, j) += entry(gen);
    const double J = F.determinant();
    if (!(J > 0.3)) continue;
    F *= std::cbrt(volume(gen) / J);  // det F = the drawn volume ratio
    out.push_back(F);
  }
  return out;
}

/// Central differences of f (a number or a matrix) in each F_kL with step h: d[k][L].
template <class Fn>
auto differences(const Fn& f, const Mat3& F, double h) {
  using Value = std::decay_t<decltype(f(F))>;
  std::array<std::array<Value, 3>, 3> d;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      Mat3 Fp = F, Fm = F;
      Fp(k, L) += h;
      Fm(k, L) -= h;
      d[static_cast<std::size_t>(k)][static_cast<std::size_t>(L)] = (f(Fp) - f(Fm)) / (2.0 * h);
    }
  return d;
}

/// ∂P_iJ/∂F_kL of `piola` by central differences with step h.
template <class Piola>
Tangent4 difference_tangent(const Piola& piola, const Mat3& F, double h) {
  const auto d = differences([&](const Mat3& X) -> Mat3 { return piola(X); }, F, h);
  Tangent4 A;
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t L = 0; L < 3; ++L)
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t J = 0; J < 3; ++J)
          A[3 * i + k](static_cast<int>(J), static_cast<int>(L)) =
              d[k][L](static_cast<int>(i), static_cast<int>(J));
  return A;
}

/// Largest |stiffness(b, G, a, i, e, k) − ∇₀N_a,J A_iJkL ∇₀N_e,L| over all a, i, e, k,
/// relative to the largest contraction, for shape gradients dN.
template <class Response>
double stiffness_error(const Response& r, const Tangent4& A, const Mat3& F,
                       const ShapeGradients& dN) {
  const ShapeGradients b = dN * F.inverse();
  const ShapeProducts G = dN * dN.transpose();
  double err = 0.0, scale = 0.0;
  for (int a = 0; a < 10; ++a)
    for (int e = 0; e < 10; ++e)
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
          const double ref =
              dN.row(a).dot(A[static_cast<std::size_t>(3 * i + k)] * dN.row(e).transpose());
          err = std::max(err, std::abs(r.stiffness(b, G, a, i, e, k) - ref));
          scale = std::max(scale, std::abs(ref));
        }
  return err / scale;
}

ShapeGradients some_shape_gradients() {
  ShapeGradients dN;
  for (int a = 0; a < 10; ++a)
    for (int j = 0; j < 3; ++j) dN(a, j) = 0.1 * (a + 1) * (j - 1.2) + 0.05 * a * a * (j == 1);
  return dN;
}

// P = ∂W/∂F: central differences of the energy (step 1e-6), relative to |P| + H_A.
TEST(HolmesMowSolid, StressIsTheEnergyGradient) {
  for (const HolmesMowSolid& m : kLaws)
    for (const Mat3& F : random_gradients(11, 8)) {
      const Mat3 P = m.first_piola(F);
      const auto d = differences([&](const Mat3& X) { return m.energy(X); }, F, 1e-6);
      Mat3 dW;
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          dW(k, L) = d[static_cast<std::size_t>(k)][static_cast<std::size_t>(L)];
      EXPECT_LT((dW - P).norm() / (P.norm() + m.p_wave_modulus()), 1e-8)
          << name_of(m) << " J=" << F.determinant();
    }
}

// ∂P/∂F by central differences of P (step 1e-6) contracted with shape gradients equals the
// response's stiffness; the response's stress is the law's; both with and without a pore
// pressure p (the mixture stress P − pJF⁻ᵀ, J = det F varying with F).
TEST(HolmesMowSolid, StiffnessIsTheContractedStressDerivative) {
  const ShapeGradients dN = some_shape_gradients();
  const double p = 0.37;
  for (const HolmesMowSolid& m : kLaws)
    for (const Mat3& F : random_gradients(23, 6)) {
      const double J = F.determinant();
      const Mat3 FinvT = F.inverse().transpose();
      const auto r = m.response(F, J);
      EXPECT_LT((r.first_piola(F, FinvT) - m.first_piola(F)).norm(), 1e-13 * m.p_wave_modulus());
      const Tangent4 A =
          difference_tangent([&](const Mat3& X) { return m.first_piola(X); }, F, 1e-6);
      EXPECT_LT(stiffness_error(r, A, F, dN), 1e-8) << name_of(m) << " J=" << J;

      auto mixture = [&](const Mat3& X) -> Mat3 {
        return m.first_piola(X) - p * X.determinant() * X.inverse().transpose();
      };
      const auto rp = r.with_pore_pressure(p * J);
      EXPECT_LT((rp.first_piola(F, FinvT) - mixture(F)).norm(), 1e-13 * m.p_wave_modulus());
      EXPECT_LT(stiffness_error(rp, difference_tangent(mixture, F, 1e-6), F, dN), 1e-8)
          << name_of(m) << " J=" << J << " with p";
    }
}

// The check above sees a wrong tangent: the same stress with the tangent of β = 0 fails it.
TEST(HolmesMowSolid, WrongTangentIsDetected) {
  const HolmesMowSolid m{1.0, 0.3, 0.8}, flat{1.0, 0.3, 0.0};
  const ShapeGradients dN = some_shape_gradients();
  const Mat3 F = random_gradients(5, 1).front();
  auto r = flat.response(F, F.determinant());
  r.tau = m.response(F, F.determinant()).tau;
  const Tangent4 A = difference_tangent([&](const Mat3& X) { return m.first_piola(X); }, F, 1e-6);
  EXPECT_GT(stiffness_error(r, A, F, dN), 1e-2);
}

// Stress free and energy free at F = I; H_A = λ + 2μ = E(1 − ν)/((1 + ν)(1 − 2ν)).
TEST(HolmesMowSolid, ReferenceStateAndModuli) {
  for (const HolmesMowSolid& m : kLaws) {
    EXPECT_EQ(m.energy(Mat3::Identity()), 0.0);
    EXPECT_LT(m.first_piola(Mat3::Identity()).norm(), 1e-15);
    EXPECT_NEAR(m.p_wave_modulus(), m.E * (1 - m.nu) / ((1 + m.nu) * (1 - 2 * m.nu)), 1e-14);
    EXPECT_NEAR(m.mu(), m.E / (2 * (1 + m.nu)), 1e-15);
  }
  const HolmesMowSolid m{1.0, 0.25, 1.0};
  EXPECT_NEAR(m.lambda(), 0.4, 1e-15);
  EXPECT_NEAR(m.mu(), 0.4, 1e-15);
  EXPECT_THROW(m.first_piola(Mat3::Zero()), std::domain_error);
}

// F = I + εH: P = λ tr(ε) 1 + 2μ ε + O(ε²), ε = sym(εH), so the relative error of linear
// elasticity with the given E, ν falls as ε (by 10 per decade).
TEST(HolmesMowSolid, SmallStrainLimitIsLinearElasticity) {
  Mat3 H;
  H << 0.3, -0.7, 0.2, 0.5, -0.4, 0.9, -0.1, 0.6, 0.8;
  for (const HolmesMowSolid& m : kLaws) {
    const double lam = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)), mu = m.E / (2 * (1 + m.nu));
    std::vector<double> errors;
    for (double eps : {1e-3, 1e-4, 1e-5}) {
      const Mat3 strain = 0.5 * eps * (H + H.transpose());
      const Mat3 linear = lam * strain.trace() * Mat3::Identity() + 2.0 * mu * strain;
      const Mat3 P = m.first_piola(Mat3::Identity() + eps * H);
      errors.push_back((P - linear).norm() / linear.norm());
    }
    EXPECT_LT(errors[0], 1e-2) << name_of(m);
    EXPECT_NEAR(errors[0] / errors[1], 10.0, 0.5) << name_of(m);
    EXPECT_NEAR(errors[1] / errors[2], 10.0, 0.5) << name_of(m);
  }
}

// P(QF) = Q P(F), W(QF) = W(F) for a rotation Q.
TEST(HolmesMowSolid, FrameIndifferent) {
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  for (const HolmesMowSolid& m : kLaws)
    for (const Mat3& F : random_gradients(31, 3)) {
      EXPECT_LT((m.first_piola(Q * F) - Q * m.first_piola(F)).norm(),
                1e-13 * (1.0 + m.first_piola(F).norm()));
      EXPECT_NEAR(m.energy(Q * F), m.energy(F), 1e-13 * (1.0 + std::abs(m.energy(F))));
    }
}

// β = 0 is the limit of β → 0: energy and stress continuous.
TEST(HolmesMowSolid, ZeroBetaIsTheLimit) {
  const Mat3 F = random_gradients(3, 1).front();
  const HolmesMowSolid zero{1.0, 0.3, 0.0}, tiny{1.0, 0.3, 1e-9};
  EXPECT_NEAR(zero.energy(F), tiny.energy(F), 1e-9 * std::abs(zero.energy(F)));
  EXPECT_LT((zero.first_piola(F) - tiny.first_piola(F)).norm(), 1e-8);
  EXPECT_GT(zero.energy(F), 0.0);
}

TEST(HolmesMowSolid, RegistryBuildsTheChosenSolid) {
  MaterialConfig c;
  c.solid_law = "holmes_mow";
  c.set("youngs_modulus", 0.6);
  c.set("poissons_ratio", 0.1);
  c.set("beta", 0.4);
  const MaterialLaws laws = make_material_laws(c);
  ASSERT_TRUE(std::holds_alternative<HolmesMowSolid>(laws.solid));
  const auto& m = std::get<HolmesMowSolid>(laws.solid);
  EXPECT_EQ(m.E, 0.6);
  EXPECT_EQ(m.nu, 0.1);
  EXPECT_EQ(m.beta, 0.4);
  EXPECT_DOUBLE_EQ(laws.p_wave_modulus(), 0.6 * 0.9 / (1.1 * 0.8));
}

}  // namespace
}  // namespace biphasic
