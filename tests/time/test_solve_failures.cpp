// Failures that used to pass silently, and failure messages in words: step counts beyond an
// int, absolute Newton tolerances that accept any state, time.bdf.max_steps, exceptions inside
// SUNDIALS callbacks, and SUNDIALS return flags as sentences.
#include <gtest/gtest.h>

#include <ida/ida.h>
#include <kinsol/kinsol.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "biphasic/time/bdf_integrator.hpp"
#include "biphasic/time/solver_messages.hpp"
#include "column_case.hpp"

namespace biphasic {
namespace {

/// The shared column (column_case.hpp), its top pushed down 5 %.
Config config(const std::vector<std::string>& overrides = {}) {
  return column_case::config("-0.05", "failures.toml", overrides);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(StepCount, IsComputedBeyondTheRangeOfInt) {
  EXPECT_EQ(interval_count(32.0, 6.4), 5);
  EXPECT_EQ(interval_count(1.0, 0.3), 4);                          // the last interval shortened
  EXPECT_EQ(interval_count(1.0, 2.0), 1);                          // at least one
  EXPECT_EQ(interval_count(416.666667, 1.6666666666666667), 250);  // a 2e-7 sliver merged
  EXPECT_EQ(interval_count(1.0001, 0.25), 5);  // a short last interval (4e-4 of a step) kept
  EXPECT_EQ(interval_count(32.0, 1e-8), 3'200'000'000LL);  // > 2^31
  EXPECT_EQ(interval_count(1e308, 1.0), std::numeric_limits<long long>::max());
  EXPECT_EQ(interval_count(1e308, 1e-300), std::numeric_limits<long long>::max());  // inf
}

TEST(StepCount, IntegratorsRefuseMoreStepsThanTheLimit) {
  EXPECT_EQ(checked_interval_count(10.0, 1e-6), 10'000'000);
  for (const auto& [t_end, dt] : {std::pair{32.0, 1e-8}, std::pair{1e308, 1.0}}) {
    try {
      checked_interval_count(t_end, dt);
      FAIL() << "accepted t_end " << t_end << ", dt " << dt;
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(contains(e.what(), "time.dt")) << e.what();
      EXPECT_TRUE(contains(e.what(), "time.t_end")) << e.what();
    }
  }
}

// An absolute tolerance as large as the loads accepts the initial guess of every step after
// zero Newton iterations (p stays 0): refused before the first step, naming key and value.
TEST(NewtonTolerance, AbsurdAbsoluteToleranceIsRefused) {
  for (const char* key : {"time.newton.atol_displacement", "time.newton.atol_pressure"}) {
    const Config cfg = config({std::string(key) + "=1e308"});
    const Mesh mesh = generate_column(cfg.mesh.column);
    BiphasicProblem problem(mesh, cfg);
    try {
      BackwardEuler be(problem, cfg.time, cfg.linear_solver);
      FAIL() << key << " = 1e308 accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(contains(e.what(), std::string(key) + " = 1e+308")) << e.what();
    }
  }
}

TEST(NewtonTolerance, DefaultToleranceSolvesEveryStep) {
  const Config cfg = config();
  const Mesh mesh = generate_column(cfg.mesh.column);
  BiphasicProblem problem(mesh, cfg);
  BackwardEuler be(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y = column_case::rest_state(problem);
  int loaded_steps = 0;
  be.run(0.0, y, [&](const StepInfo& info, const std::vector<double>& ys, auto&) {
    if (info.step == 1) {
      EXPECT_GT(info.newton_iterations, 0);
      double p_max = 0.0;
      for (Index i = problem.num_u(); i < problem.size(); ++i) p_max = std::max(p_max, ys[i]);
      EXPECT_GT(p_max, 1e-3);  // the undrained response of a 5 % push [MPa]
      ++loaded_steps;
    }
  });
  EXPECT_EQ(loaded_steps, 1);
}

// time.bdf.max_steps limits the internal steps between two outputs (IDA's own limit does not
// act in one-step mode).
TEST(BdfMaxSteps, TinyLimitStopsTheRunWithAClearMessage) {
  const Config cfg = config({"time.integrator=\"bdf\"", "time.bdf.max_steps=3"});
  const Mesh mesh = generate_column(cfg.mesh.column);
  BiphasicProblem problem(mesh, cfg);
  BdfIntegrator bdf(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y = column_case::rest_state(problem);
  try {
    bdf.run(0.0, y, nullptr);
    FAIL() << "ran with at most 3 internal steps per output";
  } catch (const StepFailure& e) {
    const std::string what = e.what();
    EXPECT_TRUE(contains(what, "BDF output step 1 (towards t = 1 s)")) << what;
    EXPECT_TRUE(contains(what, "time.bdf.max_steps = 3 internal steps taken")) << what;
    EXPECT_TRUE(contains(what, "h = ")) << what;
  }
  EXPECT_EQ(bdf.stats().steps, 0);  // accumulated only at the end
}

TEST(BdfMaxSteps, EnoughStepsRunToTheEnd) {
  const Config cfg = config({"time.integrator=\"bdf\"", "time.bdf.max_steps=500"});
  const Mesh mesh = generate_column(cfg.mesh.column);
  BiphasicProblem problem(mesh, cfg);
  BdfIntegrator bdf(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y = column_case::rest_state(problem);
  int outputs = 0;
  bdf.run(0.0, y, [&](const StepInfo& info, auto&, auto&) {
    EXPECT_LE(info.internal_steps, 500);
    ++outputs;
  });
  EXPECT_EQ(outputs, 4);
}

TEST(Callbacks, EveryExceptionIsCaughtStoredAndFlagged) {
  CallbackFailure failure;
  EXPECT_EQ(guarded_callback(failure, [] {}), 0);
  EXPECT_TRUE(failure.empty());
  EXPECT_EQ(guarded_callback(failure, [] { throw InvertedElement("element 3: J = -0.1"); }), 1);
  EXPECT_EQ(failure.message, "element 3: J = -0.1");
  EXPECT_TRUE(failure.recoverable);
  EXPECT_EQ(guarded_callback(failure, [] { throw std::bad_alloc(); }), -1);
  EXPECT_FALSE(failure.recoverable);
  EXPECT_FALSE(failure.empty());
  EXPECT_EQ(guarded_callback(failure, [] { throw 42; }), -1);
  EXPECT_EQ(failure.message, "an exception of unknown type");
}

/// A body force that cannot be evaluated after t = 1.5 s: a std::runtime_error, not an
/// inverted element (zero before).
VectorField body_force_failing_after_1_5_s() {
  return [](const Vec3&, double t) -> Vec3 {
    if (t > 1.5) throw std::runtime_error("the body force table ends at t = 1.5 s");
    return Vec3::Zero();
  };
}

/// Runs `integrator` on `problem` from rest, expecting a StepFailure; returns its message and
/// the output times the observer saw before it.
template <class Integrator>
std::pair<std::string, std::set<double>> failed_run(Integrator& integrator,
                                                    const BiphasicProblem& problem) {
  std::set<double> outputs;
  std::vector<double> y = column_case::rest_state(problem);
  try {
    integrator.run(0.0, y, [&](const StepInfo& info, auto&, auto&) { outputs.insert(info.t); });
  } catch (const StepFailure& e) {
    return {e.what(), outputs};
  }
  ADD_FAILURE() << "the run completed";
  return {"", outputs};
}

/// Runs backward Euler (up to 4 cut-backs, the default) on the column after `spoil` has made
/// some of the problem's data fail; expects it to stop at once in step 2 (t = 2 s): no
/// cut-back, the message naming the step, its time and step size and `causes`, and the output
/// at t = 1 s delivered before.
void expect_backward_euler_stops_in_step_2(const std::function<void(BiphasicProblem&)>& spoil,
                                           const std::vector<std::string>& causes) {
  const Config cfg = config();
  ASSERT_EQ(cfg.time.newton.max_cutbacks, 4);
  const Mesh mesh = generate_column(cfg.mesh.column);
  BiphasicProblem problem(mesh, cfg);
  spoil(problem);
  BackwardEuler be(problem, cfg.time, cfg.linear_solver);
  const auto [what, outputs] = failed_run(be, problem);
  EXPECT_TRUE(contains(what, "backward Euler step 2 (t = 2 s, dt = 1 s) failed: ")) << what;
  for (const std::string& cause : causes) EXPECT_TRUE(contains(what, cause)) << what;
  EXPECT_TRUE(be.stats().cutbacks.empty()) << be.stats().cutbacks.size() << " cut-backs";
  EXPECT_EQ(outputs, (std::set<double>{1.0}));
}

// An exception other than an inverted element while evaluating the residual stops backward
// Euler at once (the same evaluation would fail again after a cut-back), naming step, time and
// cause in words. Here the body force of the step's first trial state throws.
TEST(CallbackFailure, BackwardEulerStopsWithoutCutbacksNamingStepTimeAndCause) {
  expect_backward_euler_stops_in_step_2(
      [](BiphasicProblem& problem) { problem.set_body_force(body_force_failing_after_1_5_s()); },
      {"the residual could not be evaluated", "the body force table ends at t = 1.5 s"});
}

// The same inside KINSOL's residual callback (guarded_callback: no exception crosses SUNDIALS'
// C frames; any but an inverted element is unrecoverable). The boundary values come from a
// field that throws from its third evaluation at a node and time after t = 1.5 s: backward
// Euler evaluates them twice before Newton (the trial state and its residual), so the
// exception is raised within KINSol.
TEST(CallbackFailure, BackwardEulerStopsOnAnExceptionInsideTheNewtonIteration) {
  expect_backward_euler_stops_in_step_2(
      [](BiphasicProblem& problem) {
        auto evaluations =
            std::make_shared<std::map<std::tuple<double, double, double, double>, int>>();
        problem.set_dirichlet_fields(
            [evaluations](const Vec3& X, double t) -> Vec3 {
              if (t > 1.5 && ++(*evaluations)[{X(0), X(1), X(2), t}] >= 3)
                throw std::runtime_error("the boundary data ends at t = 1.5 s");
              // The case's own values: the top pushed down 0.05 mm along the ramp.
              return {0.0, 0.0, X(2) == 1.0 ? -0.05 * std::min(t, 1.0) : 0.0};
            },
            {}, [](const Vec3&, double) -> Vec3 { return Vec3::Zero(); });
      },
      {"the residual could not be evaluated (KIN_", "the boundary data ends at t = 1.5 s"});
}

// BDF: the exception inside IDA's residual callback ends the run in the output interval where it
// occurred, naming it, the internal step, t, h and the cause; the output before it delivered.
TEST(CallbackFailure, BdfStopsNamingOutputStepTimeStepSizeAndCause) {
  const Config cfg = config({"time.integrator=\"bdf\""});
  const Mesh mesh = generate_column(cfg.mesh.column);
  BiphasicProblem problem(mesh, cfg);
  problem.set_body_force(body_force_failing_after_1_5_s());
  BdfIntegrator bdf(problem, cfg.time, cfg.linear_solver);
  const auto [what, outputs] = failed_run(bdf, problem);
  EXPECT_TRUE(contains(what, "BDF output step 2 (towards t = 2 s): internal step ")) << what;
  EXPECT_TRUE(contains(what, " from t = ")) << what;
  EXPECT_TRUE(contains(what, "h = ")) << what;
  EXPECT_TRUE(contains(what, "(IDA_RES_FAIL): the body force table ends at t = 1.5 s")) << what;
  EXPECT_EQ(outputs, (std::set<double>{1.0}));
}

// Every flag KINSol and IDASolve can return reads as a sentence with the flag's name.
TEST(SolverMessages, EveryFlagIsASentenceWithItsName) {
  for (int flag = -17; flag <= 2; ++flag) {
    const std::string text = kinsol_flag_message(flag);
    EXPECT_FALSE(contains(text, "KINSOL return")) << flag << ": " << text;
    EXPECT_TRUE(contains(text, "KIN_") || contains(text, "KINSOL memory")) << flag << ": " << text;
  }
  for (int flag : {-1,  -2,  -3,  -4,  -5,  -6,  -7,  -8,  -9,  -10, -11, -12, -13, -14, -15,
                   -16, -17, -20, -21, -22, -23, -24, -25, -26, -27, -28, -29, 0,   1}) {
    const std::string text = ida_flag_message(flag, 1e-9);
    EXPECT_FALSE(contains(text, "IDA return")) << flag << ": " << text;
    EXPECT_TRUE(contains(text, "IDA_") || contains(text, "IDA memory")) << flag << ": " << text;
  }
  EXPECT_EQ(ida_flag_message(IDA_CONV_FAIL, 1e-9),
            "the Newton iteration failed to converge repeatedly (h reduced to 1e-09 s) "
            "(IDA_CONV_FAIL)");
  EXPECT_TRUE(contains(kinsol_flag_message(KIN_MAXITER_REACHED), "time.newton.max_iterations"));
  EXPECT_TRUE(contains(kinsol_flag_message(-99), "KINSOL return -99"));  // unknown: the number
}

}  // namespace
}  // namespace biphasic
