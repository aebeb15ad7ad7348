// Cryer's sphere (cases/verification/cryer): runs the sphere octant through run_case and
// compares the centre pressure with the series of biphasic_analytic; reads the line measures
// (overshoot, oscillation) of the summary along the radius from the centre to the drained
// surface.
#pragma once

#include <string>
#include <vector>

#include "verification_support.hpp"

namespace biphasic::verification {

/// Time factors T = c t/R² at which the profile is written and the centre pressure compared
/// (the notes tabulate 0.01, 0.1, 0.2; the peak is near 0.052).
inline const std::vector<double> kCryerTimes{0.01, 0.02, 0.05, 0.1, 0.2};
/// The centre pressure is compared at every output from this T on: earlier, the boundary layer
/// √(c t) is thinner than an element.
inline constexpr double kCryerFirstCompared = 0.01;
/// From this T on the physical profile is well resolved and the oscillation measure is read as
/// "after the rise began" (the analytic peak is at 0.052).
inline constexpr double kCryerQuietFrom = 0.04;

struct CryerResult {
  double max_error = 0.0;    ///< max |p_h(0, T) − p(0, T)| / P₀ over outputs T ≥ 0.01 [-]
  double peak = 0.0;         ///< largest computed centre pressure / P₀ over the outputs [-]
  double peak_time = 0.0;    ///< its T [-]
  double series_peak = 0.0;  ///< the series' maximum p(0, T) / P₀ [-]
  double series_peak_time = 0.0;  ///< its T [-]
  /// The summary's line measures along the radius: the largest oscillation over the outputs
  /// with T ≥ 0.01 and with T ≥ kCryerQuietFrom, and both measures at the output of the
  /// computed peak.
  double max_oscillation = 0.0;
  double max_oscillation_after_rise = 0.0;
  double oscillation_at_peak = 0.0;
  double overshoot_at_peak = 0.0;
  std::string drained_ends;  ///< of the probe line, from the summary
  int compared_times = 0;    ///< entries of kCryerTimes found among the outputs
};

/// Runs cases/verification/cryer/cryer.toml with `overrides` into scratch/label; when
/// $BIPHASIC_VERIFICATION_OUT is set, writes cryer/<label>_centre.csv (T, p_h(0)/P₀, series,
/// oscillation, overshoot at every output), cryer/<label>_profiles.csv (T, r/R, p_h/P₀, series
/// at kCryerTimes) and cryer/<label>_errors.csv.
CryerResult run_cryer(const std::string& label, const std::vector<std::string>& overrides,
                      const ScratchDir& scratch);

/// The undrained start: one backward-Euler step of Δt (from rest, step load) on the octant with
/// `overrides`. Returns the pressure over P₀ along the radius (r/R, p/P₀) and the summary's
/// oscillation measure of that step.
struct CryerFirstStep {
  std::vector<double> r, p;  ///< r/R increasing, p/P₀
  double oscillation = 0.0;
};
CryerFirstStep cryer_first_step(double dt, const std::vector<std::string>& overrides,
                                const ScratchDir& scratch, const std::string& label);

}  // namespace biphasic::verification
