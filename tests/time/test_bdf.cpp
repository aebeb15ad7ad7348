// BDF (IDA) and backward Euler on the same semidiscrete system: consistent start, first-order
// convergence of backward Euler against a tight BDF solution, and load-curve kinks as stop times.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../common/box_mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/study/paper_scene.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "biphasic/time/bdf_integrator.hpp"
#include "biphasic/time/consistent_start.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;

/// The coarse quarter cylinder shared by the tests (3129 unknowns).
const Mesh& coarse_mesh() {
  static const Mesh mesh = generate_quarter_cylinder(paper_reference_config(3.0).mesh.cylinder);
  return mesh;
}

std::vector<double> pressures(const BiphasicProblem& problem, const std::vector<double>& y) {
  return {y.begin() + problem.num_u(), y.end()};
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

double max_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

std::vector<double> run(Config cfg, Integrator integrator, const std::string& log = {}) {
  cfg.time.integrator = integrator;
  BiphasicProblem problem(coarse_mesh(), cfg);
  std::unique_ptr<TimeIntegrator> ti =
      make_time_integrator(problem, cfg.time, cfg.linear_solver, log);
  std::vector<double> y(problem.size(), 0.0);
  ti->run(0.0, y, nullptr);
  return pressures(problem, y);
}

/// Backward Euler at Δt = 0.64, 0.32, 0.16 s against IDA at rtol 1e-8 on the case `cfg`: the
/// error of the line pressure halves with Δt (order one) and is below 1 % at the finest.
void expect_order_one_against_tight_bdf(Config cfg) {
  cfg.time.bdf.rtol = 1e-8;
  cfg.time.bdf.atol_displacement = 1e-12;
  cfg.time.bdf.atol_pressure = 1e-14;
  const std::vector<double> reference = run(cfg, Integrator::Bdf);
  std::vector<double> errors;
  for (double dt : {0.64, 0.32, 0.16}) {
    cfg.time.dt = dt;
    errors.push_back(max_diff(run(cfg, Integrator::BackwardEuler), reference) / max_abs(reference));
  }
  EXPECT_LT(errors.back(), 1e-2);
  for (std::size_t i = 1; i < errors.size(); ++i)
    EXPECT_NEAR(errors[i - 1] / errors[i], 2.0, 0.3) << "dt halving " << i;
}

// Without stabilisation p is fixed by equilibrium and u̇, ṗ by the mass rows and the
// differentiated momentum balance, from any state (here one not in equilibrium).
TEST(ConsistentStart, RateSatisfiesTheDifferentiatedSystem) {
  Config cfg = paper_reference_config(3.0);
  cfg.stabilisation.type = "none";
  BiphasicProblem problem(coarse_mesh(), cfg);
  const Index n = problem.size();
  std::vector<double> y(n, 0.0);
  const double t0 = 3.0;  // on the ramp: the top moves at 2.5 µm/s
  problem.apply_dirichlet(t0, y.data(), nullptr);
  // A smooth pressure field drives flux in the mass rows (so they have rate terms to balance).
  const Mesh& mesh = coarse_mesh();
  for (Index v = 0; v < mesh.num_vertices; ++v)
    if (!problem.constrained()[problem.pattern().p_dof(v)])
      y[problem.pattern().p_dof(v)] =
          0.004 * std::sin(0.4 * mesh.nodes[v][2]) + 1e-4 * mesh.nodes[v][0];
  // The state is not in equilibrium: the start corrects its algebraic part first (y → cs.y).
  const ConsistentState cs = consistent_start(problem, t0, y, cfg.linear_solver);
  y = cs.y;
  const std::vector<double>& yd = cs.ydot;
  std::vector<double> zero(n, 0.0), F(n), Fp(n), Fm(n);
  // Mass rows: F_p(t0, y0, ẏ0) = 0.
  problem.residual(t0, y.data(), yd.data(), F.data());
  // Momentum rows: d/dε F_u(t0 + ε, y0 + ε ẏ0, 0) = 0.
  const double eps = 1e-4;
  std::vector<double> yp(n), ym(n);
  for (Index i = 0; i < n; ++i) {
    yp[i] = y[i] + eps * yd[i];
    ym[i] = y[i] - eps * yd[i];
  }
  problem.residual(t0 + eps, yp.data(), zero.data(), Fp.data());
  problem.residual(t0 - eps, ym.data(), zero.data(), Fm.data());
  double mass = 0.0, momentum = 0.0, mass_scale = 0.0;
  std::vector<double> Fr(n);
  problem.residual(t0, y.data(), zero.data(), Fr.data());
  for (Index i = 0; i < n; ++i) {
    if (problem.constrained()[i]) continue;
    if (i < problem.num_u()) {
      momentum = std::max(momentum, std::abs((Fp[i] - Fm[i]) / (2 * eps)));
    } else {
      mass = std::max(mass, std::abs(F[i]));
      mass_scale = std::max(mass_scale, std::abs(F[i] - Fr[i]));  // size of the rate terms
    }
  }
  EXPECT_GT(mass_scale, 1e-6);
  EXPECT_LT(mass, 1e-10 * mass_scale);
  EXPECT_LT(momentum, 1e-9);  // N/s; load rates here are O(1e-3) N/s per node
  // Dirichlet rows carry the boundary rates: the top moves at −0.08/32 mm/s.
  const Boundary* top = coarse_mesh().find_boundary("top");
  ASSERT_NE(top, nullptr);
  for (const Tri6& f : top->faces)
    EXPECT_NEAR(yd[problem.pattern().u_dof(f[0], 2)], -0.0025, 1e-15);
}

/// Confined compression of a column (1 × 1 × 4 mm, 8 cells): drained top platen moving down
/// on a ramp, bottom fixed and sealed, lateral rollers.
Config confined_column_config(std::string stabilisation) {
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(0.2, 0.5, 1e-2);
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {100.0, 1.0}}};
  cfg.bcs = {{BcType::Displacement, "z1", 2, -0.2, {}, "ramp"},
             {BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Symmetry, "x0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "x1", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y1", 0, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 0.0, {}, ""}};
  cfg.stabilisation.type = stabilisation;
  cfg.time.integrator = Integrator::Bdf;
  cfg.time.t_end = cfg.time.dt = 20.0;
  return cfg;
}

const Mesh& column_mesh() {
  static const Mesh mesh = test::box_mesh({1, 1, 8}, {1.0, 1.0, 4.0});
  return mesh;
}

struct StartCase {
  const char* scene;
  std::string stabilisation;
};

class ConsistentStartEveryRow : public ::testing::TestWithParam<StartCase> {};

// F(t₀, y₀, ẏ₀) = 0 on every free row at the start of a ramp from rest, with each stabilisation,
// on the paper's scene and on a confined compression. With GLS the momentum rows hold u̇ and the
// pressure is algebraic: a rate computed from the differentiated equilibrium alone leaves a
// momentum residual of the order of the load (measured: 1 N on mesh 1), far above the bound.
TEST_P(ConsistentStartEveryRow, FullResidualVanishes) {
  const StartCase c = GetParam();
  const bool paper = std::string(c.scene) == "paper";
  Config cfg = paper ? paper_reference_config(3.0) : confined_column_config(c.stabilisation);
  cfg.stabilisation.type = c.stabilisation;
  const Mesh& mesh = paper ? coarse_mesh() : column_mesh();
  BiphasicProblem problem(mesh, cfg);
  const Index n = problem.size();
  std::vector<double> y(n, 0.0);
  problem.apply_dirichlet(0.0, y.data(), nullptr);
  const ConsistentState cs = consistent_start(problem, 0.0, y, cfg.linear_solver);
  EXPECT_EQ(cs.pressure == PressureRole::Value, c.stabilisation == "gls");
  std::vector<double> F(n);
  problem.residual(0.0, cs.y.data(), cs.ydot.data(), F.data());
  // Load scales: the force that the largest prescribed displacement means over one element
  // [N], and the size of the mass rows' rate terms, Σ_j |∂F_p/∂ẏ_ij ẏ_j| [mm³/s] (their sum
  // vanishes at an undrained start; its terms do not).
  const double force_scale = problem.stiffness_scale() * problem.solution_scales().first;
  const SparsityPattern& pat = problem.pattern();
  std::vector<double> A(pat.nnz()), R(pat.nnz()), terms(n, 0.0);
  problem.jacobian(0.0, cs.y.data(), cs.ydot.data(), 0.0, A.data(), R.data());
  for (Index j = 0; j < n; ++j)
    for (Index q = pat.colptr()[j]; q < pat.colptr()[j + 1]; ++q)
      terms[pat.rowind()[q]] += std::abs(R[q] * cs.ydot[j]);
  double momentum = 0.0, mass = 0.0, mass_scale = 0.0;
  for (Index i = 0; i < n; ++i) {
    if (problem.constrained()[i]) continue;
    if (i < problem.num_u()) {
      momentum = std::max(momentum, std::abs(F[i]));
    } else {
      mass = std::max(mass, std::abs(F[i]));
      mass_scale = std::max(mass_scale, terms[i]);
    }
  }
  ASSERT_GT(force_scale, 0.0);
  ASSERT_GT(mass_scale, 0.0);  // the start moves: the rate terms are not trivially zero
  EXPECT_LE(momentum, 1e-10 * force_scale) << "momentum residual " << momentum << " N";
  EXPECT_LE(mass, 1e-10 * mass_scale) << "mass residual " << mass << " mm3/s";
  EXPECT_NEAR(cs.residual_u, momentum, 1e-300 + 1e-12 * force_scale);
  // The boundary rate is carried: the top moves at the ramp's rate.
  const Boundary* top = mesh.find_boundary(paper ? "top" : "z1");
  ASSERT_NE(top, nullptr);
  const double rate = paper ? -0.0025 : -0.002;
  for (const Tri6& f : top->faces)
    EXPECT_NEAR(cs.ydot[problem.pattern().u_dof(f[0], 2)], rate, 1e-15);
}

void PrintTo(const StartCase& c, std::ostream* os) {
  *os << c.scene << " stabilisation " << c.stabilisation;
}

std::string start_case_name(const ::testing::TestParamInfo<StartCase>& param) {
  return std::string(param.param.scene) + "_" + param.param.stabilisation;
}

INSTANTIATE_TEST_SUITE_P(StabilisationsAndScenes, ConsistentStartEveryRow,
                         ::testing::Values(StartCase{"paper", "none"}, StartCase{"paper", "gls"},
                                           StartCase{"paper", "flux_perturbation"},
                                           StartCase{"confined", "none"},
                                           StartCase{"confined", "gls"},
                                           StartCase{"confined", "flux_perturbation"}),
                         start_case_name);

// A ramp then a hold with GLS: BDF starts and restarts at the kink from consistent values (the
// pressure jumps there: the GLS term's volumetric rate stops with the platen), with the full
// residual at each start ≤ 1e-10 of the load (IDA leaves the algebraic constraints out of
// balance by its own tolerance at the kink; the start corrects them); the end state agrees with
// backward Euler at small steps. (Without the consistent start BDF failed at t = 0 on this kind of
// case.)
TEST(Bdf, RestartsConsistentlyAfterAKinkWithGls) {
  Config cfg = confined_column_config("gls");
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {10.0, 0.5}}};
  cfg.time.t_end = 20.0;
  cfg.time.dt = 2.0;
  cfg.time.bdf.rtol = 1e-6;
  BiphasicProblem problem(column_mesh(), cfg);
  BdfIntegrator bdf(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y(problem.size(), 0.0);
  bdf.run(0.0, y, nullptr);
  const auto& starts = bdf.stats().starts;
  ASSERT_EQ(starts.size(), 2u);
  EXPECT_DOUBLE_EQ(starts[1].t, 10.0);
  const double force_scale = problem.stiffness_scale() * problem.solution_scales().first;
  for (const auto& st : starts) {
    EXPECT_TRUE(st.pressure_solved);
    EXPECT_LE(st.residual_u, 1e-10 * force_scale) << "start at t = " << st.t;
  }
  Config be_cfg = cfg;
  be_cfg.time.integrator = Integrator::BackwardEuler;
  be_cfg.time.dt = 0.02;
  BiphasicProblem be_problem(column_mesh(), be_cfg);
  BackwardEuler be(be_problem, be_cfg.time, be_cfg.linear_solver);
  std::vector<double> y_be(be_problem.size(), 0.0);
  be.run(0.0, y_be, nullptr);
  const std::vector<double> p_bdf = pressures(problem, y), p_be = pressures(be_problem, y_be);
  EXPECT_LT(max_diff(p_bdf, p_be) / max_abs(p_bdf), 5e-3);
}

// adaptive_backward_euler is IDA held at order 1.
TEST(AdaptiveBackwardEuler, TakesOnlyFirstOrderSteps) {
  Config cfg = confined_column_config("none");
  cfg.time.integrator = Integrator::AdaptiveBackwardEuler;
  cfg.time.bdf.rtol = 1e-5;
  BiphasicProblem problem(column_mesh(), cfg);
  std::unique_ptr<TimeIntegrator> ti =
      make_time_integrator(problem, cfg.time, cfg.linear_solver, "");
  std::vector<double> y(problem.size(), 0.0);
  ti->run(0.0, y, nullptr);
  const auto& orders = ti->stats().order_counts;
  EXPECT_GT(orders[0], 5);
  for (std::size_t q = 1; q < orders.size(); ++q) EXPECT_EQ(orders[q], 0) << "order " << q + 1;
}

TEST(BackwardEuler, ConvergesAtOrderOneAgainstTightBdf) {
  Config cfg = paper_reference_config(3.0);
  expect_order_one_against_tight_bdf(cfg);
}

// The need-following GLS is frozen at stabilisation.time_step, so backward Euler at any Δt and
// IDA integrate one DAE F(t, y, ẏ) = 0: backward Euler converges at order one to the tight BDF
// solution. Had the coefficient followed each step's Δt, backward Euler would converge to
// another model than IDA's. Δt* is chosen so that H_A Δt* is the median of the paper's
// c_e = h²/(4k): half the elements keep a reduced GLS term, the other half none.
TEST(BackwardEuler, ConvergesToBdfWithTheNeedFollowingGls) {
  Config cfg = paper_reference_config(3.0);
  cfg.material.set("permeability", 0.05);
  std::vector<double> paper_ce;
  {
    const BiphasicProblem paper(coarse_mesh(), cfg);
    for (Index e = 0; e < paper.num_elements(); ++e) paper_ce.push_back(paper.gls_coefficient(e));
  }
  std::nth_element(paper_ce.begin(), paper_ce.begin() + paper_ce.size() / 2, paper_ce.end());
  cfg.stabilisation.type = "gls_minimal";
  cfg.stabilisation.time_step = paper_ce[paper_ce.size() / 2] / 1.2;  // H_A = 1.2 MPa
  {
    const BiphasicProblem problem(coarse_mesh(), cfg);
    ASSERT_TRUE(problem.has_gls());
    std::size_t off = 0;
    for (Index e = 0; e < problem.num_elements(); ++e) off += problem.gls_coefficient(e) == 0.0;
    EXPECT_GE(off, paper_ce.size() / 2 - 1);
    EXPECT_LT(off, paper_ce.size());
  }
  expect_order_one_against_tight_bdf(cfg);
}

TEST(Bdf, StopsAtLoadCurveKinkAndMatchesBackwardEuler) {
  Config cfg = paper_reference_config(3.0);
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {10.0, 0.5}}};  // ramp 10 s, then hold
  cfg.time.t_end = 20.0;
  cfg.time.dt = 2.0;
  cfg.time.bdf.rtol = 1e-6;
  cfg.time.bdf.step_log = true;
  const fs::path dir = fs::temp_directory_path() / ("biphasic_bdf_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::vector<double> bdf = run(cfg, Integrator::Bdf, dir.string());
  // No internal step straddles the kink at t = 10 s; one ends on it.
  std::ifstream log(dir / "steps.csv");
  std::string line;
  std::getline(log, line);
  EXPECT_EQ(line, "t,h,order");
  bool lands_on_kink = false;
  int steps = 0;
  while (std::getline(log, line)) {
    double t = 0, h = 0;
    char comma = 0;
    std::istringstream(line) >> t >> comma >> h;
    EXPECT_FALSE(t - h < 10.0 - 1e-9 && t > 10.0 + 1e-9) << "step (" << t - h << ", " << t << "]";
    lands_on_kink |= std::abs(t - 10.0) < 1e-9;
    ++steps;
  }
  EXPECT_TRUE(lands_on_kink);
  EXPECT_GT(steps, 5);
  fs::remove_all(dir);
  // After the kink the solution relaxes; backward Euler with small steps agrees.
  cfg.time.dt = 0.05;
  const std::vector<double> be = run(cfg, Integrator::BackwardEuler);
  EXPECT_LT(max_diff(be, bdf) / max_abs(bdf), 5e-3);
}

// IDA limited to maximum order q converges at order q: under tolerance proportionality the
// error against a tight reference falls as N^(−q) with the number of steps N. Confined
// consolidation of a column (1 × 1 × 4 mm, 8 cells), drained top, ramp loading.
TEST(Bdf, ConvergesAtItsMaximumOrder) {
  const Mesh mesh = test::box_mesh({1, 1, 8}, {1.0, 1.0, 4.0});
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(0.2, 0.5, 1e-2);
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {100.0, 1.0}}};
  cfg.bcs = {{BcType::Displacement, "z1", 2, -0.2, {}, "ramp"},
             {BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Symmetry, "x0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "x1", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y1", 0, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 0.0, {}, ""}};
  cfg.time.integrator = Integrator::Bdf;
  cfg.time.t_end = cfg.time.dt = 20.0;
  auto solve = [&](double rtol, int q) {
    Config c = cfg;
    c.time.bdf.rtol = rtol;
    c.time.bdf.atol_displacement = 1e-3 * rtol;  // mm
    c.time.bdf.atol_pressure = 1e-4 * rtol;      // MPa
    c.time.bdf.max_order = q;
    // Start near the asymptotic step size: the start-up phase (doubling from a small first
    // step) adds steps that do not scale with the tolerance and steepen the measured slope.
    c.time.bdf.initial_step = 1.0;
    BiphasicProblem problem(mesh, c);
    BdfIntegrator bdf(problem, c.time, c.linear_solver);
    std::vector<double> y(problem.size(), 0.0);
    bdf.run(0.0, y, nullptr);
    return std::make_pair(pressures(problem, y), bdf.stats().steps);
  };
  const std::vector<double> reference = solve(1e-9, 5).first;
  for (int q : {1, 2, 3}) {
    // Least-squares slope of log(error) against log(steps) over three tolerances.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (double rtol : {1e-4, 1e-5, 1e-6}) {
      const auto [p, steps] = solve(rtol, q);
      const double x = std::log(static_cast<double>(steps));
      const double yv = std::log(max_diff(p, reference) / max_abs(reference));
      std::printf("q %d rtol %g steps %ld error %g\n", q, rtol, steps, std::exp(yv));
      sx += x;
      sy += yv;
      sxx += x * x;
      sxy += x * yv;
    }
    const double slope = (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
    EXPECT_NEAR(-slope, q, 0.4) << "maximum order " << q;
  }
}

}  // namespace
}  // namespace biphasic
