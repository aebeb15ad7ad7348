// Unconfined compression between impermeable frictionless platens
// (cases/verification/unconfined_compression; Armstrong, Lai & Mow 1984): runs the quarter
// cylinder through run_case and compares the platen force (reaction on "top") and the centre
// pressure (axis, mid-height) with the ramp solution of biphasic_analytic.
#pragma once

#include <string>
#include <vector>

#include "verification_support.hpp"

namespace biphasic::verification {

/// τ = c t/a² at which the errors are reported one by one (the notes tabulate the step solution
/// at 0.01, 0.1 and 1).
inline const std::vector<double> kUnconfinedTimes{0.01, 0.05, 0.1, 0.2, 0.5, 1.0};
/// The errors are taken over the outputs from this τ on: earlier, the drained boundary layer
/// √(c t) at the lateral face is thinner than an element.
inline constexpr double kUnconfinedFirstCompared = 0.01;

struct UnconfinedResult {
  /// max over the outputs with τ ≥ 0.01 of |F_h − F| / (π a² ε₀ E) [-].
  double force_error = 0.0;
  /// max over the same outputs of |p_h − p| / (μ ε₀) at the centre [-].
  double pressure_error = 0.0;
  double max_balance = 0.0;  ///< max |F_top + F_bottom| / |F_top| (z) over the outputs [-]
  /// At kUnconfinedTimes: computed and series force and centre pressure (normalised).
  std::vector<double> force, force_series, pressure, pressure_series;
  double peak_pressure = 0.0;         ///< largest computed centre p / (μ ε₀) [-]
  double series_peak_pressure = 0.0;  ///< the series' largest value over the outputs [-]
  double max_oscillation = 0.0;       ///< summary's oscillation on the axis, τ ≥ 0.01 [-]
  std::string drained_ends;           ///< of the probe line, from the summary
};

/// Runs cases/verification/unconfined_compression/unconfined_compression.toml with `overrides`
/// into scratch/label; when $BIPHASIC_VERIFICATION_OUT is set, writes
/// unconfined_compression/<label>.csv (τ, force and centre pressure, computed and series, at
/// every output) and unconfined_compression/<label>_errors.csv.
UnconfinedResult run_unconfined(const std::string& label, const std::vector<std::string>& overrides,
                                const ScratchDir& scratch);

}  // namespace biphasic::verification
