// Terzaghi's one-dimensional consolidation under a step load q (Terzaghi 1923; Verruijt,
// "Theory and Problems of Poroelasticity", 2015). Layer of drainage length H, drained at
// ζ = 0, impermeable at ζ = H, incompressible constituents:
//   T = c t / H²,  c = k (λ + 2μ)                      (time factor; c in mm²/s)
//   p(ζ, t)/q = Σ_{m≥0} (2/M_m) sin(M_m ζ/H) exp(−M_m² T),  M_m = (2m+1)π/2
//   settlement = (q H / H_A) U(T),  U(T) = 1 − Σ_{m≥0} (2/M_m²) exp(−M_m² T)
// For T < 0.1 the equivalent short-time (image) series in erfc is used, which converges in a
// few terms however small T is.
#pragma once

namespace biphasic::analytic {

/// Pore pressure p/q [-] at depth ζ/H ∈ [0, 1] below the drained face and time factor T ≥ 0.
/// At T = 0 it is the undrained value 1 (0 on the drained face itself).
double terzaghi_pressure(double zeta_over_H, double T);

/// Degree of consolidation U(T) ∈ [0, 1) [-]: settlement / final settlement (q H / H_A).
double terzaghi_degree_of_consolidation(double T);

}  // namespace biphasic::analytic
