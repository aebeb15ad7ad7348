// Terzaghi consolidation (cases/verification/terzaghi): runs the column through run_case and
// compares pressure and settlement with the series of biphasic_analytic.
#pragma once

#include <string>
#include <vector>

#include "verification_support.hpp"

namespace biphasic::verification {

/// Depths ζ/H below the drained face and time factors T = c t/H² of the tabulated values
/// (docs/verification.md, section 1).
inline const std::vector<double> kTerzaghiDepths{0.1, 0.25, 0.5, 0.75, 1.0};
inline const std::vector<double> kTerzaghiTimes{0.01, 0.05, 0.1, 0.2, 0.5, 1.0};

/// Errors of one run against the series, normalised by q (pressure) and by the final
/// settlement q H / H_A (settlement), over the tabulated depths and times it reached.
struct TerzaghiErrors {
  double pressure = 0.0;    ///< max |p_h − p| / q [-]
  double settlement = 0.0;  ///< max |U_h − U| [-]
  int compared_times = 0;   ///< tabulated times found among the outputs
};

/// Runs cases/verification/terzaghi/terzaghi.toml with `overrides` into scratch/label; when
/// $BIPHASIC_VERIFICATION_OUT is set, writes terzaghi/<label>_profiles.csv (T, ζ/H, p_h/q,
/// series), terzaghi/<label>_settlement.csv (T, U_h, U) and terzaghi/<label>_errors.csv.
TerzaghiErrors run_terzaghi(const std::string& label, const std::vector<std::string>& overrides,
                            const ScratchDir& scratch);

/// The column overrides for nz cubic cells: width = depth = height / nz.
std::vector<std::string> terzaghi_column(int nz);

}  // namespace biphasic::verification
