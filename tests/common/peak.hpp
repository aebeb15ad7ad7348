// Golden-section search for the maximum of a unimodal function, shared by the analytic and
// verification tests.
#pragma once

#include <cmath>
#include <utility>

namespace biphasic::analytic::testing {

/// (argmax, max) of f on [a, b], to about 1e−9 (b − a).
template <class F>
std::pair<double, double> maximise(F&& f, double a, double b) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 45; ++i) {
    if (fc > fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  const double x = 0.5 * (a + b);
  return {x, f(x)};
}

}  // namespace biphasic::analytic::testing
