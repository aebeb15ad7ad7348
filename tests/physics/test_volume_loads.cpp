// Body force and fluid source: consistent load vectors (resultants and first moments exact for
// linear fields), case-file formulas against the programmatic hooks, ∂F/∂t against differences
// of the residual in t, Dirichlet data from fields.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../common/box_mesh.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic {
namespace {

/// The box [0, 1] × [0, 1.5] × [0, 2] (volume 3) in 2 × 3 × 2 cells.
const Mesh& box() {
  static const Mesh mesh = test::box_mesh({2, 3, 2}, {1.0, 1.5, 2.0});
  return mesh;
}

/// R(t, y = 0, ẏ = 0): at rest the stress vanishes, so R is the load vector alone.
std::vector<double> loads_at_rest(BiphasicProblem& problem, double t) {
  std::vector<double> y(problem.size(), 0.0), ydot(problem.size(), 0.0), R(problem.size());
  problem.residual(t, y.data(), ydot.data(), R.data());
  return R;
}

Vec3 node(const Mesh& mesh, Index n) {
  return {mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]};
}

TEST(VolumeLoads, ConstantFieldsSumToValueTimesVolume) {
  Config cfg;
  cfg.loads.body_force = {Expression::parse("0.2"), Expression::parse("-0.1"),
                          Expression::parse("0.05")};
  cfg.loads.fluid_source = Expression::parse("1e-3");
  BiphasicProblem problem(box(), cfg);
  const std::vector<double> R = loads_at_rest(problem, 0.0);
  Vec3 force = Vec3::Zero();
  for (Index n = 0; n < box().num_nodes(); ++n)
    for (int c = 0; c < 3; ++c) force(c) += R[problem.pattern().u_dof(n, c)];
  EXPECT_LT((force + 3.0 * Vec3(0.2, -0.1, 0.05)).norm(), 1e-14);
  double source = 0.0;
  for (Index v = 0; v < box().num_vertices; ++v) source += R[problem.pattern().p_dof(v)];
  EXPECT_NEAR(source, -3e-3, 1e-17);
}

TEST(VolumeLoads, LinearFieldsGiveExactResultantsAndMoments) {
  // b = (1 + 2x − y, 3z, x + y + z), s = 2 + x − 3y + z on [0,1]×[0,1.5]×[0,2]:
  // ∫ b_i dX and ∫ b_i X_j dX (Σ_a N_a X_a = X) are integrated exactly by the 4-point rule.
  const VectorField b = [](const Vec3& X, double) {
    return Vec3(1 + 2 * X(0) - X(1), 3 * X(2), X(0) + X(1) + X(2));
  };
  const ScalarField s = [](const Vec3& X, double) { return 2 + X(0) - 3 * X(1) + X(2); };
  Config cfg;
  BiphasicProblem problem(box(), cfg);
  problem.set_body_force(b);
  problem.set_fluid_source(s);
  const std::vector<double> R = loads_at_rest(problem, 0.0);

  // Exact integrals over the box by the midpoint rule per axis (fields at most quadratic in
  // one variable after multiplying by X_j: Simpson in each direction is exact).
  Vec3 exact_force = Vec3::Zero();
  Mat3 exact_moment = Mat3::Zero();
  double exact_source = 0.0;
  const double L[3] = {1.0, 1.5, 2.0};
  const double nodes[3] = {0.0, 0.5, 1.0}, weights[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Vec3 X(L[0] * nodes[i], L[1] * nodes[j], L[2] * nodes[k]);
        const double w = 3.0 * weights[i] * weights[j] * weights[k];
        exact_force += w * b(X, 0.0);
        exact_moment += w * b(X, 0.0) * X.transpose();
        exact_source += w * s(X, 0.0);
      }
  Vec3 force = Vec3::Zero();
  Mat3 moment = Mat3::Zero();
  for (Index n = 0; n < box().num_nodes(); ++n)
    for (int c = 0; c < 3; ++c) {
      force(c) += R[problem.pattern().u_dof(n, c)];
      moment.row(c) += R[problem.pattern().u_dof(n, c)] * node(box(), n).transpose();
    }
  EXPECT_LT((force + exact_force).norm(), 1e-13 * exact_force.norm());
  EXPECT_LT((moment + exact_moment).norm(), 1e-13 * exact_moment.norm());
  double source = 0.0, source_moment = 0.0;
  for (Index v = 0; v < box().num_vertices; ++v) {
    source += R[problem.pattern().p_dof(v)];
    source_moment += R[problem.pattern().p_dof(v)] * box().nodes[v][0];
  }
  EXPECT_NEAR(source, -exact_source, 1e-13 * std::abs(exact_source));
  // ∫ s x dX by the same tensor rule.
  double exact_sx = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Vec3 X(L[0] * nodes[i], L[1] * nodes[j], L[2] * nodes[k]);
        exact_sx += 3.0 * weights[i] * weights[j] * weights[k] * s(X, 0.0) * X(0);
      }
  EXPECT_NEAR(source_moment, -exact_sx, 1e-13 * std::abs(exact_sx));
}

TEST(VolumeLoads, FormulasEqualTheProgrammaticHooks) {
  Config cfg;
  cfg.loads.body_force = {Expression::parse("sin(x + 2*y) * t"), Expression(),
                          Expression::parse("exp(-z) * (1 + t^2)")};
  cfg.loads.fluid_source = Expression::parse("x * y * z * cos(t)");
  BiphasicProblem from_case(box(), cfg);
  Config plain;
  BiphasicProblem from_hooks(box(), plain);
  from_hooks.set_body_force([](const Vec3& X, double t) {
    return Vec3(std::sin(X(0) + 2 * X(1)) * t, 0.0, std::exp(-X(2)) * (1 + t * t));
  });
  from_hooks.set_fluid_source(
      [](const Vec3& X, double t) { return X(0) * X(1) * X(2) * std::cos(t); });
  for (double t : {0.0, 0.7, 2.0}) {
    const std::vector<double> a = loads_at_rest(from_case, t), b = loads_at_rest(from_hooks, t);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-15) << i;
  }
  // Removing the hooks removes the loads.
  from_hooks.set_body_force({});
  from_hooks.set_fluid_source({});
  for (double r : loads_at_rest(from_hooks, 1.0)) EXPECT_EQ(r, 0.0);
}

TEST(VolumeLoads, JacobianDoesNotChange) {
  Config cfg;
  cfg.bcs = {{BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 0.0, {}, ""}};
  BiphasicProblem plain(box(), cfg);
  cfg.loads.body_force[1] = Expression::parse("x * t");
  cfg.loads.fluid_source = Expression::parse("1 + z");
  BiphasicProblem loaded(box(), cfg);
  std::vector<double> y(plain.size()), ydot(plain.size());
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> d(-0.02, 0.02);
  for (auto& v : y) v = d(gen);
  for (auto& v : ydot) v = d(gen);
  std::vector<double> A(plain.pattern().nnz()), B(plain.pattern().nnz());
  plain.jacobian(0.5, y.data(), ydot.data(), 3.0, A.data());
  loaded.jacobian(0.5, y.data(), ydot.data(), 3.0, B.data());
  EXPECT_EQ(A, B);
}

/// Max over rows of |∂F/∂t − central difference of F in t| relative to max |∂F/∂t|.
double time_derivative_error(BiphasicProblem& problem, double t, const std::vector<double>& y,
                             const std::vector<double>& ydot, double* scale_out = nullptr) {
  const Index n = problem.size();
  std::vector<double> dFdt(n), Fp(n), Fm(n);
  problem.time_derivative(t, dFdt.data());
  const double h = 1e-4;
  problem.residual(t + h, y.data(), ydot.data(), Fp.data());
  problem.residual(t - h, y.data(), ydot.data(), Fm.data());
  double err = 0.0, scale = 0.0;
  for (Index i = 0; i < n; ++i) {
    err = std::max(err, std::abs(dFdt[i] - (Fp[i] - Fm[i]) / (2 * h)));
    scale = std::max(scale, std::abs(dFdt[i]));
  }
  if (scale_out) *scale_out = scale;
  return err / scale;
}

TEST(VolumeLoads, TimeDerivativeMatchesDifferencesOfTheResidual) {
  // Formulas (exact derivatives), hooks without rates (central differences), Dirichlet data from
  // fields, and a ramped traction on a face whose edge nodes are also fixed.
  Config cfg;
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {2.0, 1.0}}};
  cfg.bcs = {{BcType::Displacement, "z0", 0, 0.0, {}, ""},
             {BcType::Displacement, "z0", 1, 0.0, {}, ""},
             {BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Displacement, "z1", 2, -0.05, {}, "ramp"},
             {BcType::Pressure, "x1", 0, 0.0, {}, ""},
             {BcType::Traction, "y1", 0, 0.0, {0.01, 0.0, -0.02}, "ramp"}};
  cfg.loads.body_force = {Expression::parse("0.01 * sin(x + t)"), Expression::parse("0.02 * t^2"),
                          Expression::parse("-0.01 * z * exp(-t)")};
  cfg.loads.fluid_source = Expression::parse("1e-3 * cos(2 * t) * (1 + y)");
  BiphasicProblem problem(box(), cfg);
  const Index n = problem.size();
  std::vector<double> y(n), ydot(n);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> d(-0.01, 0.01);
  for (auto& v : y) v = d(gen);
  for (auto& v : ydot) v = d(gen);
  const double t = 0.8;
  double scale = 0.0;
  EXPECT_LT(time_derivative_error(problem, t, y, ydot, &scale), 1e-8);
  EXPECT_GT(scale, 1e-4);

  // The same loads through hooks without rates, plus Dirichlet data from fields.
  Config plain = cfg;
  plain.loads = {};
  BiphasicProblem hooked(box(), plain);
  hooked.set_body_force([](const Vec3& X, double s) {
    return Vec3(0.01 * std::sin(X(0) + s), 0.02 * s * s, -0.01 * X(2) * std::exp(-s));
  });
  hooked.set_fluid_source(
      [](const Vec3& X, double s) { return 1e-3 * std::cos(2 * s) * (1 + X(1)); });
  hooked.set_dirichlet_fields(
      [](const Vec3& X, double s) { return Vec3(0.01 * X(0) * s, -0.02 * s * s, 0.03 * X(1) * s); },
      [](const Vec3& X, double s) { return 0.1 * std::sin(X(2) * s); });
  EXPECT_LT(time_derivative_error(hooked, t, y, ydot), 1e-8);
  std::vector<double> dFdt(n), dFdt_case(n);
  hooked.time_derivative(t, dFdt.data());
  problem.time_derivative(t, dFdt_case.data());
  for (Index i = 0; i < n; ++i)
    if (!problem.constrained()[i]) {
      EXPECT_NEAR(dFdt[i], dFdt_case[i], 1e-12) << i;
    }
}

TEST(VolumeLoads, DirichletDataFromFields) {
  Config cfg;
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {1.0, 1.0}}};
  cfg.bcs = {{BcType::Displacement, "x1", 0, 5.0, {}, "ramp"},
             {BcType::Displacement, "x1", 2, 5.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 7.0, {}, ""}};
  BiphasicProblem problem(box(), cfg);
  const auto u = [](const Vec3& X, double t) -> Vec3 {
    return 0.01 * Vec3(X(0) * t, X(1), X(2) * t * t);
  };
  const auto p = [](const Vec3& X, double t) { return X(0) + X(1) * t; };
  problem.set_dirichlet_fields(u, p, {}, [](const Vec3& X, double) { return X(1); });
  const Index n = problem.size();
  std::vector<double> y(n, 0.0), ydot(n, 0.0);
  const double t = 0.5;
  problem.apply_dirichlet(t, y.data(), ydot.data());
  const Mesh& mesh = box();
  const SparsityPattern& pat = problem.pattern();
  int fixed_u = 0, fixed_p = 0, fixed_sym = 0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Vec3 X = node(mesh, a);
    if (X(0) == 1.0) {
      EXPECT_DOUBLE_EQ(y[pat.u_dof(a, 0)], 0.01 * X(0) * t);
      EXPECT_NEAR(ydot[pat.u_dof(a, 0)], 0.01 * X(0), 1e-11);  // central difference
      EXPECT_DOUBLE_EQ(y[pat.u_dof(a, 2)], 0.01 * X(2) * t * t);
      EXPECT_NEAR(ydot[pat.u_dof(a, 2)], 0.02 * X(2) * t, 1e-11);
      fixed_u += 2;
    }
    if (X(1) == 0.0) {
      EXPECT_EQ(y[pat.u_dof(a, 1)], 0.0);  // symmetry stays zero
      EXPECT_EQ(ydot[pat.u_dof(a, 1)], 0.0);
      ++fixed_sym;
    } else {
      EXPECT_FALSE(problem.constrained()[pat.u_dof(a, 1)]);
    }
    if (a < mesh.num_vertices && X(2) == 2.0) {
      EXPECT_DOUBLE_EQ(y[pat.p_dof(a)], X(0) + X(1) * t);
      EXPECT_EQ(ydot[pat.p_dof(a)], X(1));  // the rate given
      ++fixed_p;
    }
  }
  EXPECT_GT(fixed_u, 0);
  EXPECT_GT(fixed_p, 0);
  EXPECT_GT(fixed_sym, 0);
  // The residual's Dirichlet rows vanish at the applied values.
  std::vector<double> R(n);
  problem.residual(t, y.data(), ydot.data(), R.data());
  for (Index i = 0; i < n; ++i)
    if (problem.constrained()[i]) {
      EXPECT_NEAR(R[i], 0.0, 1e-15) << i;
    }
  // Empty fields restore value · curve(t).
  problem.set_dirichlet_fields({}, {});
  problem.apply_dirichlet(t, y.data(), nullptr);
  for (Index a = 0; a < mesh.num_nodes(); ++a)
    if (mesh.nodes[a][0] == 1.0) {
      EXPECT_EQ(y[pat.u_dof(a, 0)], 2.5);
    }
}

TEST(VolumeLoads, FormulaNotFiniteInTheDomainIsRefused) {
  Config cfg;
  cfg.loads.fluid_source = Expression::parse("log(x - 0.5)");
  try {
    BiphasicProblem problem(box(), cfg);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("fluid_source.value = \"log(x - 0.5)\" is NaN at X = ("), std::string::npos)
        << what;
    EXPECT_NE(what.find("t = 0 s"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace biphasic
