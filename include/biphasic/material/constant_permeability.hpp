// Constant spatial permeability (the paper's model): k(J) = k₀, dk/dJ = 0.
// Case-file keys (describe()): material.permeability_law = "constant", material.permeability = k₀
// [mm⁴ N⁻¹ s⁻¹].
#pragma once

#include "biphasic/material/permeability_law.hpp"

namespace biphasic {

struct ConstantPermeability {
  double k0 = 1e-3;  ///< k₀ [mm⁴ N⁻¹ s⁻¹]

  static LawDescription describe() {
    return {"constant", "k = k0, the paper's model", {permeability_parameters::reference()}, {}};
  }
  static ConstantPermeability from_parameters(const ParameterSource& p) {
    return {p("permeability")};
  }

  double permeability(double /*J*/) const { return k0; }
  double permeability_derivative(double /*J*/) const { return 0.0; }
};
static_assert(PermeabilityLaw<ConstantPermeability>);

}  // namespace biphasic
