// Constant spatial permeability (the paper's model): k(J) = k₀, dk/dJ = 0.
// Case-file key: material.permeability = k₀ [mm⁴ N⁻¹ s⁻¹] (src/io/case_schema.cpp).
#pragma once

#include "biphasic/material/permeability_law.hpp"

namespace biphasic {

struct ConstantPermeability {
  double k0 = 1e-3;  ///< k₀ [mm⁴ N⁻¹ s⁻¹]

  double permeability(double /*J*/) const { return k0; }
  double permeability_derivative(double /*J*/) const { return 0.0; }
};
static_assert(PermeabilityLaw<ConstantPermeability>);

}  // namespace biphasic
