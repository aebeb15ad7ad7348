#include "biphasic/analytic/cryer.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "numerics.hpp"

namespace biphasic::analytic {
namespace {

double cryer_eta(double nu) {
  if (!(nu > -1.0 && nu < 0.5)) {
    throw std::domain_error("Cryer: drained Poisson ratio ν = " + std::to_string(nu) +
                            " outside (−1, 1/2)");
  }
  return (1.0 - nu) / (2.0 * (1.0 - 2.0 * nu));
}

/// Roots of (1 − η ξ²) sin ξ − ξ cos ξ (no poles; ≈ (1/3 − η) ξ³ < 0 near 0 since η > 1/3),
/// scanned in steps of 0.05 (the roots are about π apart).
std::vector<double> roots_for_eta(double eta, int n, double x_max) {
  auto f = [eta](double x) { return (1.0 - eta * x * x) * std::sin(x) - x * std::cos(x); };
  return detail::scan_roots(f, 1e-3, 0.05, n, x_max);
}

}  // namespace

std::vector<double> cryer_roots(double nu, int n) {
  return roots_for_eta(cryer_eta(nu), n, std::numeric_limits<double>::infinity());
}

double cryer_pressure(double nu, double rho, double T) {
  const double eta = cryer_eta(nu);
  if (!(rho >= 0.0 && rho <= 1.0)) {
    throw std::domain_error("cryer_pressure: r/R = " + std::to_string(rho) + " outside [0, 1]");
  }
  if (!(T >= 0.0)) {
    throw std::domain_error("cryer_pressure: time factor T = " + std::to_string(T) + " < 0");
  }
  if (rho == 1.0) return 0.0;
  if (T == 0.0) return 1.0;
  // All roots with ξ² T ≤ 50 (the rest contribute below e^−50).
  double sum = 0.0;
  for (double xi : roots_for_eta(eta, std::numeric_limits<int>::max(), std::sqrt(50.0 / T))) {
    const double s = std::sin(xi), c = std::cos(xi);
    const double shape = rho > 0.0 ? std::sin(xi * rho) / rho : xi;
    sum +=
        2.0 * eta * (s - shape) / (eta * xi * c + (2.0 * eta - 1.0) * s) * std::exp(-xi * xi * T);
  }
  return sum;
}

}  // namespace biphasic::analytic
