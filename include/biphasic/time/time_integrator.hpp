// What every time integrator reports and how it hands results to observers.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace biphasic {

/// One accepted step, as printed on the terminal and passed to observers.
struct StepInfo {
  int step = 0;     ///< 1-based
  double t = 0.0;   ///< end of the step [s]
  double dt = 0.0;  ///< [s]
  int newton_iterations = 0;
  int setups = 0;           ///< Jacobian evaluations + factorisations in this step
  double residual_u = 0.0;  ///< ‖R_u‖_∞ over free momentum rows at the solution [N]
  double residual_p = 0.0;  ///< ‖R_p‖_∞ over free mass rows [mm³/s]
};

/// Counters accumulated over a run.
struct IntegratorStats {
  long steps = 0;
  long newton_iterations = 0;
  long nonlinear_failures = 0;  ///< failed Newton solves that were retried
  long jacobian_evaluations = 0;
  long residual_evaluations = 0;
};

/// Called after every accepted step with the solution y at StepInfo::t.
using StepObserver = std::function<void(const StepInfo&, const std::vector<double>& y)>;

/// A step that could not be completed: names the step, the time and the reason.
struct StepFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace biphasic
