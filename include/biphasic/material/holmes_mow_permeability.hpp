// Strain-dependent permeability of Holmes & Mow (J. Biomech. 23, 1990), the law FEBio calls
// "perm-Holmes-Mow":
//   k(J) = k₀ ((J − φ₀)/(1 − φ₀))^κ exp(M (J² − 1)/2)               [mm⁴ N⁻¹ s⁻¹]
//   dk/dJ = k(J) (κ/(J − φ₀) + M J)
// with φ₀ the solid volume fraction in the reference state (J = φ₀ is the fully compacted
// mixture, where the pores close and k → 0), κ ≥ 0 and M ≥ 0 dimensionless. k(1) = k₀.
// Case-file keys (describe()): material.permeability_law = "holmes_mow", material.permeability
// (k₀), material.solid_fraction (φ₀), material.permeability_kappa (κ), material.permeability_M
// (M).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "biphasic/material/permeability_law.hpp"

namespace biphasic {

struct HolmesMowPermeability {
  double k0 = 1e-3;    ///< k₀, the permeability at J = 1 [mm⁴ N⁻¹ s⁻¹]
  double phi0 = 0.2;   ///< φ₀, referential solid volume fraction, 0 < φ₀ < 1
  double kappa = 0.0;  ///< κ, exponent of the porosity ratio
  double M = 0.0;      ///< M, exponential stiffening coefficient

  static LawDescription describe() {
    return {"holmes_mow",
            "k0 ((J - phi0)/(1 - phi0))^kappa exp(M (J^2 - 1)/2), Holmes & Mow 1990",
            {permeability_parameters::reference(),
             permeability_parameters::solid_fraction(),
             {"permeability_kappa", 0.0, ParameterBounds::at_least(0.0), "",
              "Exponent kappa of the porosity ratio (J - phi0)/(1 - phi0)."},
             permeability_parameters::exponential_coefficient()},
            {}};
  }
  static HolmesMowPermeability from_parameters(const ParameterSource& p) {
    return {p("permeability"), p("solid_fraction"), p("permeability_kappa"), p("permeability_M")};
  }

  double permeability(double J) const {
    return k0 * std::pow(porosity_ratio(J), kappa) * std::exp(0.5 * M * (J * J - 1.0));
  }
  double permeability_derivative(double J) const {
    return permeability(J) * (kappa / (J - phi0) + M * J);
  }

 private:
  /// (J − φ₀)/(1 − φ₀); throws std::domain_error at or below full compaction (J ≤ φ₀).
  double porosity_ratio(double J) const {
    if (!(J > phi0)) {
      throw std::domain_error("Holmes-Mow permeability: J = " + std::to_string(J) +
                              " is at or below the solid volume fraction phi0 = " +
                              std::to_string(phi0) + " (the pores have closed)");
    }
    return (J - phi0) / (1.0 - phi0);
  }
};
static_assert(PermeabilityLaw<HolmesMowPermeability>);

}  // namespace biphasic
