// Unconfined compression of a cylinder (radius a) between rigid, impermeable, frictionless
// platens, lateral face drained (Armstrong, Lai & Mow 1984, J. Biomech. Eng. 106:165–173),
// linear biphasic theory with incompressible constituents:
//   τ = c t / a²,  c = k (λ + 2μ),  E, ν drained Young's modulus and Poisson ratio
//   J₁(α_n) − ((1 − ν)/(1 − 2ν)) α_n J₀(α_n) = 0
// Step axial strain ε₀ (compressive) at t = 0:
//   F/(π a² ε₀ E) = 1 + Σ_n (1 − ν)(1 − 2ν) / ((1 + ν)[(1 − ν)² α_n² − (1 − 2ν)]) e^{−α_n² τ}
//   p(r, τ)/(μ ε₀) = Σ_n 2(1 − ν)(1 − 2ν) (J₀(α_n r/a) − J₀(α_n))
//                        / (J₀(α_n) [(1 − ν)² α_n² − (1 − 2ν)]) e^{−α_n² τ}
// The pressure series is derived here from the same solution by Laplace transform: H_A e − p
// is uniform in r, e = div u diffuses with c, and σ_rr(a) = 0 gives H_A e(a) − μ ē = −μ ε₀
// (ē the mean over the section); the residues at q = iα_n give the series. p(r, 0⁺) = μ ε₀,
// F(0⁺) = 3μ ε₀ π a², F(∞) = E ε₀ π a².
// Ramp ε(t) = ε₀ min(t/t₀, 1): Duhamel's integral of the step response, term by term,
//   R(τ) = (1/τ₀) [S_∞ τ + Σ a_n (1 − e^{−α_n² τ})/α_n²]            (τ ≤ τ₀)
//   R(τ) = S_∞ + (1/τ₀) Σ a_n (e^{−α_n² (τ−τ₀)} − e^{−α_n² τ})/α_n²   (τ ≥ τ₀)
// for a step response S(τ) = S_∞ + Σ a_n e^{−α_n² τ}; values are per final strain ε₀.
#pragma once

#include <vector>

namespace biphasic::analytic {

/// The first n positive roots of J₁(α) − ((1 − ν)/(1 − 2ν)) α J₀(α) [-], increasing;
/// drained ν ∈ (−1, 1/2). One lies in each interval between a zero of J₁ and the next zero of J₀.
std::vector<double> unconfined_roots(double nu, int n);

/// The solution for one Poisson ratio, with its roots computed once (they cost Bessel function
/// evaluations). Values are normalised: forces by π a² ε₀ E, pressures by μ ε₀; times are
/// τ = c t/a² ≥ 0; radii r/a ∈ [0, 1].
class UnconfinedCompression {
 public:
  /// Keeps the roots below 400π (about 400): enough for the ramp (its series converges like
  /// N⁻³, leaving ~1e−10) and for step responses at τ ≥ 50/(400π)² ≈ 3e−5; earlier step values
  /// compute the further roots they need on each call.
  explicit UnconfinedCompression(double nu);

  double nu() const { return nu_; }
  const std::vector<double>& roots() const { return roots_; }

  /// Step strain: F/(π a² ε₀ E) (3/(2(1 + ν)) at τ = 0, 1 as τ → ∞).
  double force(double tau) const;
  /// Step strain: p/(μ ε₀) (1 at τ = 0 inside, 0 at r = a).
  double pressure(double r_over_a, double tau) const;
  /// Ramp to ε₀ over τ₀ = c t₀/a² > 0, then held: F/(π a² ε₀ E).
  double ramp_force(double tau, double tau0) const;
  /// Ramp to ε₀ over τ₀ > 0, then held: p/(μ ε₀).
  double ramp_pressure(double r_over_a, double tau, double tau0) const;

 private:
  struct Series;
  double step(const Series& s, double tau) const;
  double ramp(const Series& s, double tau, double tau0) const;

  double nu_;
  std::vector<double> roots_;
};

}  // namespace biphasic::analytic
