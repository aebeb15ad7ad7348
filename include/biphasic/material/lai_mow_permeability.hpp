// Strain-dependent permeability of Lai & Mow (Biorheology 17:111–123, 1980), exponential in the
// volumetric strain ε = J − 1:
//   k(J) = k₀ exp(M (J − 1))                                          [mm⁴ N⁻¹ s⁻¹]
//   dk/dJ = M k(J)
// with M ≥ 0 dimensionless; k(1) = k₀. Unlike the "exponential" law (FEBio's form, which
// reduces to this one with M' = M/(1 − φ₀) at small strain), k stays positive at every J > 0:
// there is no pore closure, so no solid fraction and no failure at J ≤ φ₀. Suited to small and
// moderate compression, where Lai & Mow fitted it to cartilage permeation data.
// Case-file keys (describe()): material.permeability_law = "lai_mow", material.permeability
// (k₀), material.permeability_M (M).
#pragma once

#include <cmath>

#include "biphasic/material/permeability_law.hpp"

namespace biphasic {

struct LaiMowPermeability {
  double k0 = 1e-3;  ///< k₀, the permeability at J = 1 [mm⁴ N⁻¹ s⁻¹]
  double M = 0.0;    ///< M, exponential coefficient of the volumetric strain

  static LawDescription describe() {
    return {
        "lai_mow",
        "k0 exp(M (J - 1)), Lai & Mow 1980",
        {permeability_parameters::reference(), permeability_parameters::exponential_coefficient()},
        {}};
  }
  static LaiMowPermeability from_parameters(const ParameterSource& p) {
    return {p("permeability"), p("permeability_M")};
  }

  double permeability(double J) const { return k0 * std::exp(M * (J - 1.0)); }
  double permeability_derivative(double J) const { return M * permeability(J); }
};
static_assert(PermeabilityLaw<LaiMowPermeability>);

}  // namespace biphasic
