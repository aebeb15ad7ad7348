// Compressible Neo-Hookean solid skeleton (Bonet & Wood; the paper's eq. neohooke):
//   Ψ = μ/2 (tr C − 3) − μ ln J + λ/2 (ln J)²   [MPa]
//   P_eff = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ            (first Piola–Kirchhoff, MPa)
#pragma once

#include <cmath>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

struct NeoHookean {
  double lambda = 0.2;  ///< Lamé λ [MPa]
  double mu = 0.5;      ///< shear modulus μ [MPa]

  /// Strain energy per reference volume [MPa]. Throws if det F ≤ 0.
  double energy(const Mat3& F) const;
  /// Effective first Piola–Kirchhoff stress [MPa]. Throws if det F ≤ 0.
  Mat3 first_piola(const Mat3& F) const;

  /// The tangent A = ∂P_eff/∂F written as
  ///   A_iJkL = c₁ δ_ik δ_JL + c₂ F⁻ᵀ_iJ F⁻ᵀ_kL − c₃ F⁻ᵀ_iL F⁻ᵀ_kJ
  /// with c₁ = μ, c₂ = λ, c₃ = λ ln J − μ [MPa].
  struct Tangent {
    double c1, c2, c3;
  };
  Tangent tangent(double J) const { return {mu, lambda, lambda * std::log(J) - mu}; }
  /// A : H for a direction H (used by tests).
  Mat3 tangent_apply(const Mat3& F, const Mat3& H) const;
};

/// det F, refusing non-positive values with a message that gives the value.
double checked_jacobian(const Mat3& F);

}  // namespace biphasic
