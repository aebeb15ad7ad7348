// The pre-run oscillation advisor (biphasic/study/oscillation_advisor.hpp) on the column of the
// oscillation benchmark (cases/verification/oscillation, h = 0.1 mm layers, c = 1e-3 mm²/s):
// its r against c Δt / h² by hand, its verdict against the first-step overshoot the solver
// actually produces, and its threshold against where that overshoot crosses 1 %.
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>

#include "biphasic/study/oscillation_advisor.hpp"
#include "oscillation_benchmark.hpp"

namespace biphasic::verification {
namespace {

constexpr double kLayer = 0.1;  // H / nz of the case [mm]
constexpr double kC = 1e-3;     // k (λ + 2μ) = 1e-3 · (0 + 2 · 0.5) [mm²/s]

Config column(double r, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides{"time.dt=" + std::to_string(r * kLayer * kLayer / kC),
                                     "time.t_end=" + std::to_string(r * kLayer * kLayer / kC)};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return read_case_file(case_path("oscillation", "oscillation.toml"), overrides);
}

TEST(OscillationAdvisor, RatioIsCDtOverTheLayerThicknessSquared) {
  for (double r : {0.05, 0.3, 1.2}) {
    const Config config = column(r);
    const Mesh mesh = build_mesh(config, "");
    const OscillationAdvice advice = advise_oscillation(mesh, config);
    EXPECT_NEAR(advice.consolidation_coefficient, kC, 1e-15);
    ASSERT_EQ(advice.faces.size(), 1u);  // only "top" is drained
    const DrainedFaceAdvice& top = advice.faces[0];
    EXPECT_EQ(top.face, "top");
    EXPECT_EQ(top.elements, 2);  // one cell under the top, its square split into two triangles
    EXPECT_NEAR(top.h_min, kLayer, 1e-12);
    EXPECT_NEAR(top.h_median, kLayer, 1e-12);
    EXPECT_NEAR(top.h_max, kLayer, 1e-12);
    const double by_hand = kC * config.time.dt / (kLayer * kLayer);
    EXPECT_NEAR(top.r_min, by_hand, 1e-9 * by_hand);
    EXPECT_NEAR(top.r_median, by_hand, 1e-9 * by_hand);
    EXPECT_EQ(top.in_regime, r < kOscillationThreshold) << "r = " << r;
  }
  // A finer, wider column: 4 × 3 cells under the top, still h = 0.1 mm.
  const Config wide = column(0.2, {"mesh.column.nx=4", "mesh.column.ny=3", "mesh.column.width=0.4",
                                   "mesh.column.depth=0.3"});
  const OscillationAdvice advice = advise_oscillation(build_mesh(wide, ""), wide);
  EXPECT_EQ(advice.faces.at(0).elements, 2 * 4 * 3);
  EXPECT_NEAR(advice.faces.at(0).r_min, 0.2, 1e-9);
}

// With material regions, the drained face's r uses the material next to it: a top region four
// times less permeable has a quarter of c, so r falls by 4 and the verdict can change; the same
// region under the top (not touching it) leaves r alone.
TEST(OscillationAdvisor, EachDrainedFaceUsesTheMaterialNextToIt) {
  const std::vector<std::string> layered{"mesh.column.region_names=[\"lower\", \"upper\"]",
                                         "mesh.column.region_tops=[0.5, 1.0]"};
  for (const std::string& tight : {std::string("upper"), std::string("lower")}) {
    Config config = column(0.6, layered);
    RegionConfig region{tight, config.material};
    region.material.set("permeability", 0.25 * config.material.get("permeability"));
    config.regions.push_back(region);
    const OscillationAdvice advice = advise_oscillation(build_mesh(config, ""), config);
    EXPECT_NEAR(advice.consolidation_coefficient, kC, 1e-15);  // [material]'s
    const DrainedFaceAdvice& top = advice.faces.at(0);
    const double c_top = tight == "upper" ? 0.25 * kC : kC;
    EXPECT_NEAR(top.consolidation_coefficient, c_top, 1e-15) << tight;
    EXPECT_NEAR(top.r_min, c_top * config.time.dt / (kLayer * kLayer), 1e-9) << tight;
    EXPECT_EQ(top.in_regime, tight == "upper") << tight;  // r = 0.15 < 0.33 only when upper
  }
}

TEST(OscillationAdvisor, VerdictAgreesWithTheSolversFirstStep) {
  const Mesh mesh = build_mesh(column(1.0), "");
  // Two r on either side of the threshold: flagged ⇔ the first step overshoots q by > 1 %.
  for (double r : {0.1, 0.25, 0.45, 0.7}) {
    const Config config = column(r);
    const DrainedFaceAdvice top = advise_oscillation(mesh, config).faces.at(0);
    const double overshoot = first_step_overshoot(mesh, config, r).vertices;
    EXPECT_EQ(top.in_regime, overshoot > 0.01) << "r = " << r << ", overshoot " << overshoot;
    EXPECT_EQ(top.in_regime, r < kOscillationThreshold) << "r = " << r;
    if (top.in_regime) {
      // The remedies: Δt ≥ r* h²/c and h ≤ sqrt(c Δt / r*).
      ASSERT_EQ(top.advice.size(), 3u);
      EXPECT_NE(top.advice[0].find("gls"), std::string::npos);
      const double dt_min = kOscillationThreshold * kLayer * kLayer / kC;
      char expected[64];
      std::snprintf(expected, sizeof expected, "time.dt >= %.3g s", dt_min);
      EXPECT_EQ(top.advice[1], expected);
    } else {
      EXPECT_TRUE(top.advice.empty());
    }
  }
}

TEST(OscillationAdvisor, ThresholdIsWhereTheColumnsOvershootCrossesOnePercent) {
  // With every height equal to the layer thickness, r* must be where the first-step overshoot
  // (max p − q)/q falls through 0.01; located by bisection (the overshoot decreases with r).
  const Config base = column(1.0);
  const Mesh mesh = build_mesh(base, "");
  double lo = 0.25, hi = 0.45;
  ASSERT_GT(first_step_overshoot(mesh, base, lo).vertices, 0.01);
  ASSERT_LT(first_step_overshoot(mesh, base, hi).vertices, 0.01);
  while (hi - lo > 1e-4) {
    const double mid = 0.5 * (lo + hi);
    (first_step_overshoot(mesh, base, mid).vertices > 0.01 ? lo : hi) = mid;
  }
  std::cout << "[ advisor ] column: the first-step overshoot crosses 1 % at r = " << hi << "\n";
  EXPECT_LE(hi, kOscillationThreshold);
  EXPECT_GT(hi, 0.95 * kOscillationThreshold);
}

TEST(OscillationAdvisor, StabilisationAndBdfNotes) {
  const Mesh mesh = build_mesh(column(0.1), "");
  for (const char* s : {"gls", "flux_perturbation"}) {
    const Config config = column(0.1, {std::string("stabilisation.type=") + s});
    const DrainedFaceAdvice top = advise_oscillation(mesh, config).faces.at(0);
    EXPECT_TRUE(top.in_regime);
    ASSERT_EQ(top.advice.size(), 1u);
    EXPECT_NE(top.advice[0].find(std::string("stabilisation \"") + s + "\" is on"),
              std::string::npos);
  }
  // BDF: whatever time.dt (here r = 10 at time.dt), IDA's first step is 1 % of the first output
  // interval (or of the time to the first kink), so r ≤ 0.1 at the start.
  const Config bdf = column(10.0, {"time.integrator=bdf"});
  const OscillationAdvice advice = advise_oscillation(mesh, bdf);
  EXPECT_TRUE(advice.bdf);
  EXPECT_NEAR(advice.first_step, 1e-2 * std::min(bdf.time.dt, bdf.time.t_end), 1e-12);
  EXPECT_NEAR(advice.faces.at(0).r_min, 10.0 * advice.first_step / bdf.time.dt, 1e-9);
  EXPECT_TRUE(advice.faces.at(0).in_regime);
  EXPECT_NE(advice.faces.at(0).advice.back().find("whatever time.dt"), std::string::npos);
  // With a configured initial step, r is that step's.
  const Config bdf_h0 = column(10.0, {"time.integrator=bdf", "time.bdf.initial_step=5"});
  EXPECT_NEAR(advise_oscillation(mesh, bdf_h0).faces.at(0).r_min, 0.5, 1e-9);
  EXPECT_FALSE(advise_oscillation(mesh, bdf_h0).faces.at(0).in_regime);
}

TEST(OscillationAdvisor, SummaryHoldsTheAdvice) {
  const ScratchDir scratch("advisor");
  const BenchmarkRun run =
      run_benchmark("oscillation", {"time.dt=1.0", "time.t_end=1.0"}, scratch, "r0.1");
  const auto& top = run.summary.at("advisor").at("faces").at("top");
  EXPECT_NEAR(top.at("r_min").get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(top.at("r_median").get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(top.at("h_max").get<double>(), kLayer, 1e-12);
  EXPECT_EQ(top.at("threshold").get<double>(), kOscillationThreshold);
  EXPECT_TRUE(top.at("in_regime").get<bool>());
  EXPECT_EQ(top.at("advice").size(), 3u);
  // The solver agrees: the first output overshoots along the probe edge by far more than 1 %.
  EXPECT_GT(run.summary.at("outputs").at(1).at("overshoot").get<double>(), 0.05);
}

}  // namespace
}  // namespace biphasic::verification
