// Step cut-back of backward Euler (time.newton.max_cutbacks): a confined column whose drained
// top is pushed down 12 % of its height within the first step. At the full step the predictor
// (the previous state with the new boundary values) inverts the top elements; half steps
// succeed. A second variant fails on the Newton iteration limit instead.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "biphasic/app/run.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "column_case.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;

/// The shared column (column_case.hpp), its top pushed down 12 %, with a probe line on its axis.
Config config(const std::vector<std::string>& overrides = {}) {
  return column_case::config("-0.12", "cutback.toml", overrides,
                             "line_start = [0.0, 0.0, 0.0]\nline_end = [0.0, 0.0, 1.0]\n");
}

struct Output {
  StepInfo info;
  std::vector<double> y;
};

struct Record {
  std::vector<Output> outputs;
  IntegratorStats stats;
  std::vector<std::string> log;
};

/// Integrates `cfg` from t0 and state y (overwritten), recording every observer call.
Record integrate(const Mesh& mesh, const Config& cfg, double t0, std::vector<double>& y) {
  BiphasicProblem problem(mesh, cfg);
  BackwardEuler be(problem, cfg.time, cfg.linear_solver);
  Record run;
  be.set_log([&](const std::string& line) { run.log.push_back(line); });
  if (y.empty()) y = column_case::rest_state(problem, t0);
  be.run(t0, y,
         [&](const StepInfo& info, const std::vector<double>& ys, const std::vector<double>&) {
           run.outputs.push_back({info, ys});
         });
  run.stats = be.stats();
  return run;
}

/// max |a − b| over the unknowns, relative to max |b|.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

TEST(Cutback, WithoutCutbacksTheFullStepFails) {
  const Config cfg = config({"time.newton.max_cutbacks=0"});
  const Mesh mesh = generate_column(cfg.mesh.column);
  std::vector<double> y;
  try {
    integrate(mesh, cfg, 0.0, y);
    FAIL() << "the full first step should fail";
  } catch (const StepFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("backward Euler step 1 (t = 1 s, dt = 1 s)"), std::string::npos) << what;
    EXPECT_NE(what.find("inverted"), std::string::npos) << what;
  }
}

TEST(Cutback, HalvedStepsReachTheOutputsAndAgreeWithSmallStepsFromTheStart) {
  const Config cfg = config();
  ASSERT_EQ(cfg.time.newton.max_cutbacks, 4);  // the default
  const Mesh mesh = generate_column(cfg.mesh.column);
  std::vector<double> y;
  const Record run = integrate(mesh, cfg, 0.0, y);

  // One cut in step 1 (from t = 0 to dt = 0.5 s, an inverted element), logged once; then two
  // half steps reach t = 1 s, and the step doubles back to 1 s.
  ASSERT_EQ(run.stats.cutbacks.size(), 1u);
  EXPECT_EQ(run.stats.cutbacks[0].step, 1);
  EXPECT_EQ(run.stats.cutbacks[0].t, 0.0);
  EXPECT_EQ(run.stats.cutbacks[0].dt, 0.5);
  EXPECT_NE(run.stats.cutbacks[0].reason.find("inverted"), std::string::npos);
  ASSERT_EQ(run.log.size(), 1u);
  EXPECT_NE(run.log[0].find("retrying with dt = 0.5 s"), std::string::npos) << run.log[0];
  EXPECT_EQ(run.stats.steps, 5);

  // The observer sees exactly the requested output times, no sub-step.
  ASSERT_EQ(run.outputs.size(), 4u);
  const std::vector<int> sub_steps{2, 1, 1, 1};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(run.outputs[k].info.step, static_cast<int>(k) + 1);
    EXPECT_EQ(run.outputs[k].info.t, static_cast<double>(k + 1));
    EXPECT_EQ(run.outputs[k].info.sub_steps, sub_steps[k]) << "output " << k + 1;
  }
  EXPECT_EQ(run.outputs[0].info.dt, 0.5);
  EXPECT_EQ(run.outputs[1].info.dt, 1.0);

  // Independent reference: dt = 0.5 s from the start to t = 1 s, then dt = 1 s from there.
  std::vector<double> y_ref;
  const Record first = integrate(mesh, config({"time.dt=0.5", "time.t_end=1.0"}), 0.0, y_ref);
  ASSERT_EQ(first.outputs.size(), 2u);
  EXPECT_TRUE(first.stats.cutbacks.empty());
  EXPECT_LT(relative_difference(run.outputs[0].y, first.outputs[1].y), 1e-7);
  const Record rest = integrate(mesh, cfg, 1.0, y_ref);
  ASSERT_EQ(rest.outputs.size(), 3u);
  EXPECT_TRUE(rest.stats.cutbacks.empty());
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(rest.outputs[k].info.t, run.outputs[k + 1].info.t);
    EXPECT_LT(relative_difference(run.outputs[k + 1].y, rest.outputs[k].y), 1e-7)
        << "t = " << rest.outputs[k].info.t;
  }
  // The cut matters: the full step from rest is not this state (it fails), and a run of dt =
  // 0.5 s throughout differs at t = 4 s by the time-discretisation error, far above tolerance.
  std::vector<double> y_half;
  const Record half = integrate(mesh, config({"time.dt=0.5"}), 0.0, y_half);
  EXPECT_GT(relative_difference(run.outputs[3].y, half.outputs[7].y), 1e-5);
}

TEST(Cutback, NewtonIterationLimitCutsInsideOutputIntervals) {
  // With 3 full-Newton iterations allowed, a 10 % push fails on the iteration limit instead.
  const std::vector<std::string> tight{"boundary[0].value=-0.1", "time.newton.max_iterations=3",
                                       "time.newton.max_setup_calls=1"};
  const Mesh mesh = generate_column(config().mesh.column);
  {
    auto overrides = tight;
    overrides.push_back("time.newton.max_cutbacks=0");
    std::vector<double> y;
    try {
      integrate(mesh, config(overrides), 0.0, y);
      FAIL() << "should fail on the iteration limit";
    } catch (const StepFailure& e) {
      EXPECT_NE(std::string(e.what()).find("did not converge within time.newton.max_iterations "
                                           "iterations (KIN_MAXITER_REACHED)"),
                std::string::npos)
          << e.what();
    }
  }
  std::vector<double> y;
  const Record run = integrate(mesh, config(tight), 0.0, y);
  ASSERT_FALSE(run.stats.cutbacks.empty());
  EXPECT_EQ(run.log.size(), run.stats.cutbacks.size());
  long sub_steps = 0;
  for (std::size_t k = 0; k < run.outputs.size(); ++k) {
    EXPECT_EQ(run.outputs[k].info.t, static_cast<double>(k + 1));
    sub_steps += run.outputs[k].info.sub_steps;
  }
  EXPECT_EQ(run.outputs.size(), 4u);
  EXPECT_EQ(sub_steps, run.stats.steps);
  for (const Cutback& c : run.stats.cutbacks) {
    EXPECT_NE(c.reason.find("(KIN_MAXITER_REACHED)"), std::string::npos);
    // Halvings of dt = 1 s, starting inside the output interval of their step.
    const double levels = std::log2(1.0 / c.dt);
    EXPECT_EQ(levels, std::round(levels));
    EXPECT_GE(c.t, c.step - 1.0);
    EXPECT_LT(c.t, static_cast<double>(c.step));
  }
}

TEST(Cutback, FailureAfterTheLastCutNamesStepTimeAndReason) {
  // A 30 % push needs dt/8 at the start; one cut-back is not enough.
  const Config cfg = config({"boundary[0].value=-0.3", "time.newton.max_cutbacks=1"});
  const Mesh mesh = generate_column(cfg.mesh.column);
  std::vector<double> y;
  try {
    integrate(mesh, cfg, 0.0, y);
    FAIL() << "should fail after one cut-back";
  } catch (const StepFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("backward Euler step 1 (t = 0.5 s, dt = 0.5 s, after 1 cut-backs"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("inverted"), std::string::npos) << what;
  }
}

TEST(Cutback, SummaryCountsTheCutbacks) {
  fs::path dir = fs::temp_directory_path() / ("biphasic_cutback_" + std::to_string(::getpid()));
  RunOptions options;
  options.output_dir = dir.string();
  options.quiet = true;
  const nlohmann::json summary = run_case(config(), options);
  fs::remove_all(dir);
  EXPECT_EQ(summary.at("status"), "completed");
  EXPECT_EQ(summary.at("counters").at("cutbacks"), 1);
  EXPECT_EQ(summary.at("counters").at("steps"), 5);
  ASSERT_EQ(summary.at("cutbacks").size(), 1u);
  EXPECT_EQ(summary.at("cutbacks")[0].at("dt"), 0.5);
  // Outputs at t = 0 and the four requested times, nothing in between.
  ASSERT_EQ(summary.at("outputs").size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(summary.at("outputs")[k].at("t"), static_cast<double>(k));
  EXPECT_EQ(summary.at("steps")[0].at("sub_steps"), 2);
}

}  // namespace
}  // namespace biphasic
