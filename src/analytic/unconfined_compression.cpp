#include "biphasic/analytic/unconfined_compression.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numerics.hpp"

namespace biphasic::analytic {
namespace {

/// Exponentials below e^−50 are dropped.
constexpr double kMaxExponent = 50.0;
/// Roots kept by UnconfinedCompression: those below 400π.
constexpr double kAlphaMax = 400.0 * std::numbers::pi;

double checked_poisson(double nu) {
  if (!(nu > -1.0 && nu < 0.5)) {
    throw std::domain_error("unconfined compression: drained Poisson ratio ν = " +
                            std::to_string(nu) + " outside (−1, 1/2)");
  }
  return nu;
}

void check_time(double tau) {
  if (!(tau >= 0.0)) {
    throw std::domain_error("unconfined compression: time factor τ = " + std::to_string(tau) +
                            " < 0");
  }
}

void check_radius(double r) {
  if (!(r >= 0.0 && r <= 1.0)) {
    throw std::domain_error("unconfined compression: r/a = " + std::to_string(r) +
                            " outside [0, 1]");
  }
}

/// Roots in (from, alpha_max], at most n. f ≈ (1/2 − β) α < 0 near 0 since β > 2/3; one root
/// lies between each zero of J₁ and the next zero of J₀, so the roots are more than ~π/2 apart
/// and steps of 0.5 cannot skip a pair.
std::vector<double> find_roots(double nu, double from, int n, double alpha_max) {
  const double beta = (1.0 - nu) / (1.0 - 2.0 * nu);
  auto f = [beta](double a) {
    return std::cyl_bessel_j(1.0, a) - beta * a * std::cyl_bessel_j(0.0, a);
  };
  return detail::scan_roots(f, from, 0.5, n, alpha_max);
}

}  // namespace

/// A step response S(τ) = S_∞ + Σ a_n e^{−α_n² τ}: its limit and coefficients a_n.
struct UnconfinedCompression::Series {
  double nu;
  double limit;   // S_∞
  double r = -1;  // r/a for the pressure, < 0 for the force
  double coefficient(double alpha) const {
    const double d = (1.0 - nu) * (1.0 - nu) * alpha * alpha - (1.0 - 2.0 * nu);
    if (r < 0.0) return (1.0 - nu) * (1.0 - 2.0 * nu) / ((1.0 + nu) * d);
    const double j0 = std::cyl_bessel_j(0.0, alpha);
    return 2.0 * (1.0 - nu) * (1.0 - 2.0 * nu) * (std::cyl_bessel_j(0.0, alpha * r) - j0) /
           (j0 * d);
  }
};

std::vector<double> unconfined_roots(double nu, int n) {
  return find_roots(checked_poisson(nu), 1e-3, n, std::numeric_limits<double>::infinity());
}

UnconfinedCompression::UnconfinedCompression(double nu)
    : nu_(checked_poisson(nu)),
      roots_(find_roots(nu, 1e-3, std::numeric_limits<int>::max(), kAlphaMax)) {}

double UnconfinedCompression::step(const Series& s, double tau) const {
  const double alpha_max = std::sqrt(kMaxExponent / tau);
  double sum = s.limit;
  for (double a : roots_) {
    if (a > alpha_max) return sum;
    sum += s.coefficient(a) * std::exp(-a * a * tau);
  }
  // Very early times: the roots beyond the stored ones.
  for (double a :
       find_roots(nu_, roots_.back() + 0.25, std::numeric_limits<int>::max(), alpha_max)) {
    sum += s.coefficient(a) * std::exp(-a * a * tau);
  }
  return sum;
}

double UnconfinedCompression::ramp(const Series& s, double tau, double tau0) const {
  if (!(tau0 > 0.0)) {
    throw std::domain_error(
        "unconfined compression: ramp time factor τ₀ = " + std::to_string(tau0) + " must be > 0");
  }
  double sum = 0.0;
  if (tau <= tau0) {
    for (double a : roots_) sum += s.coefficient(a) * -std::expm1(-a * a * tau) / (a * a);
    return (s.limit * tau + sum) / tau0;
  }
  const double since = tau - tau0;
  const double alpha_max = std::sqrt(kMaxExponent / since);
  for (double a : roots_) {
    if (a > alpha_max) break;
    // e^{−α²(τ−τ₀)} − e^{−α²τ} without cancellation for short ramps
    sum += s.coefficient(a) * std::exp(-a * a * since) * -std::expm1(-a * a * tau0) / (a * a);
  }
  return s.limit + sum / tau0;
}

double UnconfinedCompression::force(double tau) const {
  check_time(tau);
  if (tau == 0.0) return 3.0 / (2.0 * (1.0 + nu_));  // undrained: 3μ/E
  return step({nu_, 1.0}, tau);
}

double UnconfinedCompression::pressure(double r, double tau) const {
  check_radius(r);
  check_time(tau);
  if (r == 1.0) return 0.0;
  if (tau == 0.0) return 1.0;
  return step({nu_, 0.0, r}, tau);
}

double UnconfinedCompression::ramp_force(double tau, double tau0) const {
  check_time(tau);
  return ramp({nu_, 1.0}, tau, tau0);
}

double UnconfinedCompression::ramp_pressure(double r, double tau, double tau0) const {
  check_radius(r);
  check_time(tau);
  if (r == 1.0) return 0.0;
  return ramp({nu_, 0.0, r}, tau, tau0);
}

}  // namespace biphasic::analytic
