// The registry of material laws: the one place where the case's material choices become law
// objects. A law is registered by adding its type to one of the variants below (and its header
// to the includes); its case-file keys, checks and documentation come from the law's own
// describe() (law_parameters.hpp, docs/model_layer.md). The element kernel is instantiated for
// every pair of registered laws and the pair is chosen once per element call, outside the
// quadrature loop.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "biphasic/material/constant_permeability.hpp"
#include "biphasic/material/exponential_permeability.hpp"
#include "biphasic/material/holmes_mow_permeability.hpp"
#include "biphasic/material/holmes_mow_solid.hpp"
#include "biphasic/material/lai_mow_permeability.hpp"
#include "biphasic/material/law_parameters.hpp"
#include "biphasic/material/material_config.hpp"
#include "biphasic/material/neo_hookean.hpp"

namespace biphasic {

/// Every solid law of the skeleton the solver can run; the first is the default.
using AnySolidLaw = std::variant<NeoHookean, HolmesMowSolid>;
/// Every permeability law the solver can run; the first is the default.
using AnyPermeabilityLaw = std::variant<ConstantPermeability, HolmesMowPermeability,
                                        ExponentialPermeability, LaiMowPermeability>;

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

/// The laws a material section selects, built from its parameter values. Throws
/// std::invalid_argument for a law name that is not registered.
MaterialLaws make_material_laws(const MaterialConfig& material);

/// One kind of law a material section chooses: the choice key and the registered laws.
struct LawFamily {
  std::string key;   ///< the choice key inside the section, "solid_law" or "permeability_law"
  std::string what;  ///< what the choice is, e.g. "Solid law of the skeleton"
  std::vector<LawDescription> laws;     ///< in registration order; the first is the default
  std::string MaterialConfig::*chosen;  ///< where MaterialConfig holds the choice
};

/// The solid and the permeability family. Throws std::logic_error (at first use) if two laws
/// declare the same parameter differently.
const std::vector<LawFamily>& material_law_families();

/// The declaration of a parameter of any registered law, or nullptr.
const LawParameter* find_law_parameter(const std::string& name);

}  // namespace biphasic
