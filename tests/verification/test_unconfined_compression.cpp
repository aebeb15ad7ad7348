// Unconfined compression between impermeable frictionless platens (Armstrong, Lai & Mow 1984;
// cases/verification/unconfined_compression): the force on the top platen (a reaction) and the
// pressure at the centre against the linear series for a short ramp, with their errors falling
// under mesh refinement.
#include <gtest/gtest.h>

#include <cmath>

#include "unconfined_benchmark.hpp"

namespace biphasic::verification {
namespace {

// BDF (rtol 1e-6) on lc = 0.2 and 0.15, compared at every output with τ ≥ 0.01 (Δτ = 0.005).
// Measured: force error 4.1e-3 → 2.1e-3, centre-pressure error 2.25e-2 → 1.49e-2 (both
// largest during the early rise, τ = 0.01 and 0.06; normalised by π a² ε₀ E and μ ε₀).
TEST(UnconfinedCompression, ForceAndCentrePressureConvergeWithTheMesh) {
  ScratchDir scratch("unconfined");
  const UnconfinedResult coarse = run_unconfined("bdf_lc0.2", {"mesh.lc=0.2"}, scratch);
  const UnconfinedResult fine = run_unconfined("bdf_lc0.15", {"mesh.lc=0.15"}, scratch);
  for (const UnconfinedResult* r : {&coarse, &fine}) {
    EXPECT_EQ(r->force.size(), kUnconfinedTimes.size());
    EXPECT_EQ(r->drained_ends, "none");
    // The platens carry equal and opposite forces (up to BDF's interpolation between steps).
    EXPECT_LT(r->max_balance, 1e-6);
    // The centre pressure rises above its undrained value μ ε₀ (to 1.23 in the series): a
    // physical rise, and along the axis (p uniform in z) no oscillation.
    EXPECT_GT(r->peak_pressure, 1.15);
    EXPECT_NEAR(r->peak_pressure, r->series_peak_pressure, 0.03);
    EXPECT_LT(r->max_oscillation, 2e-3);
  }
  EXPECT_LT(coarse.force_error, 6e-3);
  EXPECT_LT(coarse.pressure_error, 3e-2);
  EXPECT_LT(fine.force_error, 0.7 * coarse.force_error);
  EXPECT_LT(fine.pressure_error, 0.8 * coarse.pressure_error);
  std::cout << "[ unconfined ] lc 0.2: force " << coarse.force_error << ", pressure "
            << coarse.pressure_error << ", balance " << coarse.max_balance << ", oscillation "
            << coarse.max_oscillation << "; lc 0.15: force " << fine.force_error << ", pressure "
            << fine.pressure_error << ", balance " << fine.max_balance << ", oscillation "
            << fine.max_oscillation << "; peak p " << fine.peak_pressure << " (series "
            << fine.series_peak_pressure << ")\n";
}

}  // namespace
}  // namespace biphasic::verification
