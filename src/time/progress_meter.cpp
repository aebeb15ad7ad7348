#include "biphasic/time/progress_meter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace biphasic {

ProgressMeter::ProgressMeter(double t0, double t_end, double interval)
    : t0_(t0), t_end_(t_end), interval_(interval), start_(Clock::now()), last_(start_) {}

bool ProgressMeter::due() const {
  return std::chrono::duration<double>(Clock::now() - last_).count() >= interval_;
}

void ProgressMeter::restart() { last_ = Clock::now(); }

std::string ProgressMeter::line(const ProgressSample& s) {
  last_ = Clock::now();
  const double elapsed = std::chrono::duration<double>(last_ - start_).count();
  const double span = t_end_ - t0_;
  const double done = span > 0.0 ? std::clamp((s.t - t0_) / span, 0.0, 1.0) : 1.0;
  // Wall time per simulated second so far, times the simulated time left: unknown until
  // some simulated time has passed.
  const double estimate = done > 0.0 ? elapsed * (1.0 - done) / done : -1.0;
  const std::string left = estimate < 0.0   ? std::string("unknown")
                           : estimate < 1.0 ? format_wall_time(estimate)
                                            : "~" + format_wall_time(estimate);
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "progress  t %9.4g s (%5.1f %%)  h %8.3g s  order %d  steps %ld  "
                "factorisations %ld  error-test failures %ld  wall left %s",
                s.t, 100.0 * done, s.h, s.order, s.steps, s.setups, s.error_test_failures,
                left.c_str());
  return buf;
}

std::string format_wall_time(double seconds) {
  char buf[64];
  if (!(seconds >= 1.0)) return "< 1 s";
  if (seconds < 60.0) {
    std::snprintf(buf, sizeof buf, "%.0f s", std::floor(seconds));
  } else if (seconds < 3600.0) {
    const long s = static_cast<long>(seconds);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  } else if (seconds < 1e9) {
    const long m = static_cast<long>(seconds / 60.0);
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", m / 60, m % 60);
  } else {
    return "more than 30 years";
  }
  return buf;
}

double progress_interval_from_environment() {
  const char* env = std::getenv("BIPHASIC_PROGRESS_INTERVAL");
  if (!env) return kDefaultProgressInterval;
  char* end = nullptr;
  const double v = std::strtod(env, &end);
  if (end == env || *end != '\0' || !std::isfinite(v) || v < 0.0)
    throw std::invalid_argument("BIPHASIC_PROGRESS_INTERVAL = '" + std::string(env) +
                                "': expected the seconds of wall time between progress lines, "
                                "a number >= 0");
  return v;
}

}  // namespace biphasic
