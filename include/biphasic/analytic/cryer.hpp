// Cryer's problem (Cryer 1963, Q. J. Mech. Appl. Math. 16:401–412): a sphere of radius R with
// a drained surface, loaded at t = 0 by a uniform total surface pressure P₀. Incompressible
// constituents (Biot coefficient 1, undrained Poisson ratio 1/2):
//   T = c t / R²,  c = k (λ + 2μ)                 (the same c as Terzaghi's and Mandel's)
//   η = (1 − ν)/(2(1 − 2ν)) = (λ + 2μ)/(4μ)
//   (1 − η ξ_n²) tan ξ_n = ξ_n
//   p(r, T)/P₀ = Σ_n 2η (sin ξ_n − sin(ξ_n r/R)/(r/R)) / (η ξ_n cos ξ_n + (2η − 1) sin ξ_n)
//                     · exp(−ξ_n² T)
// Derived here by Laplace transform: H_A e − p is uniform in r, e = div u diffuses with c, and
// the surface traction gives H_A e(R) − (4μ/3) ē = −P₀ (ē the mean over the sphere); the residues
// at q = iξ_n give the series. At r = 0 (sin(ξ r/R)/(r/R) → ξ) it is the centre-pressure series
// of Verruijt, "Theory and Problems of Poroelasticity" (2015, sec. 3.3),
//   p(0, T)/P₀ = Σ η_V (sin ξ_n − ξ_n) / ((η_V − 1) sin ξ_n + η_V ξ_n cos ξ_n / 2) e^{−ξ_n² T},
// written with η_V = 2η = (1 − ν)/(1 − 2ν) and roots (1 − η_V ξ²/2) tan ξ = ξ. p(r, 0⁺) = P₀.
#pragma once

#include <vector>

namespace biphasic::analytic {

/// The first n positive roots of (1 − η ξ²) tan ξ = ξ [-], increasing; drained ν ∈ (−1, 1/2).
std::vector<double> cryer_roots(double nu, int n);

/// Pore pressure p/P₀ [-] at r/R ∈ [0, 1] and T = c t/R² ≥ 0 (1 at T = 0 inside the sphere).
double cryer_pressure(double nu, double r_over_R, double T);

/// Centre pressure p(0, T)/P₀ [-].
inline double cryer_center_pressure(double nu, double T) { return cryer_pressure(nu, 0.0, T); }

}  // namespace biphasic::analytic
