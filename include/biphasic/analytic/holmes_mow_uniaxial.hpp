// Homogeneous uniaxial responses of the Holmes–Mow solid (Holmes & Mow 1990, in FEBio's form;
// include/biphasic/material/holmes_mow_solid.hpp), written here from principal stretches
// without the material layer, as the reference of the drained column checks
// (tests/verification/test_holmes_mow_column.cpp, docs/verification.md).
//
// With λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)), H_A = λ + 2μ and principal stretches
// (λ₁, λ₂, λ₂), λ₁ along z: I₁ = λ₁² + 2λ₂², I₂ = 2λ₁²λ₂² + λ₂⁴, I₃ = λ₁²λ₂⁴,
//   Q = β/H_A [(2μ − λ)(I₁ − 3) + λ(I₂ − 3)] − β ln I₃,
//   principal Kirchhoff stress τ_a = ½ e^Q [(2μ + λ(I₁ − 1)) λ_a² − λ λ_a⁴ − H_A],
//   nominal (first Piola) stress P_zz = τ₁/λ₁ [MPa].
// Uniaxial stress: τ₂ = 0 fixes λ₂. With x = λ₂² it reads λ x² + (2μ + λ(λ₁² − 1)) x − H_A = 0,
// independent of β; the root continuous with x = 1 at λ₁ = 1 is found by a bracketed Brent
// iteration (the test compares it with the quadratic formula).
// Confined (oedometric) compression: λ₂ = 1, and the law reduces to
//   P_zz = (H_A/2) (λ₁² − 1)/λ₁ · exp(β(λ₁² − 1)) λ₁^(−2β).
#pragma once

namespace biphasic::analytic {

/// The parameters of the Holmes–Mow solid.
struct HolmesMowParameters {
  double E = 1.0;     ///< Young's modulus [MPa]
  double nu = 0.2;    ///< Poisson's ratio, in (−1, 0.5)
  double beta = 0.0;  ///< exponential stiffening β ≥ 0
};

/// Nominal stress P_zz [MPa] for the principal stretches (λ₁ along z, λ₂ laterally twice).
double holmes_mow_nominal_stress(const HolmesMowParameters& m, double stretch_z,
                                 double stretch_lateral);
/// The lateral stretch λ₂ of uniaxial stress (lateral stress zero) at axial stretch λ₁ > 0.
double holmes_mow_uniaxial_lateral_stretch(const HolmesMowParameters& m, double stretch_z);
/// P_zz [MPa] in uniaxial stress at axial stretch λ₁.
double holmes_mow_uniaxial_stress(const HolmesMowParameters& m, double stretch_z);
/// P_zz [MPa] in confined compression (lateral stretch 1) at axial stretch λ₁.
double holmes_mow_confined_stress(const HolmesMowParameters& m, double stretch_z);

}  // namespace biphasic::analytic
