// What a pressure stabilisation is to the solver (docs/model_layer.md, "Stabilisations").
//
// Equal-order-violating P2/P1 is inf-sup stable, but at small k Δt/h² the first steps of a
// consolidation problem oscillate next to drained faces; a stabilisation adds a term that
// damps them (docs/formulation.md). Each is a small value type in its own file with
//   static StabilisationDescription describe();   its case-file name and one-line summary
//   static ElementCoefficients coefficients(double h2, const MaterialLaws& laws,
//                                           const StabilisationContext& context);
// the per-element coefficients of the kernel's stabilising terms (ElementCoefficients) for
// an element of squared length h2 = scale · h² [mm²] and material `laws`. The terms themselves
// are assembled by the kernel (biphasic_element.hpp), which sees only the coefficients.
#pragma once

#include <concepts>
#include <string>

#include "biphasic/material/material_laws.hpp"
#include "biphasic/physics/biphasic_element.hpp"

namespace biphasic {

struct StabilisationDescription {
  std::string name;              ///< the value of stabilisation.type
  std::string summary;           ///< its term and source, one sentence
  bool sized_by_element = true;  ///< reads stabilisation.length and stabilisation.scale
};

/// What a need-following coefficient reads besides the element: the threshold r* of
/// stabilisation.threshold and the step Δt* it is frozen at (stabilisation.time_step, by
/// default time.dt).
struct StabilisationContext {
  double threshold = 0.25;  ///< r*: no stabilisation where c Δt*/h² ≥ r* [-]
  double time_step = 0.0;   ///< Δt* [s]
};

template <class S>
concept Stabilisation = requires(double h2, const MaterialLaws& laws,
                                 const StabilisationContext& context) {
  { S::describe() } -> std::convertible_to<StabilisationDescription>;
  { S::coefficients(h2, laws, context) } -> std::convertible_to<ElementCoefficients>;
};

}  // namespace biphasic
