#include "biphasic/material/material_laws.hpp"

namespace biphasic {

double MaterialLaws::p_wave_modulus() const {
  return std::visit([](const auto& law) { return law.p_wave_modulus(); }, solid);
}

double MaterialLaws::reference_permeability() const {
  return std::visit([](const auto& law) { return law.permeability(1.0); }, permeability);
}

namespace {

AnyPermeabilityLaw make_permeability_law(const MaterialConfig& m) {
  switch (m.permeability_law) {
    case PermeabilityLawType::HolmesMow:
      return HolmesMowPermeability{m.permeability, m.solid_fraction, m.permeability_kappa,
                                   m.permeability_M};
    case PermeabilityLawType::Exponential:
      return ExponentialPermeability{m.permeability, m.solid_fraction, m.permeability_M};
    case PermeabilityLawType::Constant:
      break;
  }
  return ConstantPermeability{m.permeability};
}

AnySolidLaw make_solid_law(const MaterialConfig& m) {
  if (m.solid_law == SolidLawType::HolmesMow)
    return HolmesMowSolid{m.youngs_modulus, m.poissons_ratio, m.beta};
  return NeoHookean{m.lambda, m.mu};
}

}  // namespace

MaterialLaws make_material_laws(const MaterialConfig& material) {
  return {make_solid_law(material), make_permeability_law(material)};
}

}  // namespace biphasic
