#include "biphasic/analytic/mandel.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numerics.hpp"

namespace biphasic::analytic {
namespace {

constexpr double kPi = std::numbers::pi;

void check_poisson(double nu) {
  if (!(nu > -1.0 && nu < 0.5)) {
    throw std::domain_error("Mandel: drained Poisson ratio ν = " + std::to_string(nu) +
                            " outside (−1, 1/2)");
  }
}

/// The m-th root (m ≥ 1) of sin α − r α cos α = 0, r = (1 − ν)/(1/2 − ν) > 1, in its
/// bracket. The first root uses sin α/α − r cos α, which has no zero at α = 0.
double mandel_root(double r, int m) {
  if (m == 1) {
    auto f = [r](double a) { return (a < 1e-8 ? 1.0 : std::sin(a) / a) - r * std::cos(a); };
    return detail::brent_root(f, 0.0, kPi / 2.0);
  }
  auto f = [r](double a) { return std::sin(a) - r * a * std::cos(a); };
  return detail::brent_root(f, (m - 1) * kPi, (m - 0.5) * kPi);
}

}  // namespace

std::vector<double> mandel_roots(double nu, int n) {
  check_poisson(nu);
  const double r = (1.0 - nu) / (0.5 - nu);
  std::vector<double> roots;
  for (int m = 1; m <= n; ++m) roots.push_back(mandel_root(r, m));
  return roots;
}

double mandel_pressure(double nu, double x, double T) {
  check_poisson(nu);
  if (!(std::abs(x) <= 1.0)) {
    throw std::domain_error("mandel_pressure: x/a = " + std::to_string(x) + " outside [−1, 1]");
  }
  if (!(T >= 0.0)) {
    throw std::domain_error("mandel_pressure: time factor T = " + std::to_string(T) + " < 0");
  }
  if (std::abs(x) == 1.0) return 0.0;
  if (T == 0.0) return 0.5;
  const double r = (1.0 - nu) / (0.5 - nu);
  double sum = 0.0;
  for (int m = 1;; ++m) {
    const double a = mandel_root(r, m);
    if (a * a * T > 50.0) break;
    const double s = std::sin(a), c = std::cos(a);
    sum += s / (a - s * c) * (std::cos(a * x) - c) * std::exp(-a * a * T);
  }
  return sum;
}

}  // namespace biphasic::analytic
