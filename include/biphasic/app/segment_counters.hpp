// A run continued by --restart is made of segments; the summary's counters, timings and
// cut-backs describe them all. The checkpoint carries the totals up to its time, and each
// segment's own counts are added to them.
#pragma once

#include <nlohmann/json.hpp>

namespace biphasic {

/// `earlier` (the totals a checkpoint carried: summary "counters", "timings" or "cutbacks") and
/// `segment` (the same object for the work since the restart) combined into totals:
/// counts and seconds added; maxima (max_krylov_iterations) and extremes (step_size.min, .max)
/// combined; per-order counts added element by element; lists (consistent_starts, cut-backs)
/// concatenated; values that describe the state rather than the work (fill_ratio,
/// absolute_tolerances, step_size.median) taken from the segment. A key only one side has is
/// kept as it is.
nlohmann::json combine_segments(const nlohmann::json& earlier, const nlohmann::json& segment);

}  // namespace biphasic
