// Ramp confined compression (cases/verification/confined_compression): runs the column through
// run_case and compares the platen stress (reaction on "top" over the area) with the
// finite-strain Neo-Hookean reference and the linear solution of biphasic_analytic.
#pragma once

#include <string>
#include <vector>

#include "verification_support.hpp"

namespace biphasic::verification {

/// Times of the tabulated platen stresses [s] (docs/verification.md, section 2).
inline const std::vector<double> kConfinedTimes{10, 25, 50, 75, 100, 150, 200, 300, 500, 1000};

struct ConfinedResult {
  /// At each tabulated time: computed, finite-strain reference and linear platen stress [MPa].
  std::vector<double> computed, neo_hookean, linear;
  double max_error = 0.0;    ///< max |σ_h − σ_NH| / |σ_NH| over the tabulated times [-]
  double max_balance = 0.0;  ///< max |F_top + F_bottom| / |F_top| (z) over the outputs [-]
};

/// Runs cases/verification/confined_compression/confined_compression.toml with `overrides` into
/// scratch/label; when $BIPHASIC_VERIFICATION_OUT is set, writes
/// confined_compression/<label>.csv (t, computed, Neo-Hookean reference, linear) at every output
/// and confined_compression/<label>_errors.csv.
ConfinedResult run_confined(const std::string& label, const std::vector<std::string>& overrides,
                            const ScratchDir& scratch);

}  // namespace biphasic::verification
