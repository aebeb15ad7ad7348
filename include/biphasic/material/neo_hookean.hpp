// Compressible Neo-Hookean solid skeleton (Bonet & Wood; the paper's eq. neohooke):
//   Ψ = μ/2 (tr C − 3) − μ ln J + λ/2 (ln J)²   [MPa]
//   P_eff = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ            (first Piola–Kirchhoff, MPa)
//   A = ∂P_eff/∂F, A_iJkL = μ δ_ik δ_JL + λ F⁻ᵀ_iJ F⁻ᵀ_kL − (λ ln J − μ) F⁻ᵀ_iL F⁻ᵀ_kJ   [MPa]
// Small-strain P-wave modulus H_A = λ + 2μ. A SolidLaw (solid_law.hpp).
// Case-file keys (describe()): material.solid_law = "neo_hookean", material.lambda,
// material.mu [MPa]; λ + ⅔μ > 0 is checked.
#pragma once

#include <cmath>

#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/material/law_parameters.hpp"
#include "biphasic/material/solid_law.hpp"

namespace biphasic {

struct NeoHookean {
  double lambda = 0.2;  ///< Lamé λ [MPa]
  double mu = 0.5;      ///< shear modulus μ [MPa]

  /// Name "neo_hookean", parameters lambda and mu, the check λ + ⅔μ > 0.
  static LawDescription describe();
  static NeoHookean from_parameters(const ParameterSource& p) { return {p("lambda"), p("mu")}; }

  /// H_A = λ + 2μ [MPa], the oedometric modulus at small strain.
  double p_wave_modulus() const { return lambda + 2.0 * mu; }

  /// Strain energy per reference volume [MPa]. Throws if det F ≤ 0.
  double energy(const Mat3& F) const;
  /// Effective first Piola–Kirchhoff stress [MPa]. Throws if det F ≤ 0.
  Mat3 first_piola(const Mat3& F) const;

  /// The stress and tangent of the form
  ///   P = c₁ F + c₃ F⁻ᵀ,
  ///   A_iJkL = c₁ δ_ik δ_JL + c₂ F⁻ᵀ_iJ F⁻ᵀ_kL − c₃ F⁻ᵀ_iL F⁻ᵀ_kJ,
  /// with c₁ = μ, c₂ = λ, c₃ = λ ln J − μ [MPa] for the skeleton alone.
  struct Tangent {
    double c1, c2, c3;

    /// The mixture stress P − pJ F⁻ᵀ: the pore-pressure part has c₂ = c₃ = −pJ [MPa].
    Tangent with_pore_pressure(double pJ) const { return {c1, c2 - pJ, c3 - pJ}; }
    /// P = c₁ F + c₃ F⁻ᵀ [MPa].
    Mat3 first_piola(const Mat3& F, const Mat3& FinvT) const { return c1 * F + c3 * FinvT; }
    /// ∇₀N_a,J A_iJkL ∇₀N_e,L = c₂ b_ai b_ek − c₃ b_ei b_ak + c₁ G_ae δ_ik, with
    /// b = ∇₀N F⁻¹ (rows F⁻ᵀ∇₀N_a) and G_ae = ∇₀N_a·∇₀N_e.
    double stiffness(const ShapeGradients& b, const ShapeProducts& G, int a, int i, int e,
                     int k) const {
      double s = c2 * b(a, i) * b(e, k) - c3 * b(e, i) * b(a, k);
      if (i == k) s += c1 * G(a, e);
      return s;
    }
  };
  Tangent tangent(double J) const { return {mu, lambda, lambda * std::log(J) - mu}; }
  /// The SolidLaw point response at F with J = det F > 0 (only J is needed).
  Tangent response(const Mat3& /*F*/, double J) const { return tangent(J); }
  /// A : H for a direction H (used by tests).
  Mat3 tangent_apply(const Mat3& F, const Mat3& H) const;
};
static_assert(SolidLaw<NeoHookean>);

/// det F, refusing non-positive values with a message that gives the value.
double checked_jacobian(const Mat3& F);

}  // namespace biphasic
