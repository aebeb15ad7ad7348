// No pressure stabilisation: plain Galerkin P2/P1 Taylor–Hood, the paper's reference without
// GLS. Exact where k Δt/h² is large enough; oscillates in the first steps otherwise
// (docs/formulation.md, the oscillation analysis).
// Case-file value: stabilisation.type = "none" (the default).
#pragma once

#include "biphasic/physics/stabilisation/stabilisation.hpp"

namespace biphasic {

struct NoStabilisation {
  static StabilisationDescription describe() { return {"none", "plain Galerkin P2/P1", false}; }
  static ElementCoefficients coefficients(double /*h2*/, const MaterialLaws& /*laws*/,
                                          const StabilisationContext& /*context*/) {
    return {};
  }
};
static_assert(Stabilisation<NoStabilisation>);

}  // namespace biphasic
