#include "biphasic/analytic/terzaghi.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numerics.hpp"

namespace biphasic::analytic {
namespace {

/// Below this time factor the erfc (image) series is used, above it the Fourier series. At
/// T = 0.1 both need only a handful of terms for full double precision.
constexpr double kShortTime = 0.1;

/// The Fourier series stops once M² T exceeds this (the next term is below 1e−21).
constexpr double kMaxExponent = 50.0;

void check_arguments(double x, double T) {
  if (!(x >= 0.0 && x <= 1.0)) {
    throw std::domain_error("terzaghi_pressure: ζ/H = " + std::to_string(x) + " outside [0, 1]");
  }
  if (!(T >= 0.0)) {
    throw std::domain_error("terzaghi: time factor T = " + std::to_string(T) + " < 0");
  }
}

}  // namespace

double terzaghi_pressure(double x, double T) {
  check_arguments(x, T);
  if (x == 0.0) return 0.0;
  if (T == 0.0) return 1.0;
  if (T < kShortTime) {
    // Images of the drained face (sign −) and of the impermeable face (sign +):
    //   p/q = 1 − Σ_{n≥0} (−1)ⁿ [erfc((2n + x)/s) + erfc((2n + 2 − x)/s)],  s = 2√T.
    const double s = 2.0 * std::sqrt(T);
    double sum = 0.0, sign = 1.0;
    for (int n = 0;; ++n, sign = -sign) {
      const double term = std::erfc((2 * n + x) / s) + std::erfc((2 * n + 2 - x) / s);
      sum += sign * term;
      if (term < 1e-18) break;
    }
    return 1.0 - sum;
  }
  double sum = 0.0;
  for (int m = 0;; ++m) {
    const double M = (2 * m + 1) * std::numbers::pi / 2.0;
    if (M * M * T > kMaxExponent) break;
    sum += 2.0 / M * std::sin(M * x) * std::exp(-M * M * T);
  }
  return sum;
}

double terzaghi_degree_of_consolidation(double T) {
  check_arguments(0.0, T);
  if (T == 0.0) return 0.0;
  if (T < kShortTime) {
    // U = 2√(T/π) + 4√T Σ_{n≥1} (−1)ⁿ i erfc(n/√T)   (the same images integrated over ζ).
    const double r = std::sqrt(T);
    double sum = 0.0, sign = -1.0;
    for (int n = 1;; ++n, sign = -sign) {
      const double term = detail::ierfc(n / r);
      sum += sign * term;
      if (term < 1e-18) break;
    }
    return 2.0 * r / std::sqrt(std::numbers::pi) + 4.0 * r * sum;
  }
  double sum = 0.0;
  for (int m = 0;; ++m) {
    const double M = (2 * m + 1) * std::numbers::pi / 2.0;
    if (M * M * T > kMaxExponent) break;
    sum += 2.0 / (M * M) * std::exp(-M * M * T);
  }
  return 1.0 - sum;
}

}  // namespace biphasic::analytic
