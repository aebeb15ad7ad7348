// The registry of material laws: the one place where the case's material choices become law
// objects. A law is registered by adding its type to the variant below (docs/model_layer.md);
// the element kernel is instantiated for every pair of registered laws and the pair is chosen
// once per element call, outside the quadrature loop.
#pragma once

#include <variant>

#include "biphasic/io/config.hpp"
#include "biphasic/material/constant_permeability.hpp"
#include "biphasic/material/exponential_permeability.hpp"
#include "biphasic/material/holmes_mow_permeability.hpp"
#include "biphasic/material/holmes_mow_solid.hpp"
#include "biphasic/material/neo_hookean.hpp"

namespace biphasic {

/// Every solid law of the skeleton the solver can run.
using AnySolidLaw = std::variant<NeoHookean, HolmesMowSolid>;
/// Every permeability law the solver can run.
using AnyPermeabilityLaw =
    std::variant<ConstantPermeability, HolmesMowPermeability, ExponentialPermeability>;

/// The laws of one material.
struct MaterialLaws {
  AnySolidLaw solid;
  AnyPermeabilityLaw permeability;

  /// The solid's small-strain P-wave modulus H_A [MPa] (λ + 2μ of the law's small-strain limit).
  double p_wave_modulus() const;
  /// k(J = 1) [mm⁴ N⁻¹ s⁻¹], the permeability of the undeformed state: the scale of the GLS
  /// coefficient c_e = h²/(4k) and of the pressure rows.
  double reference_permeability() const;
};

/// The laws the case's [material] section selects.
MaterialLaws make_material_laws(const MaterialConfig& material);

}  // namespace biphasic
