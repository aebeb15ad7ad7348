// Mandel's problem (Mandel 1953, Géotechnique 3:287–299; Abousleiman et al. 1996,
// Géotechnique 46:187–195): plane-strain slab |x| ≤ a between rigid, frictionless, impermeable
// platens loaded by a force F (per unit length) at t = 0, lateral faces x = ±a drained.
// Incompressible constituents (Biot coefficient 1, undrained Poisson ratio 1/2):
//   σ₀ = F/a,  T = c t / a²,  c = k (λ + 2μ)
//   tan α_n = ((1 − ν)/(1/2 − ν)) α_n
//   p/σ₀ = Σ_n sin α_n / (α_n − sin α_n cos α_n) (cos(α_n x/a) − cos α_n) exp(−α_n² T)
// p(x, 0⁺) = σ₀/2; the centre pressure first rises above it (Mandel–Cryer effect).
#pragma once

#include <vector>

namespace biphasic::analytic {

/// The first n positive roots of tan α = ((1 − ν)/(1/2 − ν)) α [-], increasing:
/// α₁ ∈ (0, π/2) and α_m ∈ ((m − 1)π, (m − 1/2)π) for m ≥ 2. Drained ν ∈ (−1, 1/2).
std::vector<double> mandel_roots(double nu, int n);

/// Pore pressure p/σ₀ [-] at x/a ∈ [−1, 1] and T = c t/a² ≥ 0 (σ₀/2 at T = 0 inside the slab).
/// Sums the series until α_n² T > 50, so very small T costs many roots.
double mandel_pressure(double nu, double x_over_a, double T);

}  // namespace biphasic::analytic
