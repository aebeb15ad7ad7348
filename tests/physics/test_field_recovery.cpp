// Recovered cell fields against closed forms: a homogeneous finite deformation under a uniform
// pore pressure gives the Neo-Hookean Cauchy stress, J and k(J) in every element; a linear
// pressure field gives the Darcy flux −k(J) F⁻ᵀ∇₀p, for a constant and a Holmes–Mow law.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/field_recovery.hpp"

namespace biphasic {
namespace {

constexpr double kLambda = 0.2, kMu = 0.5, kK0 = 1e-3;

/// A general (non-symmetric) deformation gradient with J ≈ 0.94.
Mat3 deformation() {
  Mat3 F;
  F << 0.95, 0.04, 0.02, -0.03, 1.02, 0.05, 0.01, -0.02, 0.97;
  return F;
}

/// The state u = (F − I) X on every node and p = p0 + a·X on every vertex.
std::vector<double> homogeneous_state(const BiphasicProblem& problem, const Mat3& F, double p0,
                                      const Vec3& a) {
  const Mesh& mesh = problem.mesh();
  std::vector<double> y(problem.size(), 0.0);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Vec3 X(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]);
    const Vec3 u = (F - Mat3::Identity()) * X;
    for (int c = 0; c < 3; ++c) y[problem.pattern().u_dof(n, c)] = u(c);
  }
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    const Vec3 X(mesh.nodes[v][0], mesh.nodes[v][1], mesh.nodes[v][2]);
    y[problem.pattern().p_dof(v)] = p0 + a.dot(X);
  }
  return y;
}

/// Entry `k` of a 3×3 matrix stored row by row.
double entry(const Mat3& s, int k) { return s(k / 3, k % 3); }

Config material_config() {
  Config cfg;
  cfg.material.set("lambda", kLambda);
  cfg.material.set("mu", kMu);
  cfg.material.set("permeability", kK0);
  return cfg;
}

TEST(FieldRecovery, HomogeneousDeformationGivesTheNeoHookeanCauchyStress) {
  const Mesh mesh = test::box_mesh({2, 2, 2}, {1.0, 1.5, 0.8});
  const Mat3 F = deformation();
  const double J = F.determinant();
  const double p0 = 0.013;
  // σ_eff = μ/J (b − I) + λ ln J / J I, b = F Fᵀ (written out, not through the law object).
  const Mat3 sigma_eff = kMu / J * (F * F.transpose() - Mat3::Identity()) +
                         kLambda * std::log(J) / J * Mat3::Identity();
  const Mat3 sigma = sigma_eff - p0 * Mat3::Identity();
  ASSERT_GT(sigma_eff.cwiseAbs().maxCoeff(), 1e-2);
  for (int points : {4, 27}) {
    Config cfg = material_config();
    cfg.quadrature_points = points;
    const BiphasicProblem problem(mesh, cfg);
    const std::vector<double> y = homogeneous_state(problem, F, p0, Vec3::Zero());
    const CellFields f = recover_cell_fields(problem, y.data());
    const std::size_t n = mesh.tets.size();
    ASSERT_EQ(f.stress.size(), 9 * n);
    ASSERT_EQ(f.effective_stress.size(), 9 * n);
    ASSERT_EQ(f.J.size(), n);
    ASSERT_EQ(f.flux.size(), 3 * n);
    ASSERT_EQ(f.permeability.size(), n);
    for (std::size_t e = 0; e < n; ++e) {
      for (int k = 0; k < 9; ++k) {
        EXPECT_NEAR(f.effective_stress[9 * e + k], entry(sigma_eff, k), 1e-15)
            << "element " << e << " component " << k << ", " << points << " points";
        EXPECT_NEAR(f.stress[9 * e + k], entry(sigma, k), 1e-15)
            << "element " << e << " component " << k << ", " << points << " points";
      }
      EXPECT_NEAR(f.J[e], J, 1e-15) << "element " << e;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.flux[3 * e + c], 0.0, 1e-18) << "element " << e;
      EXPECT_NEAR(f.permeability[e], kK0, 1e-18) << "element " << e;
    }
  }
}

TEST(FieldRecovery, LinearPressureGivesDarcyFlux) {
  const Mesh mesh = test::box_mesh({2, 1, 2}, {1.0, 1.5, 0.8});
  const BiphasicProblem problem(mesh, material_config());
  const Vec3 a(0.03, -0.02, 0.05);  // ∇p [MPa/mm]
  const std::vector<double> y = homogeneous_state(problem, Mat3::Identity(), 0.1, a);
  const CellFields f = recover_cell_fields(problem, y.data());
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.flux[3 * e + c], -kK0 * a(c), 1e-18) << e;
    EXPECT_NEAR(f.permeability[e], kK0, 1e-18) << e;
    EXPECT_NEAR(f.J[e], 1.0, 1e-15) << e;
    for (int k = 0; k < 9; ++k) EXPECT_EQ(f.effective_stress[9 * e + k], 0.0) << e;
    // Total stress −p̄ I, p̄ the element mean of 0.1 + a·X (its value at the centroid).
    const Tet10& tet = mesh.tets[e];
    Vec3 centroid = Vec3::Zero();
    for (int c = 0; c < 4; ++c)
      centroid += 0.25 * Vec3(mesh.nodes[tet[c]][0], mesh.nodes[tet[c]][1], mesh.nodes[tet[c]][2]);
    const double p_mean = 0.1 + a.dot(centroid);
    for (int k = 0; k < 9; ++k)
      EXPECT_NEAR(f.stress[9 * e + k], k % 4 == 0 ? -p_mean : 0.0, 1e-15) << e << " " << k;
  }
}

TEST(FieldRecovery, HolmesMowPermeabilityAndFluxOfADeformedState) {
  const Mesh mesh = test::box_mesh({1, 2, 2}, {1.0, 1.5, 0.8});
  Config cfg = material_config();
  cfg.material.permeability_law = "holmes_mow";
  cfg.material.set("solid_fraction", 0.25);
  cfg.material.set("permeability_kappa", 2.0);
  cfg.material.set("permeability_M", 3.0);
  const BiphasicProblem problem(mesh, cfg);
  const Mat3 F = deformation();
  const double J = F.determinant();
  const Vec3 a(-0.02, 0.01, 0.04);  // ∇₀p [MPa/mm]
  const std::vector<double> y = homogeneous_state(problem, F, 0.05, a);
  const CellFields f = recover_cell_fields(problem, y.data());
  // k(J) = k₀ ((J − φ₀)/(1 − φ₀))^κ exp(M (J² − 1)/2), written out here.
  const double k = kK0 * std::pow((J - 0.25) / (1.0 - 0.25), 2.0) * std::exp(1.5 * (J * J - 1.0));
  ASSERT_GT(std::abs(k / kK0 - 1.0), 0.1);
  const Vec3 w = -k * F.inverse().transpose() * a;  // ∇ₓp = F⁻ᵀ∇₀p
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    EXPECT_NEAR(f.permeability[e], k, 1e-15 * kK0) << e;
    EXPECT_NEAR(f.J[e], J, 1e-15) << e;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.flux[3 * e + c], w(c), 1e-18) << e;
  }
}

TEST(FieldRecovery, InvertedElementIsNamed) {
  const Mesh mesh = test::box_mesh({1, 1, 1}, {1.0, 1.0, 1.0});
  const BiphasicProblem problem(mesh, material_config());
  Mat3 F = Mat3::Identity();
  F(2, 2) = -0.5;
  const std::vector<double> y = homogeneous_state(problem, F, 0.0, Vec3::Zero());
  try {
    recover_cell_fields(problem, y.data());
    FAIL() << "expected InvertedElement";
  } catch (const InvertedElement& e) {
    EXPECT_NE(std::string(e.what()).find("element "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace biphasic
