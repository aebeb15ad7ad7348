// Flux-perturbation stabilisation (Aguilar, Gaspar, Lisbona & Rodrigo 2008; FEBio's τ): Darcy's
// law becomes w = −k ∇ₓ(p + τ ṗ), i.e. the mass rows gain ∫ β ∇ₓṗ·∇ₓq with
//   β = k τ = scale · h²/(4 H_A)                                      [mm⁴ N⁻¹]
// H_A the solid's small-strain P-wave modulus and h the element length of
// stabilisation.length. The pressure then carries a rate: a differential variable of the DAE.
// Case-file value: stabilisation.type = "flux_perturbation", with stabilisation.length, .scale.
#pragma once

#include "biphasic/physics/stabilisation/stabilisation.hpp"

namespace biphasic {

struct FluxPerturbation {
  static StabilisationDescription describe() {
    return {"flux_perturbation",
            "Darcy flux perturbed by the pressure rate, beta = scale h^2/(4 H_A) (Aguilar et al. "
            "2008)",
            true};
  }
  static ElementCoefficients coefficients(double h2, const MaterialLaws& laws,
                                          const StabilisationContext& /*context*/) {
    ElementCoefficients c;
    c.flux_beta = h2 / (4.0 * laws.p_wave_modulus());
    return c;
  }
};
static_assert(Stabilisation<FluxPerturbation>);

}  // namespace biphasic
