// Need-following GLS: the paper's term with the least coefficient the first backward-Euler step
// needs to stay monotone (docs/formulation.md, "The first step's monotonicity"):
//   c_e(J) = max(0, r* h²/k(J) − H_A Δt*)                             [MPa s]
// i.e. τ = c_e/Δt* = max(0, r* h²/(k Δt*) − H_A): the step acts as an unstabilised step with
// r = k H_A Δt*/h² raised to r*, and elements with r ≥ r* are left unstabilised. With the
// default r* = 1/4 it equals the paper's c_e = h²/(4k) as r → 0 and vanishes from r = 1/4.
// Δt* is frozen (stabilisation.time_step, default time.dt), so the residual is one function
// F(t, y, ẏ) for backward Euler and for IDA alike. The element stores r* h²/k(1) and H_A Δt*;
// the kernel forms c_e(J) at each quadrature point (point_stabilisation).
// Case-file value: stabilisation.type = "gls_minimal", with stabilisation.threshold (r*),
// .time_step (Δt*), .length and .scale (multiplies h²).
#pragma once

#include "biphasic/physics/stabilisation/stabilisation.hpp"

namespace biphasic {

struct GlsMinimal {
  static StabilisationDescription describe() {
    return {"gls_minimal",
            "Galerkin least squares with the least coefficient the first step needs, c_e = "
            "max(0, threshold h^2/k(J) - H_A time_step)",
            true};
  }
  static ElementCoefficients coefficients(double h2, const MaterialLaws& laws,
                                          const StabilisationContext& context) {
    ElementCoefficients c;
    c.gls_c = context.threshold * h2 / laws.reference_permeability();
    c.gls_offset = laws.p_wave_modulus() * context.time_step;
    return c;
  }
};
static_assert(Stabilisation<GlsMinimal>);

}  // namespace biphasic
