// Galerkin least-squares pressure stabilisation of the paper, in semidiscrete form: the
// momentum rows gain ∫Ω₀ c_e(J) (F⁻ᵀ : ∇₀f) J̇ dX with
//   c_e(J) = scale · h²/(4 k(J))                                      [MPa s]
// h the element length of stabilisation.length. The element stores c_e,ref = scale h²/(4 k(1))
// and the kernel scales it by k(1)/k(J) at each quadrature point (docs/formulation.md, "GLS
// with a strain-dependent permeability"). With GLS the pressure is an algebraic variable of
// the DAE (docs/formulation.md, "Consistent initial values").
// Case-file value: stabilisation.type = "gls", with stabilisation.length and .scale.
#pragma once

#include "biphasic/physics/stabilisation/stabilisation.hpp"

namespace biphasic {

struct GlsStabilisation {
  static StabilisationDescription describe() {
    return {"gls", "Galerkin least squares, c_e = scale h^2/(4 k(J)) (the paper's)", true};
  }
  static ElementCoefficients coefficients(double h2, const MaterialLaws& laws,
                                          const StabilisationContext& /*context*/) {
    ElementCoefficients c;
    c.gls_c = h2 / (4.0 * laws.reference_permeability());
    return c;
  }
};
static_assert(Stabilisation<GlsStabilisation>);

}  // namespace biphasic
