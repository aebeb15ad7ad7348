// Need-following flux perturbation: Darcy's law w = −k ∇ₓp − β ∇ₓṗ with the least β the first
// backward-Euler step needs to stay monotone (docs/formulation.md, "The first step's
// monotonicity"):
//   β(J) = max(0, r* h²/H_A − k(J) Δt*)                               [mm⁴ N⁻¹]
// i.e. k + β/Δt* = max(k, r* h²/(H_A Δt*)): the step sees the conductance of an unstabilised
// step with r = k H_A Δt*/h² raised to r*, and elements with r ≥ r* are left unstabilised. With
// the default r* = 1/4 it equals Aguilar et al.'s β = h²/(4 H_A) as r → 0. Δt* is frozen
// (stabilisation.time_step, default time.dt), so the residual is one function F(t, y, ẏ).
// Case-file value: stabilisation.type = "flux_perturbation_minimal", with
// stabilisation.threshold (r*), .time_step (Δt*), .length and .scale (multiplies h²).
#pragma once

#include "biphasic/physics/stabilisation/stabilisation.hpp"

namespace biphasic {

struct FluxPerturbationMinimal {
  static StabilisationDescription describe() {
    return {"flux_perturbation_minimal",
            "Darcy flux perturbed by the pressure rate with the least coefficient the first step "
            "needs, beta = max(0, threshold h^2/H_A - k(J) time_step)",
            true};
  }
  static ElementCoefficients coefficients(double h2, const MaterialLaws& laws,
                                          const StabilisationContext& context) {
    ElementCoefficients c;
    c.flux_beta = context.threshold * h2 / laws.p_wave_modulus();
    c.flux_offset = context.time_step;
    return c;
  }
};
static_assert(Stabilisation<FluxPerturbationMinimal>);

}  // namespace biphasic
