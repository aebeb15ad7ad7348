// The two-dimensional problem assembled on a section mesh: the patch test (a homogeneous
// deformation with a uniform pressure is an exact discrete equilibrium on a distorted mesh), the
// reactions against the stress of that state times the loaded area (per mm, or over the full
// circle), and the assembled Jacobian against central differences of the assembled residual.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {
namespace {

constexpr double kLambda = 0.3, kMu = 0.6;  // [MPa]

/// The rectangle [0, 2] × [0, 1] in 5 × 4 cells with every interior vertex moved by up to 30 %
/// of a cell, midside nodes at the new edge midpoints.
SectionMesh distorted_rectangle() {
  SectionRectangleSpec spec;
  spec.width = 2.0;
  spec.height = 1.0;
  spec.nr = 5;
  spec.nz = 4;
  SectionMesh mesh = generate_section_rectangle(spec);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    Point2& x = mesh.nodes[static_cast<std::size_t>(v)];
    const bool boundary = x[0] == 0.0 || x[0] == spec.width || x[1] == 0.0 || x[1] == spec.height;
    if (boundary) continue;
    x[0] += d(gen) * spec.width / spec.nr;
    x[1] += d(gen) * spec.height / spec.nz;
  }
  for (const Tri6& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Point2& a = mesh.nodes[static_cast<std::size_t>(t[kTriEdges[k][0]])];
      const Point2& b = mesh.nodes[static_cast<std::size_t>(t[kTriEdges[k][1]])];
      mesh.nodes[static_cast<std::size_t>(t[3 + k])] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    }
  check_section_mesh(mesh);
  return mesh;
}

/// Every boundary curve holds both displacement components (axisymmetric: not the axis, which
/// holds u_r itself and leaves u_z free) and, at "lateral", the pressure.
Config patch_config(SectionModel model) {
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(kLambda, kMu, 1e-2);
  cfg.stabilisation.type = "gls";
  std::vector<std::string> curves{"lateral", "bottom", "top"};
  if (model == SectionModel::PlaneStrain) curves.push_back("axis");
  for (const std::string& c : curves)
    for (int i = 0; i < 2; ++i) cfg.bcs.push_back({BcType::Displacement, c, i, 0.0, {}, ""});
  cfg.bcs.push_back({BcType::Pressure, "lateral", 0, 0.0, {}, ""});
  return cfg;
}

/// Nominal stress P = μ(F − F⁻ᵀ) + (λ ln J − p J) F⁻ᵀ of a diagonal F (entries f), written here
/// from the law's formula.
std::array<double, 3> diagonal_stress(const std::array<double, 3>& f, double p) {
  const double J = f[0] * f[1] * f[2];
  std::array<double, 3> P{};
  for (int i = 0; i < 3; ++i)
    P[static_cast<std::size_t>(i)] =
        kMu * (f[static_cast<std::size_t>(i)] - 1.0 / f[static_cast<std::size_t>(i)]) +
        (kLambda * std::log(J) - p * J) / f[static_cast<std::size_t>(i)];
  return P;
}

void expect_patch(SectionModel model) {
  const SectionMesh mesh = distorted_rectangle();
  const Config cfg = patch_config(model);
  SectionProblem problem(mesh, model, cfg);
  // u = (a x + b y, c x + e y) in plane strain; u = (a r, e z) axisymmetric (F = diag(1+a, 1+e,
  // 1+a): a shear would make the hoop stretch vary); uniform p.
  const double a = 0.04, b = model == SectionModel::PlaneStrain ? 0.03 : 0.0,
               c = model == SectionModel::PlaneStrain ? -0.02 : 0.0, e = -0.06, p0 = 0.05;
  std::vector<double> y(static_cast<std::size_t>(problem.size()), 0.0), ydot(y.size(), 0.0);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Point2& x = mesh.nodes[static_cast<std::size_t>(n)];
    y[static_cast<std::size_t>(problem.pattern().u_dof(n, 0))] = a * x[0] + b * x[1];
    y[static_cast<std::size_t>(problem.pattern().u_dof(n, 1))] = c * x[0] + e * x[1];
  }
  for (Index v = 0; v < mesh.num_vertices; ++v)
    y[static_cast<std::size_t>(problem.pattern().p_dof(v))] = p0;
  // The Dirichlet rows read s (y − ḡ): the data must be the state's own values there.
  problem.set_dirichlet_fields(
      [&](const Vec3& X, double) { return Vec3(a * X(0) + b * X(1), c * X(0) + e * X(1), 0.0); },
      [&](const Vec3&, double) { return p0; });
  std::vector<double> F(y.size());
  problem.residual(0.0, y.data(), ydot.data(), F.data());
  const auto [ru, rp] = problem.field_norms(F.data());
  // Against the size of one element's internal force, H_A × strain × depth.
  const double depth = model == SectionModel::Axisymmetric ? 2.0 * std::numbers::pi : 1.0;
  EXPECT_LT(ru, 1e-12 * (kLambda + 2 * kMu) * 0.06 * depth) << to_string(model);
  EXPECT_LT(rp, 1e-15) << to_string(model);
  for (Index i = 0; i < problem.size(); ++i)
    if (problem.constrained()[static_cast<std::size_t>(i)]) {
      EXPECT_EQ(F[static_cast<std::size_t>(i)], 0.0) << "Dirichlet row " << i;
    }

  if (model == SectionModel::Axisymmetric) {
    // The top platen's axial force over the full circle: P_zZ π R². (Its radial component is
    // not zero: the corner node on the lateral face carries that face's P_rR; a ring's radial
    // forces are balanced by the hoop stress, not by each other.)
    const auto P = diagonal_stress({1.0 + a, 1.0 + e, 1.0 + a}, p0);
    const auto r = problem.reactions({"top"}, 0.0, y.data(), ydot.data());
    EXPECT_NEAR(r[0][1], P[1] * std::numbers::pi * 2.0 * 2.0, 1e-12) << "axial force";
  } else {
    // Per mm of thickness: the top (normal +y) carries P·N = (P_xy, P_yy) × width (the two top
    // corners' shares of the side faces' tractions cancel: equal segments, opposite normals).
    Mat3 Fm = Mat3::Identity();
    Fm(0, 0) += a;
    Fm(0, 1) += b;
    Fm(1, 0) += c;
    Fm(1, 1) += e;
    const double J = Fm.determinant();
    const Mat3 FinvT = Fm.inverse().transpose();
    const Mat3 P = kMu * (Fm - FinvT) + (kLambda * std::log(J) - p0 * J) * FinvT;
    const auto r = problem.reactions({"top"}, 0.0, y.data(), ydot.data());
    EXPECT_NEAR(r[0][0], P(0, 1) * 2.0, 1e-12);
    EXPECT_NEAR(r[0][1], P(1, 1) * 2.0, 1e-12);
  }
}

TEST(SectionProblem, PlaneStrainPassesThePatchTest) { expect_patch(SectionModel::PlaneStrain); }

TEST(SectionProblem, AxisymmetricPassesThePatchTest) { expect_patch(SectionModel::Axisymmetric); }

// dF/dy + c_j dF/dẏ assembled into the pattern against central differences of the assembled
// residual (Dirichlet rows included), at a random state, with GLS.
TEST(SectionProblem, AssembledJacobianMatchesCentralDifferences) {
  for (SectionModel model : {SectionModel::PlaneStrain, SectionModel::Axisymmetric}) {
    const SectionMesh mesh = distorted_rectangle();
    SectionProblem problem(mesh, model, patch_config(model));
    const auto n = static_cast<std::size_t>(problem.size());
    std::mt19937 gen(9);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    std::vector<double> y(n), ydot(n);
    for (std::size_t i = 0; i < n; ++i) {
      const bool u = static_cast<Index>(i) < problem.num_u();
      y[i] = (u ? 0.02 : 0.05) * d(gen);
      ydot[i] = (u ? 0.002 : 0.005) * d(gen);
    }
    problem.apply_dirichlet(0.0, y.data(), ydot.data());
    const double cj = 3.0;
    const SparsityPattern& pattern = problem.pattern();
    std::vector<double> values(static_cast<std::size_t>(pattern.nnz()));
    problem.jacobian(0.0, y.data(), ydot.data(), cj, values.data());
    std::vector<double> Fp(n), Fm(n);
    double worst = 0.0, scale = 0.0;
    for (double v : values) scale = std::max(scale, std::abs(v));
    for (std::size_t j = 0; j < n; ++j) {
      const double h = 1e-7;
      std::vector<double> yp = y, ym = y, vp = ydot, vm = ydot;
      yp[j] += h;
      ym[j] -= h;
      vp[j] += cj * h;  // the direction (δy, c_j δy) gives dF/dy + c_j dF/dẏ
      vm[j] -= cj * h;
      problem.residual(0.0, yp.data(), vp.data(), Fp.data());
      problem.residual(0.0, ym.data(), vm.data(), Fm.data());
      for (std::size_t i = 0; i < n; ++i) {
        const double fd = (Fp[i] - Fm[i]) / (2.0 * h);
        const Index k = pattern.find(static_cast<Index>(i), static_cast<Index>(j));
        const double exact = k >= 0 ? values[static_cast<std::size_t>(k)] : 0.0;
        worst = std::max(worst, std::abs(fd - exact));
      }
    }
    EXPECT_LT(worst, 1e-6 * scale)
        << to_string(model) << ": worst " << worst << ", scale " << scale;
  }
}

}  // namespace
}  // namespace biphasic
