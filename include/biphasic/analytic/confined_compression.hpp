// Ramp confined compression of a biphasic column (Mow, Kuei, Lai & Armstrong 1980, J. Biomech.
// Eng. 102:73–84): thickness h, bottom Z = 0 fixed and impermeable, top Z = h drained (p = 0)
// and displaced u_top = −V₀ t until t₀, then held; V₀ = ε₀ h/t₀. Stresses are the total platen
// stress σ [MPa], negative in compression.
//
// Linear theory, H_A = λ + 2μ, λ_n = H_A k n²π²/h²:
//   σ_ramp(t) = −(H_A V₀/h) [t + h²/(3 H_A k) − (2h²/(π² H_A k)) Σ_{n≥1} e^{−λ_n t}/n²]
//   σ(t) = σ_ramp(t) for t ≤ t₀,  σ_ramp(t) − σ_ramp(t − t₀) after.
//
// Finite strain: the Neo-Hookean solid Ψ = μ/2 (tr C − 3) − μ ln J + λ/2 (ln J)² in uniaxial
// strain (stretch λ_z = J) with constant spatial permeability k, in reference coordinates:
//   P_eff(λ_z) = μ (λ_z − 1/λ_z) + λ ln(λ_z)/λ_z      (nominal effective stress)
//   P_eff(λ_z) − p = σ(t)                              (equilibrium; σ uniform in Z)
//   ∂λ_z/∂t = ∂/∂Z ((k/λ_z) ∂p/∂Z)                     (J̇ + Div(k J C⁻¹ ∇₀p) = 0 in 1D)
//   ∫₀ʰ (λ_z − 1) dZ = u_top(t)
// Since ∂p/∂Z = ∂P_eff/∂Z, λ_z obeys ∂λ_z/∂t = ∂²Φ(λ_z)/∂Z² with the Kirchhoff potential
// Φ(s) = ∫₁ˢ k(r) P_eff'(r)/r dr, no flux at Z = 0 and, from the volume constraint, the outflow
// ∂Φ/∂Z = u̇_top at Z = h; then σ = P_eff(λ_z(h)) since p(h) = 0.
// The permeability may follow the Holmes–Mow law of J = λ_z (Holmes & Mow, J. Biomech. 23,
// 1990): k(s) = k₀ ((s − φ₀)/(1 − φ₀))^κ exp(M (s² − 1)/2); Φ is then integrated numerically
// (16-point Gauss–Legendre on [1, s]), in closed form for a constant k.
#pragma once

#include <span>
#include <vector>

namespace biphasic::analytic {

/// The column and its loading (defaults: FEBio's confined-compression verification case).
struct ConfinedRamp {
  double mu = 0.5;             ///< shear modulus μ [MPa]
  double lambda = 0.0;         ///< Lamé λ [MPa]
  double permeability = 1e-3;  ///< spatial permeability k [mm⁴/(N s)]
  double thickness = 1.0;      ///< h [mm]
  double strain = 0.1;         ///< final compressive strain ε₀ = V₀ t₀/h [-]
  double ramp_time = 100.0;    ///< t₀ [s]
  /// Holmes–Mow permeability: κ, M ≥ 0 and φ₀ ∈ (0, 1) (κ = M = 0: k = k₀ constant).
  double permeability_kappa = 0.0;
  double permeability_M = 0.0;
  double solid_fraction = 0.0;  ///< φ₀, used when κ or M is not zero
  /// Layers of different permeability, from the impermeable bottom (Z = 0) to the drained top:
  /// each a fraction of h (> 0, the fractions summing to 1 within 1e-12) and its k₀ [mm⁴/(N s)],
  /// which replaces `permeability` in that layer (κ, M and φ₀ are shared). Empty: one layer of
  /// k₀ = `permeability`. The solid is the same in every layer, so λ_z is continuous across an
  /// interface (so are the pore pressure and the effective stress). Only the finite-strain
  /// reference takes layers; the linear solution refuses them.
  struct Layer {
    double fraction = 1.0;
    double permeability = 1e-3;
  };
  std::vector<Layer> layers;
};

/// The column's permeability k(λ_z) [mm⁴/(N s)] (k₀ when κ = M = 0); throws if λ_z ≤ φ₀.
double confined_permeability(const ConfinedRamp& c, double stretch);

/// Linear theory (Mow et al. 1980): platen stress σ(t) [MPa] at time t ≥ 0 [s]. Throws
/// std::invalid_argument if `c.layers` is not empty. The constant
/// part of the series is summed in closed form; for c t < 0.1 h² (c = H_A k) the equivalent
/// short-time form σ_ramp = −(H_A V₀ h/c) [2√(T/π) + 4√T Σ_{m≥1} i erfc(m/√T)], T = c t/h², is
/// used.
double confined_ramp_stress_linear(const ConfinedRamp& c, double t);

/// Nominal effective stress of the Neo-Hookean solid in uniaxial strain [MPa]:
/// P_eff(λ_z) = μ (λ_z − 1/λ_z) + λ ln(λ_z)/λ_z; at λ_z = 1 − ε₀ it is the finite-strain
/// equilibrium platen stress (μ (λ_z² − 1)/λ_z for λ = 0). Throws if λ_z ≤ 0.
double neo_hookean_uniaxial_stress(double mu, double lambda, double stretch);

/// Resolution of the finite-strain reference.
struct ConfinedReferenceResolution {
  int cells = 200;         ///< P1 elements in Z, graded toward the drained top (fine run: twice)
  int steps = 200;         ///< BDF2 steps on the ramp and again on the hold (fine run: twice)
  bool richardson = true;  ///< combine a run and one with twice the resolution, (4 f₂ − f₁)/3
};

/// Finite-strain reference: platen stress σ(t) [MPa] (first Piola–Kirchhoff zz) at each of
/// `times` [s] (any order, ≥ 0). With `c.layers`, each element's Kirchhoff potential is scaled
/// by its layer's k₀/k: the grid node nearest each interface is moved onto it, so every element
/// lies in one layer. P1 elements with consistent mass on a grid graded toward the
/// drained top (cell sizes from 0.07 h/N to 4 h/N), variable-step BDF2 on time grids graded as
/// (i/M)⁴ from t = 0 and from t₀ (where the loading rate jumps), Newton with tridiagonal solves,
/// cubic interpolation in i/M to the requested times, and Richardson extrapolation. With the
/// defaults (≈ 0.1 s) the result is within about 6e−7 (relative) of the converged value on
/// FEBio's case; the error of the Richardson value falls about 8× per doubling. The hold grid
/// spans [t₀, max(times)], so the values depend slightly on the latest requested time.
std::vector<double> confined_ramp_stress_neo_hookean(const ConfinedRamp& c,
                                                     std::span<const double> times,
                                                     const ConfinedReferenceResolution& res = {});

}  // namespace biphasic::analytic
