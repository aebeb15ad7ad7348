// What the element kernel asks of a permeability law (docs/model_layer.md).
//
// A permeability law is a small value type giving the spatial permeability k of Darcy's law
// w = −k ∇ₓp as a function of the volume ratio J = det F, and its derivative:
//   permeability(J)             k(J)     [mm⁴ N⁻¹ s⁻¹]
//   permeability_derivative(J)  dk/dJ    [mm⁴ N⁻¹ s⁻¹]
// The derivative enters the Jacobian of the mass rows (dk/dJ ∂J/∂u, docs/formulation.md); a law
// that cannot be evaluated at J (for example J ≤ φ₀ of a porous law) throws std::domain_error,
// which the assembly reports as a failed element like an inverted one.
#pragma once

#include <concepts>

#include "biphasic/material/law_parameters.hpp"

namespace biphasic {

template <class Law>
concept PermeabilityLaw = requires(const Law& law, double J) {
  { law.permeability(J) } -> std::convertible_to<double>;
  { law.permeability_derivative(J) } -> std::convertible_to<double>;
};

/// Parameters that several permeability laws read, declared once so that they mean the same.
namespace permeability_parameters {

/// k₀ = k(J = 1), "permeability" [mm⁴ N⁻¹ s⁻¹].
inline LawParameter reference() {
  return {"permeability", 1e-3, ParameterBounds::above(0.0), "mm^4/(N s)",
          "Permeability k of the solid skeleton; with a strain-dependent law, k0 = k(J = 1)."};
}
/// φ₀, "solid_fraction": the referential solid volume fraction, 0 < φ₀ < 1.
inline LawParameter solid_fraction() {
  return {"solid_fraction", 0.2, ParameterBounds::between_open(0.0, 1.0), "",
          "Solid volume fraction phi0 of the reference state; k -> 0 as J -> phi0, and "
          "J <= phi0 fails the element."};
}
/// M, "permeability_M": the exponential coefficient of the strain dependence, M ≥ 0.
inline LawParameter exponential_coefficient() {
  return {"permeability_M", 0.0, ParameterBounds::at_least(0.0), "",
          "Exponential coefficient M of the permeability's strain dependence."};
}

}  // namespace permeability_parameters

}  // namespace biphasic
