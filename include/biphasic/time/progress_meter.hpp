// Progress lines of an adaptive integrator (BDF, adaptive backward Euler) between outputs: a
// wall-clock throttle, and the line's text with an estimate of the wall time left.
#pragma once

#include <chrono>
#include <string>

namespace biphasic {

/// Wall time between progress lines when BIPHASIC_PROGRESS_INTERVAL is not set [s].
inline constexpr double kDefaultProgressInterval = 2.0;

/// Where an integrator stands, as a progress line shows it (counts over this run).
struct ProgressSample {
  double t = 0.0;                ///< time reached [s]
  double h = 0.0;                ///< last internal step [s]
  int order = 0;                 ///< BDF order of the last internal step
  long steps = 0;                ///< internal steps taken
  long setups = 0;               ///< Jacobian setups (each a Jacobian and its factorisation)
  long error_test_failures = 0;  ///< steps rejected by the local error test
};

/// Decides when a progress line is due and writes it. Simulated time runs from t0 to t_end;
/// the wall time left is extrapolated from the fraction of it done since the meter was made.
class ProgressMeter {
 public:
  /// `interval`: wall time between lines [s]; 0 makes a line due after every step.
  ProgressMeter(double t0, double t_end, double interval);
  /// True when `interval` of wall time has passed since the meter was made or last restarted.
  bool due() const;
  /// Starts the interval afresh (after an output line, which shows progress too).
  void restart();
  /// The progress line for `s`; restarts the interval.
  std::string line(const ProgressSample& s);

 private:
  using Clock = std::chrono::steady_clock;
  double t0_, t_end_, interval_;
  Clock::time_point start_, last_;
};

/// A wall-time span for a progress line: "< 1 s", "42 s", "3 min 07 s", "2 h 05 min".
std::string format_wall_time(double seconds);

/// The interval of progress lines [s]: $BIPHASIC_PROGRESS_INTERVAL if set, else
/// kDefaultProgressInterval. Throws std::invalid_argument, naming the variable and its value,
/// if it is set to anything but a finite number ≥ 0.
double progress_interval_from_environment();

}  // namespace biphasic
