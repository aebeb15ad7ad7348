#include "biphasic/material/material_laws.hpp"

namespace biphasic {

double MaterialLaws::p_wave_modulus() const {
  return std::visit([](const auto& law) { return law.p_wave_modulus(); }, solid);
}

double MaterialLaws::reference_permeability() const {
  return std::visit([](const auto& law) { return law.permeability(1.0); }, permeability);
}

MaterialLaws make_material_laws(const MaterialConfig& material) {
  return {NeoHookean{material.lambda, material.mu}, ConstantPermeability{material.permeability}};
}

}  // namespace biphasic
