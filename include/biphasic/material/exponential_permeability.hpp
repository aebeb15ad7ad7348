// Exponential strain-dependent permeability (after Lai & Mow, Biorheology 17, 1980), in the
// form FEBio documents as "perm-exp-iso":
//   k(J) = k₀ exp(M (J − 1)/(J − φ₀))                                [mm⁴ N⁻¹ s⁻¹]
//   dk/dJ = k(J) M (1 − φ₀)/(J − φ₀)²
// with φ₀ the referential solid volume fraction and M ≥ 0 dimensionless. For small strains the
// exponent is M ε/(1 − φ₀), ε = J − 1 the volumetric strain: Lai & Mow's k₀ exp(M' ε) with
// M' = M/(1 − φ₀). k(1) = k₀; k → 0 as J → φ₀ from above.
// Case-file keys (describe()): material.permeability_law = "exponential", material.permeability
// (k₀), material.solid_fraction (φ₀), material.permeability_M (M).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "biphasic/material/permeability_law.hpp"

namespace biphasic {

struct ExponentialPermeability {
  double k0 = 1e-3;   ///< k₀, the permeability at J = 1 [mm⁴ N⁻¹ s⁻¹]
  double phi0 = 0.2;  ///< φ₀, referential solid volume fraction, 0 < φ₀ < 1
  double M = 0.0;     ///< M, exponential coefficient

  static LawDescription describe() {
    return {"exponential",
            "k0 exp(M (J - 1)/(J - phi0)), after Lai & Mow 1980",
            {permeability_parameters::reference(), permeability_parameters::solid_fraction(),
             permeability_parameters::exponential_coefficient()},
            {}};
  }
  static ExponentialPermeability from_parameters(const ParameterSource& p) {
    return {p("permeability"), p("solid_fraction"), p("permeability_M")};
  }

  double permeability(double J) const { return k0 * std::exp(M * (J - 1.0) / pores(J)); }
  double permeability_derivative(double J) const {
    const double d = pores(J);
    return permeability(J) * M * (1.0 - phi0) / (d * d);
  }

 private:
  /// J − φ₀; throws std::domain_error at or below full compaction (J ≤ φ₀).
  double pores(double J) const {
    if (!(J > phi0)) {
      throw std::domain_error("exponential permeability: J = " + std::to_string(J) +
                              " is at or below the solid volume fraction phi0 = " +
                              std::to_string(phi0) + " (the pores have closed)");
    }
    return J - phi0;
  }
};
static_assert(PermeabilityLaw<ExponentialPermeability>);

}  // namespace biphasic
