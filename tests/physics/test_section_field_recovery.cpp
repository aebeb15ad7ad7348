// Cell fields of the two-dimensional models against states worked out by hand: homogeneous
// stretches (axisymmetric with the hoop stretch, plane strain with a shear) give the
// Neo-Hookean Cauchy stress σ_eff = (μ/J)(B − I) + (λ ln J / J) I in every triangle, its (2,2)
// entry the hoop or out-of-plane stress; a linear pressure gives the Darcy flux −k F⁻ᵀ∇₀p.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "../common/h5_reader.hpp"
#include "biphasic/app/field_output.hpp"
#include "biphasic/physics/section_field_recovery.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {
namespace {

constexpr double kLambda = 0.3, kMu = 0.45, kK0 = 2e-3;

SectionMesh rectangle() {
  SectionRectangleSpec spec;
  spec.width = 2.0;
  spec.height = 1.5;
  spec.nr = 3;
  spec.nz = 2;
  return generate_section_rectangle(spec);
}

Config material() {
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(kLambda, kMu, kK0);
  return cfg;
}

/// y with u = (F₂ − I) X in the section (2 × 2 block of F) and p = p0 + g·X on the vertices.
std::vector<double> state(const SectionProblem& problem, const Eigen::Matrix2d& F2, double p0,
                          const Eigen::Vector2d& g) {
  const SectionMesh& mesh = problem.mesh();
  std::vector<double> y(static_cast<std::size_t>(problem.size()), 0.0);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Eigen::Vector2d X(mesh.nodes[n][0], mesh.nodes[n][1]);
    const Eigen::Vector2d u = (F2 - Eigen::Matrix2d::Identity()) * X;
    for (int c = 0; c < 2; ++c) y[problem.pattern().u_dof(n, c)] = u(c);
  }
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    const Eigen::Vector2d X(mesh.nodes[v][0], mesh.nodes[v][1]);
    y[problem.pattern().p_dof(v)] = p0 + g.dot(X);
  }
  return y;
}

/// (μ/J)(F Fᵀ − I) + (λ ln J / J) I, written out.
Mat3 neo_hookean_cauchy(const Mat3& F) {
  const double J = F.determinant();
  return (kMu / J) * (F * F.transpose() - Mat3::Identity()) +
         (kLambda * std::log(J) / J) * Mat3::Identity();
}

void expect_homogeneous(const CellFields& f, std::size_t triangles, const Mat3& F, double p0,
                        const std::string& what) {
  const Mat3 s_eff = neo_hookean_cauchy(F);
  const Mat3 s = s_eff - p0 * Mat3::Identity();
  const double J = F.determinant();
  ASSERT_EQ(f.stress.size(), 9 * triangles);
  ASSERT_EQ(f.flux.size(), 3 * triangles);
  for (std::size_t e = 0; e < triangles; ++e) {
    for (int k = 0; k < 9; ++k) {
      EXPECT_NEAR(f.effective_stress[9 * e + k], s_eff(k / 3, k % 3), 1e-13)
          << what << ", triangle " << e << ", entry " << k;
      EXPECT_NEAR(f.stress[9 * e + k], s(k / 3, k % 3), 1e-13)
          << what << ", triangle " << e << ", entry " << k;
    }
    EXPECT_NEAR(f.J[e], J, 1e-14) << what;
    EXPECT_NEAR(f.permeability[e], kK0, 1e-18) << what;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.flux[3 * e + c], 0.0, 1e-18) << what;
  }
}

TEST(SectionFieldRecovery, AxisymmetricStretchCarriesTheHoopStressInEntry22) {
  const SectionMesh mesh = rectangle();
  const SectionProblem problem(mesh, SectionModel::Axisymmetric, material());
  const double a = 0.04, b = -0.07, p0 = 0.021;
  const Eigen::Matrix2d F2 = Eigen::Vector2d(1 + a, 1 + b).asDiagonal();
  const std::vector<double> y = state(problem, F2, p0, Eigen::Vector2d::Zero());
  const CellFields f = recover_section_cell_fields(problem, y.data());
  const Mat3 F = Eigen::Vector3d(1 + a, 1 + b, 1 + a).asDiagonal();
  expect_homogeneous(f, mesh.triangles.size(), F, p0, "axisymmetric");
  // By hand: σ_θθ = μ/J ((1+a)² − 1) + λ ln J / J, J = (1+a)²(1+b); equal to σ_rr.
  const double J = (1 + a) * (1 + a) * (1 + b);
  const double hoop = kMu / J * ((1 + a) * (1 + a) - 1) + kLambda * std::log(J) / J;
  EXPECT_NEAR(f.effective_stress[8], hoop, 1e-14);
  EXPECT_NEAR(f.effective_stress[0], hoop, 1e-14);
  EXPECT_NEAR(f.stress[8], hoop - p0, 1e-14);
}

TEST(SectionFieldRecovery, PlaneStrainShearKeepsSigmaZZFromTheVolumeChangeAlone) {
  const SectionMesh mesh = rectangle();
  const SectionProblem problem(mesh, SectionModel::PlaneStrain, material());
  Eigen::Matrix2d F2;
  F2 << 1.05, 0.08, -0.02, 0.96;
  const double p0 = -0.01;
  const std::vector<double> y = state(problem, F2, p0, Eigen::Vector2d::Zero());
  const CellFields f = recover_section_cell_fields(problem, y.data());
  Mat3 F = Mat3::Identity();
  F.topLeftCorner<2, 2>() = F2;
  expect_homogeneous(f, mesh.triangles.size(), F, p0, "plane strain");
  const double J = F2.determinant();
  EXPECT_NEAR(f.effective_stress[8], kLambda * std::log(J) / J, 1e-14);  // B_zz − 1 = 0
  for (int k : {2, 5, 6, 7}) EXPECT_EQ(f.stress[k], 0.0) << "out-of-plane shear entry " << k;
}

TEST(SectionFieldRecovery, LinearPressureGivesTheDarcyFluxInThePlane) {
  const SectionMesh mesh = rectangle();
  for (SectionModel model : {SectionModel::PlaneStrain, SectionModel::Axisymmetric}) {
    const SectionProblem problem(mesh, model, material());
    const double a = 0.03, b = 0.05;
    const Eigen::Matrix2d F2 = Eigen::Vector2d(1 + a, 1 + b).asDiagonal();
    const Eigen::Vector2d g(0.2, -0.5);  // ∇₀p [MPa/mm]
    const std::vector<double> y = state(problem, F2, 0.1, g);
    const CellFields f = recover_section_cell_fields(problem, y.data());
    // w = −k F⁻ᵀ∇₀p with F diagonal.
    const double w0 = -kK0 * g(0) / (1 + a), w1 = -kK0 * g(1) / (1 + b);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
      EXPECT_NEAR(f.flux[3 * e], w0, 1e-16) << to_string(model) << ", triangle " << e;
      EXPECT_NEAR(f.flux[3 * e + 1], w1, 1e-16) << to_string(model) << ", triangle " << e;
      EXPECT_EQ(f.flux[3 * e + 2], 0.0);
    }
  }
}

TEST(SectionFieldOutput, WritesTheRecoveredFieldsOfASectionRun) {
  const SectionMesh mesh = rectangle();
  const SectionProblem problem(mesh, SectionModel::Axisymmetric, material());
  const double a = 0.04, b = -0.07, p0 = 0.021;
  const Eigen::Matrix2d F2 = Eigen::Vector2d(1 + a, 1 + b).asDiagonal();
  const std::vector<double> y = state(problem, F2, p0, Eigen::Vector2d::Zero());
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("biphasic_section_field_output_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  const std::vector<FieldQuantity> all{FieldQuantity::Displacement, FieldQuantity::Pressure,
                                       FieldQuantity::Stress,       FieldQuantity::J,
                                       FieldQuantity::Flux,         FieldQuantity::Permeability};
  {
    SectionFieldOutput output(all, dir.string(), mesh, std::nullopt);
    output.write(problem, 0.0, y);
    output.write(problem, 1.0, y);
  }
  {
    SectionFieldOutput output(all, dir.string(), mesh, 0.0);  // a restart at t = 0
    EXPECT_EQ(output.writer().times(), std::vector<double>{0.0});
  }
  const test::H5Reader h5(dir / "fields.h5");
  const auto ne = static_cast<hsize_t>(mesh.triangles.size());
  const auto nn = static_cast<hsize_t>(mesh.num_nodes());
  EXPECT_EQ(h5.dims("/fields/stress/0"), (std::vector<hsize_t>{ne, 9}));
  EXPECT_EQ(h5.dims("/fields/flux/0"), (std::vector<hsize_t>{ne, 3}));
  EXPECT_EQ(h5.dims("/fields/displacement/0"), (std::vector<hsize_t>{nn, 3}));
  const auto stress = h5.read<double>("/fields/stress/0", H5T_NATIVE_DOUBLE);
  const Mat3 F = Eigen::Vector3d(1 + a, 1 + b, 1 + a).asDiagonal();
  EXPECT_NEAR(stress[8], neo_hookean_cauchy(F)(2, 2) - p0, 1e-14);
  const auto u = h5.read<double>("/fields/displacement/0", H5T_NATIVE_DOUBLE);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    EXPECT_NEAR(u[3 * n], a * mesh.nodes[n][0], 1e-15);
    EXPECT_EQ(u[3 * n + 2], 0.0);
  }
  EXPECT_FALSE(h5.exists("/fields/stress/1"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace biphasic
