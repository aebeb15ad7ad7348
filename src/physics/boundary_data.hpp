// Helpers shared by the three- and two-dimensional problems for boundary data: labels in
// messages, the largest value of a condition over a run, and rates by central differences.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/io/config.hpp"

namespace biphasic::detail {

/// "boundary[i] (type on 'name')": how messages name a boundary condition.
inline std::string bc_label(std::size_t i, const BoundaryCondition& bc) {
  return "boundary[" + std::to_string(i) + "] (" + to_string(bc.type) + " on '" + bc.boundary +
         "')";
}

/// ∂f/∂t by a central difference with step 6e-6·max(1, |t|) (≈ ε^(1/3): truncation and
/// rounding errors balance near 1e-11 relative for smooth fields).
template <class Field>
auto central_rate(const Field& f, const Vec3& X, double t) {
  const double h = 6e-6 * std::max(1.0, std::abs(t));
  return (f(X, t + h) - f(X, t - h)) / (2.0 * h);
}

/// Largest |value · curve(t)| over [0, t_end] (curves are piecewise linear: their points
/// inside the interval and its ends).
inline double largest_value(const BoundaryCondition& bc,
                            const std::map<std::string, LoadCurve>& curves, double t_end) {
  const double scale = bc.type == BcType::Traction
                           ? std::sqrt(bc.vector[0] * bc.vector[0] + bc.vector[1] * bc.vector[1] +
                                       bc.vector[2] * bc.vector[2])
                           : std::abs(bc.value);
  auto it = bc.curve.empty() ? curves.end() : curves.find(bc.curve);
  if (it == curves.end()) return scale;
  const LoadCurve& c = it->second;
  double m = std::max(std::abs(c.value(0.0)), std::abs(c.value(t_end)));
  for (const auto& [t, v] : c.points)
    if (t >= 0.0 && t <= t_end) m = std::max(m, std::abs(v));
  return scale * m;
}

}  // namespace biphasic::detail
