// Element kernel of the finite-strain biphasic mixture (docs/formulation.md, the paper §2–3):
//   R_u = ∫Ω₀ ∇₀f : (P_eff − p J F⁻ᵀ) dX + ∫Ω₀ c_e (F⁻ᵀ : ∇₀f) J̇ dX        (momentum + GLS)
//   R_p = ∫Ω₀ g J̇ dX + ∫Ω₀ k J (F⁻ᵀ∇₀p)·(F⁻ᵀ∇₀g) dX                      (mass, Darcy)
// with J̇ = J F⁻ᵀ : ∇₀u̇ (incremental form) or, for backward Euler, J̇ = (J − Jₙ)/Δt with
// Jₙ = det(I + ∇₀uₙ), uₙ = u − Δt u̇ (conservative form, ElementParameters::volume_rate_dt > 0),
// and optionally the flux-perturbation stabilisation (Aguilar et al.
// 2008, FEBio's `tau`): w = −k∇ₓ(p + τṗ), i.e. R_p += ∫Ω₀ β J (F⁻ᵀ∇₀ṗ)·(F⁻ᵀ∇₀g) dX, β = kτ. Local
// unknowns: u of the 10 nodes (index 3a + i), then p of the 4 corners (index 30 + c). Units: u mm,
// p MPa, R_u N, R_p mm³/s.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "biphasic/material/neo_hookean.hpp"
#include "biphasic/physics/element_geometry.hpp"

namespace biphasic {

inline constexpr int kElementDofs = 34;
using ElementVector = Eigen::Matrix<double, kElementDofs, 1>;
using ElementMatrix = Eigen::Matrix<double, kElementDofs, kElementDofs>;

struct ElementParameters {
  NeoHookean material;
  double permeability = 1e-3;  ///< k [mm⁴ N⁻¹ s⁻¹]
  double gls_c = 0.0;          ///< c_e = h²/(4k) of the semidiscrete GLS term [MPa s]
  double flux_beta = 0.0;      ///< β = h²/(4 H_A) of the flux perturbation [mm⁴ N⁻¹]
  /// Δt [s] > 0: J̇ = (J − Jₙ)/Δt, uₙ = u − Δt u̇ (conservative); 0: J̇ = J F⁻ᵀ:∇₀u̇.
  double volume_rate_dt = 0.0;
};

/// Local state: y = (u₀ₓ, u₀ᵧ, u₀𝓏, …, u₉𝓏, p₀, …, p₃) and its rate ẏ.
struct ElementOutput {
  ElementVector residual;
  ElementMatrix dfdy;     ///< ∂R/∂y
  ElementMatrix dfdydot;  ///< ∂R/∂ẏ
};

/// Evaluates the residual and, if `with_jacobian`, both Jacobian blocks.
/// Throws std::domain_error if det F ≤ 0 at a quadrature point.
void biphasic_element(const std::vector<PointGeometry>& geometry, const ElementParameters& params,
                      const ElementVector& y, const ElementVector& ydot, bool with_jacobian,
                      ElementOutput& out);

}  // namespace biphasic
