// Oscillation measures on a pressure profile along a line (DESIGN.md §5).
#pragma once

#include <vector>

namespace biphasic {

struct LineMeasures {
  double p_mid = 0.0;       ///< pressure at mid-length of the line [MPa]
  double p_max = 0.0;       ///< [MPa]
  double p_min = 0.0;       ///< [MPa]
  double overshoot = 0.0;   ///< (max p − p_mid) / p_mid [-]
  double undershoot = 0.0;  ///< −min p / p_mid [-] (positive when p dips below zero)
  bool defined = false;     ///< false when p_mid = 0 (ratios undefined)
};

/// Measures of the profile p(s) given at increasing arc lengths s [mm]; p_mid interpolated
/// linearly at the middle of [s.front(), s.back()].
LineMeasures line_measures(const std::vector<double>& s, const std::vector<double>& p);

}  // namespace biphasic
