#include "biphasic/material/material_laws.hpp"

#include <stdexcept>
#include <utility>

namespace biphasic {

double MaterialLaws::p_wave_modulus() const {
  return std::visit([](const auto& law) { return law.p_wave_modulus(); }, solid);
}

double MaterialLaws::reference_permeability() const {
  return std::visit([](const auto& law) { return law.permeability(1.0); }, permeability);
}

namespace {

/// describe() of every alternative of `Variant`, in order.
template <class Variant>
std::vector<LawDescription> describe_all() {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    static_assert((DescribedLaw<std::variant_alternative_t<I, Variant>> && ...));
    return std::vector<LawDescription>{std::variant_alternative_t<I, Variant>::describe()...};
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

/// The alternative of `Variant` whose description is called `name`, built from `source`.
template <class Variant>
Variant make_law(const std::string& family, const std::string& name,
                 const ParameterSource& source) {
  std::optional<Variant> made;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (void)((std::variant_alternative_t<I, Variant>::describe().name == name
                ? (made.emplace(std::variant_alternative_t<I, Variant>::from_parameters(source)),
                   true)
                : false) ||
           ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
  if (!made) throw std::invalid_argument(family + " \"" + name + "\" is not a registered law");
  return *std::move(made);
}

std::vector<LawFamily> build_families() {
  std::vector<LawFamily> families{
      {"solid_law", "Solid law of the skeleton", describe_all<AnySolidLaw>(),
       &MaterialConfig::solid_law},
      {"permeability_law", "How the permeability k depends on J = det F",
       describe_all<AnyPermeabilityLaw>(), &MaterialConfig::permeability_law}};
  // A parameter read by several laws must mean the same to each of them.
  std::vector<const LawParameter*> seen;
  for (const LawFamily& family : families) {
    for (const LawDescription& law : family.laws) {
      for (const LawParameter& p : law.parameters) {
        for (const LawParameter* other : seen) {
          if (other->name == p.name && !(*other == p)) {
            throw std::logic_error("material law \"" + law.name + "\" declares parameter \"" +
                                   p.name + "\" differently from another law");
          }
        }
        seen.push_back(&p);
      }
    }
  }
  return families;
}

}  // namespace

const std::vector<LawFamily>& material_law_families() {
  static const std::vector<LawFamily> families = build_families();
  return families;
}

const LawParameter* find_law_parameter(const std::string& name) {
  for (const LawFamily& family : material_law_families()) {
    for (const LawDescription& law : family.laws) {
      for (const LawParameter& p : law.parameters) {
        if (p.name == name) return &p;
      }
    }
  }
  return nullptr;
}

std::string default_solid_law() {
  return std::variant_alternative_t<0, AnySolidLaw>::describe().name;
}
std::string default_permeability_law() {
  return std::variant_alternative_t<0, AnyPermeabilityLaw>::describe().name;
}

MaterialLaws make_material_laws(const MaterialConfig& material) {
  const ParameterSource source = [&material](const std::string& name) {
    return material.get(name);
  };
  return {
      make_law<AnySolidLaw>("material.solid_law", material.solid_law, source),
      make_law<AnyPermeabilityLaw>("material.permeability_law", material.permeability_law, source)};
}

}  // namespace biphasic
