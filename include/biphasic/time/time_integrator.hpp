// What every time integrator reports and how it hands results to observers.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/time/progress_meter.hpp"

namespace biphasic {

/// One output time (backward Euler: one interval of time.dt, in one step or several sub-steps
/// after cut-backs; BDF: the internal steps since the previous output), as printed on the
/// terminal and passed to observers.
struct StepInfo {
  int step = 0;               ///< 1-based
  double t = 0.0;             ///< end of the step [s]
  double dt = 0.0;            ///< the last (sub-)step [s]
  int newton_iterations = 0;  ///< over the sub-steps (backward Euler)
  int setups = 0;             ///< Jacobian evaluations (= factorisations) in this step
  int internal_steps = 0;     ///< BDF: internal steps since the previous output
  int order = 0;              ///< BDF: order of the last internal step
  double residual_u = 0.0;    ///< ‖R_u‖_∞ over free momentum rows at the solution [N]
  double residual_p = 0.0;    ///< ‖R_p‖_∞ over free mass rows [mm³/s]
  int sub_steps = 1;          ///< backward Euler: steps taken since the previous output
};

/// A backward-Euler step that failed and was retried with half the step.
struct Cutback {
  int step = 0;     ///< output step (1-based) being integrated
  double t = 0.0;   ///< start of the failed step [s]
  double dt = 0.0;  ///< the new, halved step [s]
  std::string reason;
};

/// Counters accumulated over a run (over restarts, for BDF). Residual and Jacobian evaluations
/// are counted by the problem itself (AssemblyStats).
struct IntegratorStats {
  long steps = 0;
  long newton_iterations = 0;
  long nonlinear_failures = 0;     ///< failed Newton solves (retried / step reduced)
  long error_test_failures = 0;    ///< BDF only
  long restarts = 0;               ///< BDF: re-initialisations at load-curve kinks
  std::vector<long> order_counts;  ///< BDF: steps taken at order 1..5 (index q − 1)
  std::vector<double> step_sizes;  ///< BDF: every accepted internal step [s]
  std::vector<Cutback> cutbacks;   ///< backward Euler: every step halved after a failure
  /// BDF: the consistent start at t₀ and at every restart, with ‖F(t, y, ẏ)‖∞ there.
  struct Start {
    double t = 0.0;
    double residual_u = 0.0;       ///< [N]
    double residual_p = 0.0;       ///< [mm³/s]
    bool pressure_solved = false;  ///< p was recomputed (GLS: p is algebraic)
  };
  std::vector<Start> starts;
};

/// Called at every output time t0 + k·time.dt (backward Euler: after the last sub-step of that
/// interval; BDF: by interpolation) with the solution y and its rate ẏ at StepInfo::t
/// (backward Euler: the last sub-step's difference quotient; BDF: IDA's interpolant).
using StepObserver = std::function<void(const StepInfo&, const std::vector<double>& y,
                                        const std::vector<double>& ydot)>;

/// A step that could not be completed: names the step, the time and the reason.
struct StepFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct LinearSolverStats;

/// IDA's first step when time.bdf.initial_step is 0 [s]: 1 % of the first output interval or
/// of the time to the first load-curve kink, whichever is shorter (docs/integrators.md).
inline double default_first_step(double output_interval, double time_to_first_stop) {
  return 1e-2 * std::min(output_interval, time_to_first_stop);
}

/// Largest number of output intervals t_end / time.dt a run may have (10⁷; the case file is
/// refused beyond it): more would not fit a step counter, and would take months to write.
inline constexpr long long kMaxOutputIntervals = 10'000'000;

/// A remainder shorter than this fraction of a step is merged into the step before it instead
/// of being taken as a step of its own: a sliver step (t_end given to 6 digits, 416.666667 s
/// with Δt = 1.6666… s, leaves 2e-7 Δt) has a mass residual that divides round-off by its
/// length and cannot converge.
inline constexpr double kSliverFraction = 1e-6;

/// Number of intervals of length dt in [0, t_end], the last one shortened (or lengthened by
/// less than kSliverFraction of an interval) to land on t_end: ⌈t_end / dt − kSliverFraction⌉,
/// at least 1. Computed in double and returned in 64 bits, saturated at the largest long long
/// (t_end / dt may be 1e316 or infinite).
inline long long interval_count(double t_end, double dt) {
  const double count = std::ceil(t_end / dt - kSliverFraction);
  if (!(count < 9.0e18)) return std::numeric_limits<long long>::max();
  return std::max(1LL, static_cast<long long>(count));
}

/// interval_count as an int for the integrators; throws std::invalid_argument naming time.dt
/// and time.t_end when the count exceeds kMaxOutputIntervals.
inline int checked_interval_count(double t_end, double dt) {
  const long long count = interval_count(t_end, dt);
  if (count > kMaxOutputIntervals) {
    std::ostringstream msg;
    msg << "time.t_end / time.dt = " << t_end << " s / " << dt << " s gives " << count
        << " steps, more than the " << kMaxOutputIntervals << " allowed";
    throw std::invalid_argument(msg.str());
  }
  return static_cast<int>(count);
}

/// What run_case drives: backward Euler or BDF over one SemidiscreteSystem.
class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  /// Integrates from t0 (y = a consistent initial state, overwritten with the final one) to
  /// the configured end time, calling `observer` at each output. Throws StepFailure.
  virtual void run(double t0, std::vector<double>& y, const StepObserver& observer) = 0;
  /// Number of observer calls run() will make (for progress lines).
  virtual int planned_outputs() const = 0;
  virtual const IntegratorStats& stats() const = 0;
  virtual const LinearSolverStats& linear_solver_stats() const = 0;
  /// What the integrator needs beyond (t, y) to continue from the current output time exactly
  /// as an uninterrupted run would; read by an observer for a checkpoint. Empty where nothing
  /// is carried over (BDF: IDA's history cannot be restored; docs/output_and_restart.md).
  virtual std::vector<double> resume_state() const { return {}; }
  /// Makes the next run(t0, …) continue from a checkpoint at t0 with the state resume_state()
  /// returned there. An empty state starts afresh at t0. Throws std::invalid_argument if the
  /// state does not fit this problem.
  virtual void set_resume_state(const std::vector<double>& /*state*/) {}
  /// Where the integrator's notes during a run go (one line each; e.g. cut-backs). None by
  /// default.
  void set_log(std::function<void(const std::string&)> log) { log_ = std::move(log); }
  /// Wall time between the progress lines an adaptive integrator (BDF) writes to the log while
  /// it steps between outputs [s]; 0: after every internal step. Backward Euler writes none.
  void set_progress_interval(double seconds) { progress_interval_ = seconds; }

 protected:
  void note(const std::string& line) const {
    if (log_) log_(line);
  }
  double progress_interval() const { return progress_interval_; }

 private:
  std::function<void(const std::string&)> log_;
  double progress_interval_ = kDefaultProgressInterval;  ///< [s]
};

}  // namespace biphasic
