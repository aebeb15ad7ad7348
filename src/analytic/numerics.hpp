// Private helpers of the analytic solutions: a bracketed scalar root (Brent), the roots of a
// function found by scanning for sign changes, and the iterated complementary error function.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace biphasic::analytic::detail {

/// Root of f in [a, b] with f(a) f(b) ≤ 0 (Brent's method: inverse quadratic interpolation,
/// secant and bisection), to the last bits of double precision.
template <class F>
double brent_root(F&& f, double a, double b) {
  double fa = f(a), fb = f(b);
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  if ((fa > 0.0) == (fb > 0.0)) {
    throw std::invalid_argument("brent_root: [" + std::to_string(a) + ", " + std::to_string(b) +
                                "] does not bracket a root");
  }
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 0; iter < 200; ++iter) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * 2.2e-16 * std::abs(b) + 1e-300;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double r = fb / fc, t = fa / fc;
        p = s * (2.0 * m * t * (t - r) - (b - a) * (r - 1.0));
        q = (t - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

/// The roots of f on (x0, x_max], at most n of them, increasing: f is stepped with `step`
/// (smaller than half the spacing of the roots) and each sign change refined by brent_root.
template <class F>
std::vector<double> scan_roots(F&& f, double x0, double step, int n,
                               double x_max = std::numeric_limits<double>::infinity()) {
  std::vector<double> roots;
  double a = x0, fa = f(a);
  while (static_cast<int>(roots.size()) < n && a < x_max) {
    const double b = a + step, fb = f(b);
    if (fb == 0.0 || (fa > 0.0) != (fb > 0.0)) {
      roots.push_back(brent_root(f, a, b));
      if (fb == 0.0) {  // step past the root so that it is not counted again
        a = b + 0.5 * step;
        fa = f(a);
        continue;
      }
    }
    a = b;
    fa = fb;
  }
  while (!roots.empty() && roots.back() > x_max) roots.pop_back();
  return roots;
}

/// i erfc(x) = ∫ₓ^∞ erfc(s) ds = e^{−x²}/√π − x erfc(x).
inline double ierfc(double x) {
  return std::exp(-x * x) / std::sqrt(std::numbers::pi) - x * std::erfc(x);
}

/// Nodes and weights of the n-point Gauss–Legendre rule on [−1, 1] (Newton on the Legendre
/// recurrence from Chebyshev guesses; exact for polynomials of degree 2n − 1).
inline std::pair<std::vector<double>, std::vector<double>> gauss_legendre(int n) {
  std::vector<double> x(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = z;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);  // P_n'(z)
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[static_cast<std::size_t>(i)] = z;
    w[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
  return {x, w};
}

}  // namespace biphasic::analytic::detail
