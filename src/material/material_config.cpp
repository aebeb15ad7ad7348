#include "biphasic/material/material_config.hpp"

#include <stdexcept>

#include "biphasic/material/material_laws.hpp"

namespace biphasic {

namespace {

const LawParameter& declared(const std::string& name) {
  const LawParameter* p = find_law_parameter(name);
  if (p == nullptr) {
    throw std::invalid_argument("no registered material law has a parameter \"" + name + "\"");
  }
  return *p;
}

}  // namespace

MaterialConfig MaterialConfig::neo_hookean(double lambda, double mu, double permeability) {
  MaterialConfig m;
  m.solid_law = "neo_hookean";
  m.permeability_law = "constant";
  m.set("lambda", lambda);
  m.set("mu", mu);
  m.set("permeability", permeability);
  return m;
}

double MaterialConfig::get(const std::string& name) const {
  const auto it = values_.find(name);
  return it != values_.end() ? it->second : declared(name).default_value;
}

void MaterialConfig::set(const std::string& name, double value) {
  declared(name);
  values_[name] = value;
}

}  // namespace biphasic
