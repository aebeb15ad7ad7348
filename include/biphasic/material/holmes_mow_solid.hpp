// Holmes–Mow solid skeleton: the coupled, compressible, isotropic law of
//   M. H. Holmes and V. C. Mow, "The nonlinear characteristics of soft gels and hydrated
//   connective tissues in ultrafiltration", J. Biomech. 23(11):1145–1156 (1990),
// in the form FEBio implements as its material "Holmes-Mow" (FEBio User's Manual, material
// "Holmes-Mow"; FEBio source FEHolmesMow.cpp):
//   λ = Eν/((1 + ν)(1 − 2ν)),  μ = E/(2(1 + ν)),  H_A = λ + 2μ                     [MPa]
//   q = (2μ − λ)(I₁ − 3) + λ(I₂ − 3) − H_A ln I₃                                    [MPa]
//   Q = β q / H_A,   W = H_A/(4β) (e^Q − 1)   (= ½ c (e^Q − 1), c = H_A/(2β))       [MPa]
// with I₁, I₂, I₃ = J² the invariants of C = FᵀF (equal to those of b = FFᵀ). At F = I,
// q = 0 and ∂q/∂C = 0: stress free. To second order in E = (C − I)/2,
// W = ½λ (tr E)² + μ tr E²: linear elasticity with E, ν, and H_A is the P-wave modulus.
// β = 0 is the limit W = q/4 (a compressible Mooney–Rivlin form): every formula below is
// written with dW/dq = e^Q/4 and d²W/dq² = β e^Q/(4 H_A), which hold at β = 0 too; only the
// energy divides by β and uses the limit there.
//
// Stress (Kirchhoff τ = J σ = F S Fᵀ, b = FFᵀ):
//   τ = ½ e^Q [(2μ + λ(I₁ − 1)) b − λ b² − H_A 1],   P = τ F⁻ᵀ.
// Spatial tangent of τ (push-forward of ℂ = 4 ∂²W/∂C∂C; derivation in docs/formulation.md):
//   𝒸_ijkl = γ τ_ij τ_kl + e^Q [λ (b_ij b_kl − ½(b_ik b_jl + b_il b_jk)) + H_A ½(δ_ik δ_jl + δ_il
//   δ_jk)], γ = 4β/(H_A e^Q),
// and ∂P_iJ/∂F_kL = F⁻¹_Jj (𝒸_ijkl + δ_ik τ_jl) F⁻¹_Ll.
// Case-file keys (describe()): material.solid_law = "holmes_mow", material.youngs_modulus (E),
// material.poissons_ratio (ν), material.beta (β). A SolidLaw.
#pragma once

#include <array>

#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/material/law_parameters.hpp"
#include "biphasic/material/solid_law.hpp"

namespace biphasic {

struct HolmesMowSolid {
  double E = 1.0;     ///< Young's modulus [MPa], > 0
  double nu = 0.3;    ///< Poisson's ratio, in (−1, 0.5)
  double beta = 0.0;  ///< exponential stiffening coefficient β ≥ 0 (0: the limit form)

  /// Name "holmes_mow", parameters youngs_modulus, poissons_ratio and beta.
  static LawDescription describe();
  static HolmesMowSolid from_parameters(const ParameterSource& p) {
    return {p("youngs_modulus"), p("poissons_ratio"), p("beta")};
  }

  double lambda() const { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }  ///< Lamé λ [MPa]
  double mu() const { return 0.5 * E / (1.0 + nu); }                          ///< μ [MPa]
  /// H_A = λ + 2μ = E(1 − ν)/((1 + ν)(1 − 2ν)) [MPa], the oedometric modulus at small strain.
  double p_wave_modulus() const { return lambda() + 2.0 * mu(); }

  /// Strain energy per reference volume [MPa]. Throws if det F ≤ 0.
  double energy(const Mat3& F) const;
  /// Effective first Piola–Kirchhoff stress [MPa]. Throws if det F ≤ 0.
  Mat3 first_piola(const Mat3& F) const;

  /// The point response: the Kirchhoff stress τ and, per pair (i, k), the 3 × 3 block
  /// D_ik(j, l) = 𝒸_ijkl + δ_ik τ_jl, so that
  ///   ∇₀N_a,J (∂P_iJ/∂F_kL) ∇₀N_e,L = Σ_jl b_aj D_ik(j, l) b_el,   b_a = F⁻ᵀ∇₀N_a.
  struct Response {
    Mat3 tau;               ///< Kirchhoff stress τ = P Fᵀ [MPa]
    std::array<Mat3, 9> D;  ///< D[3i + k] [MPa]

    /// The mixture stress P − pJ F⁻ᵀ: τ − pJ 1, and the tangent's −pJ(F⁻ᵀ_iJ F⁻ᵀ_kL − F⁻ᵀ_iL
    /// F⁻ᵀ_kJ), i.e. D_ik += −pJ (e_i e_kᵀ − e_k e_iᵀ) [MPa].
    Response with_pore_pressure(double pJ) const;
    /// P = τ F⁻ᵀ [MPa].
    Mat3 first_piola(const Mat3& /*F*/, const Mat3& FinvT) const { return tau * FinvT; }
    /// Σ_jl b_aj D_ik(j, l) b_el [MPa mm⁻²] (G is not needed).
    double stiffness(const ShapeGradients& b, const ShapeProducts& /*G*/, int a, int i, int e,
                     int k) const {
      return b.row(a).dot(D[static_cast<std::size_t>(3 * i + k)] * b.row(e).transpose());
    }
  };
  /// The SolidLaw point response at F with J = det F > 0.
  Response response(const Mat3& F, double J) const;
};
static_assert(SolidLaw<HolmesMowSolid>);

}  // namespace biphasic
