// Manufactured solutions of the two-dimensional models (plane strain and axisymmetric) on the
// unit square, the axisymmetric one including the axis R = 0: the L² errors of u and p at
// t = 1 s converge at the orders of P2/P1, 3 and 2.
//
// Exact fields, linear in t (y = 0 is an exact, consistent start), regular on the axis
// (U_r odd in R, U_z and P even in R):
//   U_r = A R sin(0.9R² + 1.1Z + 0.3),  U_z = A cos(0.7R² − 0.6Z),
//   P = P₀ cos(1.2R²) sin(0.9Z + 0.5);   u = t U, p = t P
// (the same functions of (x, y) for plane strain). The loads that make them exact are written
// here again from the model of docs/formulation.md, independently of src/:
//   b = −Div P, P = μ(F − F⁻ᵀ) + (λ ln J − pJ) F⁻ᵀ,  s = J̇ − Div Q, Q = k J C⁻¹∇₀p,
// with, axisymmetric, F_θΘ = 1 + u_r/R, (Div P)_r = ∂P_rR/∂R + ∂P_rZ/∂Z + (P_rR − P_θΘ)/R,
// (Div P)_z = ∂P_zR/∂R + ∂P_zZ/∂Z + P_zR/R and Div Q = ∂Q_R/∂R + ∂Q_Z/∂Z + Q_R/R. Derivatives
// are complex-step derivatives (exact to rounding).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <vector>

#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/section_problem.hpp"
#include "biphasic/time/bdf_integrator.hpp"

namespace biphasic {
namespace {

using C = std::complex<double>;
constexpr double kStep = 1e-30;
using Mat3C = Eigen::Matrix<C, 3, 3>;

struct SectionMms {
  SectionModel model;
  double lambda = 0.2, mu = 0.5, k = 0.1;  // [MPa], [MPa], [mm⁴ N⁻¹ s⁻¹]
  double A = 0.08, P0 = 0.1;               // [mm/s], [MPa/s]
  /// P = P₀ (1 + 0.5Z) instead: held exactly by P1, so the displacement error is the P2
  /// approximation's alone (with a general pressure its O(h²) error feeds the displacement).
  bool linear_pressure = false;

  // U (2), ∇U (2 × 2), P, ∇P at (R, Z).
  template <class T>
  void fields(T R, T Z, T U[2], T G[2][2], T& P, T gP[2]) const {
    using std::cos;
    using std::sin;
    const T a = 0.9 * R * R + 1.1 * Z + 0.3, b = 0.7 * R * R - 0.6 * Z;
    U[0] = A * R * sin(a);
    U[1] = A * cos(b);
    G[0][0] = A * (sin(a) + R * cos(a) * 1.8 * R);
    G[0][1] = A * R * cos(a) * 1.1;
    G[1][0] = -A * sin(b) * 1.4 * R;
    G[1][1] = A * sin(b) * 0.6;
    if (linear_pressure) {
      P = P0 * (1.0 + 0.5 * Z);
      gP[0] = T(0.0);
      gP[1] = T(0.5 * P0);
      return;
    }
    const T c = 1.2 * R * R, d = 0.9 * Z + 0.5;
    P = P0 * cos(c) * sin(d);
    gP[0] = -P0 * sin(c) * 2.4 * R * sin(d);
    gP[1] = P0 * cos(c) * cos(d) * 0.9;
  }
  bool axisymmetric() const { return model == SectionModel::Axisymmetric; }

  Mat3C deformation(C R, C Z, C t) const {
    C U[2], G[2][2], P, gP[2];
    fields(R, Z, U, G, P, gP);
    Mat3C F = Mat3C::Identity();
    for (int i = 0; i < 2; ++i)
      for (int J = 0; J < 2; ++J) F(i, J) += t * G[i][J];
    if (axisymmetric()) F(2, 2) += t * U[0] / R;
    return F;
  }
  Mat3C stress(C R, C Z, C t) const {
    C U[2], G[2][2], P, gP[2];
    fields(R, Z, U, G, P, gP);
    const Mat3C F = deformation(R, Z, t);
    const C J = F.determinant();
    const Mat3C FinvT = F.inverse().transpose();
    return mu * (F - FinvT) + (lambda * std::log(J) - t * P * J) * FinvT;
  }
  Eigen::Matrix<C, 3, 1> flux(C R, C Z, C t) const {
    C U[2], G[2][2], P, gP[2];
    fields(R, Z, U, G, P, gP);
    const Mat3C F = deformation(R, Z, t);
    const Mat3C Finv = F.inverse();
    const Eigen::Matrix<C, 3, 1> g(t * gP[0], t * gP[1], C(0.0));
    return k * F.determinant() * (Finv * Finv.transpose()) * g;
  }

  Vec3 u(const Vec3& X, double t) const {
    double U[2], G[2][2], P, gP[2];
    fields(X(0), X(1), U, G, P, gP);
    return {t * U[0], t * U[1], 0.0};
  }
  double p(const Vec3& X, double t) const {
    double U[2], G[2][2], P, gP[2];
    fields(X(0), X(1), U, G, P, gP);
    return t * P;
  }
  Vec3 body_force(const Vec3& X, double t) const {
    const C R(X(0)), Z(X(1)), T(t), h(0.0, kStep);
    const Mat3C dR = stress(R + h, Z, T), dZ = stress(R, Z + h, T);
    Vec3 b(-(dR(0, 0).imag() + dZ(0, 1).imag()) / kStep,
           -(dR(1, 0).imag() + dZ(1, 1).imag()) / kStep, 0.0);
    if (axisymmetric()) {
      const Mat3C S = stress(R, Z, T);
      b(0) -= (S(0, 0).real() - S(2, 2).real()) / X(0);
      b(1) -= S(1, 0).real() / X(0);
    }
    return b;
  }
  double fluid_source(const Vec3& X, double t) const {
    const C R(X(0)), Z(X(1)), T(t), h(0.0, kStep);
    const double Jdot = deformation(R, Z, T + h).determinant().imag() / kStep;
    double divQ = (flux(R + h, Z, T)(0).imag() + flux(R, Z + h, T)(1).imag()) / kStep;
    if (axisymmetric()) divQ += flux(R, Z, T)(0).real() / X(0);
    return Jdot - divQ;
  }
};

struct Errors {
  double u = 0.0, p = 0.0;
};

/// L² errors of u and p with the model's measure (2πR dR dZ or dx dy), on each triangle's
/// quadrature rule.
Errors l2_errors(const SectionProblem& problem, const std::vector<double>& y,
                 const SectionMms& exact, double t) {
  const SectionMesh& mesh = problem.mesh();
  const SparsityPattern& dofs = problem.pattern();
  double eu = 0.0, ep = 0.0;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const Tri6& tri = mesh.triangles[e];
    for (const SectionPointGeometry& g : problem.point_geometry(static_cast<Index>(e))) {
      Vec3 X = Vec3::Zero(), uh = Vec3::Zero();
      double ph = 0.0;
      for (int a = 0; a < 6; ++a) {
        X += g.N(a) * Vec3(mesh.nodes[tri[a]][0], mesh.nodes[tri[a]][1], 0.0);
        for (int i = 0; i < 2; ++i) uh(i) += g.N(a) * y[dofs.u_dof(tri[a], i)];
      }
      for (int c = 0; c < 3; ++c) ph += g.Np(c) * y[dofs.p_dof(tri[c])];
      eu += g.weight * (uh - exact.u(X, t)).squaredNorm();
      ep += g.weight * std::pow(ph - exact.p(X, t), 2);
    }
  }
  return {std::sqrt(eu), std::sqrt(ep)};
}

/// The unit square in n × n cells; u and p prescribed from the exact fields on every side but
/// the axis (axisymmetric: there only u_r = 0, which the model holds itself, and the natural
/// conditions of symmetry); BDF to t = 1 s.
Errors solve(const SectionMms& exact, int n) {
  SectionRectangleSpec spec;
  spec.width = spec.height = 1.0;
  spec.nr = spec.nz = n;
  const SectionMesh mesh = generate_section_rectangle(spec);
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(exact.lambda, exact.mu, exact.k);
  cfg.stabilisation.type = "none";
  std::vector<std::string> sides{"lateral", "bottom", "top"};
  if (!exact.axisymmetric()) sides.push_back("axis");
  for (const std::string& side : sides) {
    for (int c = 0; c < 2; ++c) cfg.bcs.push_back({BcType::Displacement, side, c, 0.0, {}, ""});
    cfg.bcs.push_back({BcType::Pressure, side, 0, 0.0, {}, ""});
  }
  cfg.time.integrator = Integrator::Bdf;
  cfg.time.t_end = cfg.time.dt = 1.0;
  cfg.time.bdf.rtol = 1e-7;
  cfg.time.bdf.initial_step = 0.01;
  cfg.time.bdf.atol_displacement = 1e-9 * exact.A;
  cfg.time.bdf.atol_pressure = 1e-9 * exact.P0;
  SectionProblem problem(mesh, exact.model, cfg);
  problem.set_body_force([&](const Vec3& X, double t) { return exact.body_force(X, t); });
  problem.set_fluid_source([&](const Vec3& X, double t) { return exact.fluid_source(X, t); });
  problem.set_dirichlet_fields([&](const Vec3& X, double t) { return exact.u(X, t); },
                               [&](const Vec3& X, double t) { return exact.p(X, t); });
  BdfIntegrator integrator(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y(static_cast<std::size_t>(problem.size()), 0.0);
  integrator.run(0.0, y, nullptr);
  return l2_errors(problem, y, exact, 1.0);
}

/// Errors on 4², 8², 16² cells and the observed rates log₂(e_{n/2}/e_n).
struct Study {
  std::vector<Errors> errors;
  std::vector<double> rate_u, rate_p;
};

Study run_study(const SectionMms& exact) {
  const int sizes[] = {4, 8, 16};
  Study s;
  for (int n : sizes) s.errors.push_back(solve(exact, n));
  std::cout << to_string(exact.model) << (exact.linear_pressure ? ", linear pressure" : "")
            << ": n, L2 error u [mm], L2 error p [MPa], rates\n";
  for (std::size_t i = 0; i < s.errors.size(); ++i) {
    std::cout << std::setprecision(4) << sizes[i] << ", " << s.errors[i].u << ", " << s.errors[i].p;
    if (i > 0) {
      s.rate_u.push_back(std::log2(s.errors[i - 1].u / s.errors[i].u));
      s.rate_p.push_back(std::log2(s.errors[i - 1].p / s.errors[i].p));
      std::cout << ", " << s.rate_u.back() << ", " << s.rate_p.back();
    }
    std::cout << '\n';
  }
  return s;
}

// A general pressure: p converges at order 2; u at order 2 to 3, its error O(h³) + O(h²) with the
// second part fed by the P1 pressure error (as in three dimensions, docs/verification_mms.md).
void expect_general_rates(SectionModel model) {
  const Study s = run_study(SectionMms{model});
  for (std::size_t i = 0; i < s.rate_p.size(); ++i) {
    EXPECT_NEAR(s.rate_p[i], 2.0, 0.15) << to_string(model) << " refinement " << i + 1;
    EXPECT_GT(s.rate_u[i], 1.9) << to_string(model) << " refinement " << i + 1;
  }
}

// A pressure P1 holds: u converges at order 3, the order of P2.
void expect_displacement_order_three(SectionModel model) {
  SectionMms exact{model};
  exact.linear_pressure = true;
  const Study s = run_study(exact);
  for (double r : s.rate_u) EXPECT_NEAR(r, 3.0, 0.2) << to_string(model);
  for (const Errors& e : s.errors) EXPECT_LT(e.p, 1e-3 * exact.P0) << to_string(model);
}

TEST(SectionMms, PlaneStrainPressureConvergesAtOrderTwo) {
  expect_general_rates(SectionModel::PlaneStrain);
}

TEST(SectionMms, AxisymmetricPressureConvergesAtOrderTwoThroughTheAxis) {
  expect_general_rates(SectionModel::Axisymmetric);
}

TEST(SectionMms, PlaneStrainDisplacementConvergesAtOrderThree) {
  expect_displacement_order_three(SectionModel::PlaneStrain);
}

TEST(SectionMms, AxisymmetricDisplacementConvergesAtOrderThreeThroughTheAxis) {
  expect_displacement_order_three(SectionModel::Axisymmetric);
}

}  // namespace
}  // namespace biphasic
