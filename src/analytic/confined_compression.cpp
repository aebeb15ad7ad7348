#include "biphasic/analytic/confined_compression.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "numerics.hpp"

namespace biphasic::analytic {
namespace {

constexpr double kPi = std::numbers::pi;

void check_column(const ConfinedRamp& c) {
  if (!(c.mu > 0.0 && c.lambda + 2.0 * c.mu > 0.0)) {
    throw std::domain_error("confined ramp: moduli μ = " + std::to_string(c.mu) +
                            ", λ = " + std::to_string(c.lambda) + " not positive definite");
  }
  if (!(c.permeability > 0.0 && c.thickness > 0.0 && c.ramp_time > 0.0)) {
    throw std::domain_error("confined ramp: k = " + std::to_string(c.permeability) +
                            ", h = " + std::to_string(c.thickness) +
                            ", t₀ = " + std::to_string(c.ramp_time) + " must be > 0");
  }
  if (!(c.permeability_kappa >= 0.0 && c.permeability_M >= 0.0)) {
    throw std::domain_error(
        "confined ramp: Holmes-Mow κ = " + std::to_string(c.permeability_kappa) +
        ", M = " + std::to_string(c.permeability_M) + " must be >= 0");
  }
  if ((c.permeability_kappa != 0.0 || c.permeability_M != 0.0) &&
      !(c.solid_fraction > 0.0 && c.solid_fraction < 1.0)) {
    throw std::domain_error("confined ramp: Holmes-Mow φ₀ = " + std::to_string(c.solid_fraction) +
                            " must lie in (0, 1)");
  }
}

void check_layers(const ConfinedRamp& c) {
  double sum = 0.0;
  for (std::size_t i = 0; i < c.layers.size(); ++i) {
    const ConfinedRamp::Layer& l = c.layers[i];
    if (!(l.fraction > 0.0 && l.permeability > 0.0 && std::isfinite(l.permeability))) {
      throw std::domain_error("confined ramp: layer " + std::to_string(i) + " has fraction " +
                              std::to_string(l.fraction) +
                              " and k0 = " + std::to_string(l.permeability) + "; both must be > 0");
    }
    sum += l.fraction;
  }
  if (!c.layers.empty() && !(std::abs(sum - 1.0) <= 1e-12)) {
    throw std::domain_error("confined ramp: layer fractions sum to " + std::to_string(sum) +
                            ", not 1");
  }
}

bool constant_permeability(const ConfinedRamp& c) {
  return c.permeability_kappa == 0.0 && c.permeability_M == 0.0;
}

/// F(T) = T + 1/3 − (2/π²) Σ_{n≥1} e^{−n²π² T}/n², the ramp response per (H_A V₀ h/c).
double ramp_response(double T) {
  if (T <= 0.0) return 0.0;
  if (T < 0.1) {
    // Poisson summation of F'(T) = 1 + 2 Σ e^{−n²π²T} = (πT)^{−1/2} Σ_{m∈ℤ} e^{−m²/T}, integrated.
    const double r = std::sqrt(T);
    double sum = 0.0;
    for (int m = 1;; ++m) {
      const double term = detail::ierfc(m / r);
      sum += term;
      if (term < 1e-18) break;
    }
    return 2.0 * r / std::sqrt(kPi) + 4.0 * r * sum;
  }
  double sum = 0.0;
  for (int n = 1; n * n * kPi * kPi * T < 50.0; ++n) {
    sum += std::exp(-n * n * kPi * kPi * T) / (n * n);
  }
  return T + 1.0 / 3.0 - 2.0 / (kPi * kPi) * sum;
}

// ---- finite strain ---------------------------------------------------------------------------

/// Neo-Hookean column in uniaxial strain: P_eff, the Kirchhoff potential Φ and Φ' = D.
class Column {
 public:
  explicit Column(const ConfinedRamp& c) : c_(c), constant_(constant_permeability(c)) {
    if (!constant_) std::tie(nodes_, weights_) = detail::gauss_legendre(16);
  }
  double stress(double s) const { return neo_hookean_uniaxial_stress(c_.mu, c_.lambda, s); }
  /// Φ(s) = ∫₁ˢ k(r) P_eff'(r)/r dr; for a constant k
  /// Φ(s) = k [μ (ln s − 1/(2s²) + 1/2) + λ ((2 ln s − 1)/(4s²) + 1/4)].
  double potential(double s) const {
    if (constant_) {
      const double l = std::log(s), is2 = 1.0 / (s * s);
      return c_.permeability *
             (c_.mu * (l - 0.5 * is2 + 0.5) + c_.lambda * (0.25 * (2.0 * l - 1.0) * is2 + 0.25));
    }
    const double half = 0.5 * (s - 1.0), mid = 0.5 * (s + 1.0);
    double sum = 0.0;
    for (std::size_t q = 0; q < nodes_.size(); ++q)
      sum += weights_[q] * diffusivity(mid + half * nodes_[q]);
    return half * sum;
  }
  /// D(s) = Φ'(s) = k(s) P_eff'(s)/s = k(s) [μ (1/s + 1/s³) + λ (1 − ln s)/s³].
  double diffusivity(double s) const {
    const double is3 = 1.0 / (s * s * s);
    return confined_permeability(c_, s) *
           (c_.mu * (1.0 / s + is3) + c_.lambda * (1.0 - std::log(s)) * is3);
  }

 private:
  ConfinedRamp c_;
  bool constant_;
  std::vector<double> nodes_, weights_;
};

/// Solves a tridiagonal system (sub-diagonal a, diagonal b, super-diagonal c) in place of d.
void solve_tridiagonal(std::vector<double>& a, std::vector<double>& b, std::vector<double>& c,
                       std::vector<double>& d) {
  const std::size_t n = b.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double w = a[i] / b[i - 1];
    b[i] -= w * c[i - 1];
    d[i] -= w * d[i - 1];
  }
  d[n - 1] /= b[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) d[i] = (d[i] - c[i] * d[i + 1]) / b[i];
}

/// P1 Galerkin discretisation of ∂λ/∂t = ∂²Φ(λ)/∂Z² on Z ∈ [0, h] with consistent mass,
/// no flux at Z = 0 and the flux ∂Φ/∂Z = q at Z = h, stepped with BDF2.
class ColumnSolver {
 public:
  ColumnSolver(const ConfinedRamp& c, int cells)
      : column_(c), n_(static_cast<std::size_t>(cells) + 1) {
    // Distance from the top d(η) = h (e^{gη} − 1)/(e^g − 1), η uniform: cells from
    // g/(e^g − 1) h/N ≈ 0.07 h/N at the top to 4 h/N at the bottom.
    constexpr double g = 4.0;
    std::vector<double> Z(n_);
    for (std::size_t j = 0; j < n_; ++j) {
      const double eta = static_cast<double>(n_ - 1 - j) / static_cast<double>(cells);
      Z[j] = c.thickness * (1.0 - std::expm1(g * eta) / std::expm1(g));
    }
    Z[0] = 0.0;
    Z[n_ - 1] = c.thickness;
    // Layers: the inner node nearest each interface moves onto it; each element then takes the
    // factor k₀(layer)/k of the layer holding its midpoint.
    std::vector<double> interfaces;
    double below = 0.0;
    for (std::size_t i = 0; i + 1 < c.layers.size(); ++i) {
      below += c.layers[i].fraction * c.thickness;
      interfaces.push_back(below);
      std::size_t nearest = 1;
      for (std::size_t j = 1; j + 1 < n_; ++j)
        if (std::abs(Z[j] - below) < std::abs(Z[nearest] - below)) nearest = j;
      Z[nearest] = below;
    }
    for (std::size_t j = 1; j < n_; ++j) {
      if (!(Z[j] > Z[j - 1])) {
        throw std::invalid_argument("confined ramp reference: " + std::to_string(cells) +
                                    " cells cannot resolve the layers");
      }
    }
    len_.resize(n_ - 1);
    factor_.assign(n_ - 1, 1.0);
    for (std::size_t e = 0; e + 1 < n_; ++e) {
      len_[e] = Z[e + 1] - Z[e];
      if (c.layers.empty()) continue;
      const double mid = 0.5 * (Z[e] + Z[e + 1]);
      std::size_t layer = 0;
      while (layer < interfaces.size() && mid > interfaces[layer]) ++layer;
      factor_[e] = c.layers[layer].permeability / c.permeability;
    }
    lam_.assign(n_, 1.0);
    prev_ = lam_;
    pot_.resize(n_);
    dif_.resize(n_);
  }

  double top_stress() const { return column_.stress(lam_.back()); }

  /// One step of length dt with outflow q: backward Euler if `first`, else BDF2 with the
  /// previous step dt_prev.
  void step(double dt, double dt_prev, bool first, double q) {
    // λ̇ ≈ a0 λⁿ⁺¹ + a1 λⁿ + a2 λⁿ⁻¹ (variable-step BDF2, ω = dt/dt_prev).
    double a0 = 1.0 / dt, a1 = -1.0 / dt, a2 = 0.0;
    if (!first) {
      const double w = dt / dt_prev;
      a0 = (1.0 + 2.0 * w) / ((1.0 + w) * dt);
      a1 = -(1.0 + w) / dt;
      a2 = w * w / ((1.0 + w) * dt);
    }
    std::vector<double> hist(n_);
    for (std::size_t j = 0; j < n_; ++j) hist[j] = a1 * lam_[j] + a2 * prev_[j];
    const std::vector<double> mhist = mass_times(hist);
    // Predictor: linear extrapolation (the current state on the first step).
    std::vector<double> x = lam_;
    if (!first) {
      const double w = dt / dt_prev;
      for (std::size_t j = 0; j < n_; ++j) x[j] = lam_[j] + w * (lam_[j] - prev_[j]);
    }
    std::vector<double> lo(n_), di(n_), up(n_), r(n_);
    double last_change = std::numeric_limits<double>::infinity();
    for (int it = 0;; ++it) {
      if (it == 50) throw std::runtime_error("confined ramp reference: Newton did not converge");
      for (std::size_t j = 0; j < n_; ++j) {
        if (!(x[j] > 0.0)) {
          throw std::domain_error("confined ramp reference: stretch λ_z = " + std::to_string(x[j]) +
                                  " ≤ 0");
        }
        pot_[j] = column_.potential(x[j]);
        dif_[j] = column_.diffusivity(x[j]);
      }
      const std::vector<double> mx = mass_times(x);
      for (std::size_t j = 0; j < n_; ++j) {
        r[j] = a0 * mx[j] + mhist[j];
        lo[j] = up[j] = 0.0;
        di[j] = 0.0;
      }
      for (std::size_t e = 0; e + 1 < n_; ++e) {
        const double L = len_[e];
        const double f = factor_[e];  // the layer's k₀/k scales the element's potential
        const double flux = f * (pot_[e + 1] - pot_[e]) / L;
        r[e] -= flux;
        r[e + 1] += flux;
        di[e] += a0 * L / 3.0 + f * dif_[e] / L;
        di[e + 1] += a0 * L / 3.0 + f * dif_[e + 1] / L;
        up[e] += a0 * L / 6.0 - f * dif_[e + 1] / L;
        lo[e + 1] += a0 * L / 6.0 - f * dif_[e] / L;
      }
      r[n_ - 1] -= q;
      for (double& v : r) v = -v;
      solve_tridiagonal(lo, di, up, r);
      double change = 0.0;
      for (std::size_t j = 0; j < n_; ++j) {
        x[j] += r[j];
        change = std::max(change, std::abs(r[j]));
      }
      // Converged at 1e−14, or at the round-off floor once the updates stop shrinking.
      if (change < 1e-14 || (change < 1e-11 && change > 0.5 * last_change)) break;
      last_change = change;
    }
    prev_ = std::move(lam_);
    lam_ = std::move(x);
  }

 private:
  std::vector<double> mass_times(const std::vector<double>& v) const {
    std::vector<double> out(n_, 0.0);
    for (std::size_t e = 0; e + 1 < n_; ++e) {
      const double L = len_[e];
      out[e] += L / 3.0 * v[e] + L / 6.0 * v[e + 1];
      out[e + 1] += L / 6.0 * v[e] + L / 3.0 * v[e + 1];
    }
    return out;
  }

  Column column_;
  std::size_t n_;
  std::vector<double> len_, factor_, lam_, prev_, pot_, dif_;
};

/// Time grid of one phase: t_i = start + length (i/M)⁴, graded toward its start where the
/// loading rate jumps and σ behaves like √(t − start) (so σ is smooth in i/M; a grading of 3
/// left 4× larger errors just after t₀).
constexpr double kTimeGrading = 4.0;

/// Cubic Lagrange interpolation of values on the uniform grid s_i = i/M at s ∈ [0, 1].
double interpolate(const std::vector<double>& v, double s) {
  const int M = static_cast<int>(v.size()) - 1;
  int i0 = static_cast<int>(std::floor(s * M)) - 1;
  i0 = std::clamp(i0, 0, std::max(M - 3, 0));
  const int np = std::min(4, M + 1);
  double sum = 0.0;
  for (int a = 0; a < np; ++a) {
    double w = 1.0;
    for (int b = 0; b < np; ++b) {
      if (b != a) w *= (s * M - (i0 + b)) / static_cast<double>(a - b);
    }
    sum += w * v[static_cast<std::size_t>(i0 + a)];
  }
  return sum;
}

std::vector<double> run(const ConfinedRamp& c, std::span<const double> times, int cells,
                        int steps) {
  const double t0 = c.ramp_time;
  double t_end = t0;
  for (double t : times) {
    if (!(t >= 0.0)) {
      throw std::domain_error("confined ramp reference: time " + std::to_string(t) + " < 0");
    }
    t_end = std::max(t_end, t);
  }
  ColumnSolver solver(c, cells);
  const double q = -c.strain * c.thickness / t0;
  // σ on the grid of each phase: [0, t₀] and [t₀, t_end].
  std::vector<double> ramp(static_cast<std::size_t>(steps) + 1, 0.0);
  std::vector<double> hold(static_cast<std::size_t>(steps) + 1, 0.0);
  const auto grid = [steps](double length, int i) {
    return length * std::pow(static_cast<double>(i) / steps, kTimeGrading);
  };
  for (int phase = 0; phase < 2; ++phase) {
    const double length = phase == 0 ? t0 : t_end - t0;
    std::vector<double>& out = phase == 0 ? ramp : hold;
    out[0] = solver.top_stress();
    if (phase == 1 && !(length > 0.0)) break;
    double dt_prev = 0.0;
    for (int i = 1; i <= steps; ++i) {
      const double dt = grid(length, i) - grid(length, i - 1);
      solver.step(dt, dt_prev, i == 1, phase == 0 ? q : 0.0);
      dt_prev = dt;
      out[static_cast<std::size_t>(i)] = solver.top_stress();
    }
  }
  std::vector<double> sigma;
  sigma.reserve(times.size());
  for (double t : times) {
    if (t <= t0) {
      sigma.push_back(interpolate(ramp, std::pow(t / t0, 1.0 / kTimeGrading)));
    } else {
      sigma.push_back(interpolate(hold, std::pow((t - t0) / (t_end - t0), 1.0 / kTimeGrading)));
    }
  }
  return sigma;
}

}  // namespace

double confined_ramp_stress_linear(const ConfinedRamp& c, double t) {
  check_column(c);
  if (!c.layers.empty())
    throw std::invalid_argument("confined_ramp_stress_linear: layered columns are not supported");
  if (!(t >= 0.0)) {
    throw std::domain_error("confined_ramp_stress_linear: time " + std::to_string(t) + " < 0");
  }
  const double HA = c.lambda + 2.0 * c.mu;
  const double cv = HA * c.permeability;  // consolidation coefficient [mm²/s]
  const double h = c.thickness;
  const double V0 = c.strain * h / c.ramp_time;
  const double scale = -HA * V0 * h / cv;
  const double T = cv * t / (h * h);
  const double T0 = cv * c.ramp_time / (h * h);
  if (t <= c.ramp_time) return scale * ramp_response(T);
  return scale * (ramp_response(T) - ramp_response(T - T0));
}

double confined_permeability(const ConfinedRamp& c, double s) {
  if (constant_permeability(c)) return c.permeability;
  const double phi0 = c.solid_fraction;
  if (!(s > phi0)) {
    throw std::domain_error("confined ramp reference: stretch λ_z = " + std::to_string(s) +
                            " ≤ φ₀ = " + std::to_string(phi0) + " (the pores have closed)");
  }
  return c.permeability * std::pow((s - phi0) / (1.0 - phi0), c.permeability_kappa) *
         std::exp(0.5 * c.permeability_M * (s * s - 1.0));
}

double neo_hookean_uniaxial_stress(double mu, double lambda, double s) {
  if (!(s > 0.0)) {
    throw std::domain_error("neo_hookean_uniaxial_stress: stretch λ_z = " + std::to_string(s) +
                            " ≤ 0");
  }
  return mu * (s - 1.0 / s) + lambda * std::log(s) / s;
}

std::vector<double> confined_ramp_stress_neo_hookean(const ConfinedRamp& c,
                                                     std::span<const double> times,
                                                     const ConfinedReferenceResolution& res) {
  check_column(c);
  check_layers(c);
  if (res.cells < 2 || res.steps < 3) {
    throw std::invalid_argument("confined ramp reference: resolution of " +
                                std::to_string(res.cells) + " cells and " +
                                std::to_string(res.steps) + " steps too coarse");
  }
  std::vector<double> coarse = run(c, times, res.cells, res.steps);
  if (!res.richardson) return coarse;
  const std::vector<double> fine = run(c, times, 2 * res.cells, 2 * res.steps);
  for (std::size_t i = 0; i < coarse.size(); ++i) coarse[i] = (4.0 * fine[i] - coarse[i]) / 3.0;
  return coarse;
}

}  // namespace biphasic::analytic
