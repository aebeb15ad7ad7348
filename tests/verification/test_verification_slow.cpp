// The verification benchmarks on finer meshes and with smaller steps (label `slow`).
#include <gtest/gtest.h>

#include <cmath>

#include "confined_benchmark.hpp"
#include "cryer_benchmark.hpp"
#include "oscillation_benchmark.hpp"
#include "terzaghi_benchmark.hpp"
#include "unconfined_benchmark.hpp"

namespace biphasic::verification {
namespace {

// BDF (tight tolerance) on 40 layers: the spatial error keeps falling (pressure 4.3e-3 → 1.0e-3,
// settlement 5.8e-4 → 1.2e-4 from 20 to 40 layers).
TEST(TerzaghiSlow, BdfOnFortyLayers) {
  ScratchDir scratch("terzaghi_slow_bdf");
  std::vector<std::string> o = terzaghi_column(40);
  for (const char* s :
       {"curves.load=[[0.0, 0.0], [0.01, 1.0]]", "boundary[0].curve=load", "time.integrator=bdf",
        "time.bdf.rtol=1e-6", "time.bdf.atol_displacement=1e-14", "time.bdf.atol_pressure=1e-14"})
    o.emplace_back(s);
  const TerzaghiErrors e = run_terzaghi("bdf_nz40", o, scratch);
  EXPECT_EQ(e.compared_times, 6);
  EXPECT_LT(e.pressure, 2e-3);
  EXPECT_LT(e.settlement, 3e-4);
  std::cout << "[ BDF ] nz 40: p " << e.pressure << ", U " << e.settlement << "\n";
}

// Backward Euler on 40 layers with Δt = 1.25 s: first order in time continues.
TEST(TerzaghiSlow, BackwardEulerOnFortyLayers) {
  ScratchDir scratch("terzaghi_slow_be");
  std::vector<std::string> o = terzaghi_column(40);
  o.emplace_back("time.dt=1.25");
  const TerzaghiErrors e = run_terzaghi("be_nz40_dt1.25", o, scratch);
  EXPECT_EQ(e.compared_times, 6);
  EXPECT_LT(e.pressure, 0.025);
  EXPECT_LT(e.settlement, 2.5e-3);
  std::cout << "[ backward Euler ] nz 40, dt 1.25: p " << e.pressure << ", U " << e.settlement
            << "\n";
}

// 40 layers graded 20:1 toward the drained top, BDF at rtol 1e-7.
TEST(ConfinedCompressionSlow, FineColumn) {
  ScratchDir scratch("confined_slow");
  const ConfinedResult r = run_confined(
      "bdf_nz40", {"mesh.column.nz=40", "mesh.column.grading_ratio=20", "time.bdf.rtol=1e-7"},
      scratch);
  EXPECT_LT(r.max_error, 5e-4);
  std::cout << "[ confined compression ] nz 40: max relative error " << r.max_error << "\n";
}

// Backward Euler with Δt = 0.5 s (2000 steps) on the default column: its first-order time error
// is largest early in the ramp.
TEST(ConfinedCompressionSlow, BackwardEuler) {
  ScratchDir scratch("confined_slow_be");
  const ConfinedResult r =
      run_confined("be_nz20_dt0.5",
                   {"time.integrator=backward_euler", "time.dt=0.5", "output.every=10"}, scratch);
  EXPECT_LT(r.max_error, 1e-2);
  std::cout << "[ confined compression ] backward Euler dt 0.5: max relative error " << r.max_error
            << "\n";
}

// On 20 layers the overshoot is a function of r alone: the same as on 10 layers.
TEST(OscillationSlow, TwentyLayersGiveTheSameCurve) {
  const OscillationSweep coarse = sweep_first_step(10);
  const OscillationSweep fine = sweep_first_step(20);
  for (const auto& [name, values] : coarse.overshoot) {
    for (std::size_t i = 0; i < values.size(); ++i)
      EXPECT_NEAR(fine.overshoot.at(name)[i].vertices, values[i].vertices, 0.02)
          << name << ", r = " << coarse.r[i];
    EXPECT_NEAR(fine.threshold.at(name), coarse.threshold.at(name),
                0.05 * coarse.threshold.at(name))
        << name;
  }
}

// Cryer's sphere on lc = 0.1 (14.6k unknowns), backward Euler with Δt = 0.5 s (ΔT = 5e-4):
// the centre-pressure error keeps falling (0.026 on lc = 0.15 with Δt = 1 s).
TEST(CryerSlow, FineOctant) {
  ScratchDir scratch("cryer_slow");
  const CryerResult r =
      run_cryer("be_lc0.1_dt0.5", {"mesh.sphere_octant.lc=0.1", "time.dt=0.5"}, scratch);
  EXPECT_EQ(r.compared_times, 5);
  EXPECT_LT(r.max_error, 0.016);
  EXPECT_NEAR(r.peak, r.series_peak, 0.016);
  EXPECT_NEAR(r.peak_time, r.series_peak_time, 0.003);
  EXPECT_LT(r.max_oscillation_after_rise, 1e-9);
  EXPECT_GT(r.overshoot_at_peak, 0.2);
  std::cout << "[ Cryer ] lc 0.1, dt 0.5: max error " << r.max_error << ", peak " << r.peak
            << " at T = " << r.peak_time << ", oscillation over T >= 0.01 " << r.max_oscillation
            << "\n";
}

// Unconfined compression on lc = 0.1 (11.5k unknowns): force error 2.1e-3 → 1.3e-3 and centre
// pressure error 1.5e-2 → 6.7e-3 from lc = 0.15.
TEST(UnconfinedCompressionSlow, FineCylinder) {
  ScratchDir scratch("unconfined_slow");
  const UnconfinedResult r = run_unconfined("bdf_lc0.1", {"mesh.lc=0.1"}, scratch);
  EXPECT_EQ(r.force.size(), kUnconfinedTimes.size());
  EXPECT_LT(r.force_error, 1.8e-3);
  EXPECT_LT(r.pressure_error, 1e-2);
  EXPECT_LT(r.max_balance, 1e-6);
  std::cout << "[ unconfined ] lc 0.1: force " << r.force_error << ", pressure " << r.pressure_error
            << "\n";
}

}  // namespace
}  // namespace biphasic::verification
