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

namespace biphasic {

template <class Law>
concept PermeabilityLaw = requires(const Law& law, double J) {
  { law.permeability(J) } -> std::convertible_to<double>;
  { law.permeability_derivative(J) } -> std::convertible_to<double>;
};

}  // namespace biphasic
