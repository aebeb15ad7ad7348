// The registry of pressure stabilisations: a stabilisation is registered by adding its type to
// AnyStabilisation (and its header to the includes). The case file's stabilisation.type takes
// its allowed values and help from the descriptions; BiphasicProblem asks the chosen one for
// each element's coefficients.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "biphasic/physics/stabilisation/flux_perturbation.hpp"
#include "biphasic/physics/stabilisation/flux_perturbation_minimal.hpp"
#include "biphasic/physics/stabilisation/gls_minimal.hpp"
#include "biphasic/physics/stabilisation/gls_stabilisation.hpp"
#include "biphasic/physics/stabilisation/no_stabilisation.hpp"
#include "biphasic/physics/stabilisation/stabilisation_config.hpp"

namespace biphasic {

/// Every stabilisation the solver can run; the first is the default.
using AnyStabilisation = std::variant<NoStabilisation, GlsStabilisation, FluxPerturbation,
                                      GlsMinimal, FluxPerturbationMinimal>;

/// The descriptions of the registered stabilisations, in registration order.
inline const std::vector<StabilisationDescription>& stabilisation_descriptions() {
  static const std::vector<StabilisationDescription> all =
      []<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<StabilisationDescription>{
        std::variant_alternative_t<I, AnyStabilisation>::describe()...};
  }
  (std::make_index_sequence<std::variant_size_v<AnyStabilisation>>{});
  return all;
}

/// The stabilisation called `name`; throws std::invalid_argument for a name not registered.
inline AnyStabilisation make_stabilisation(const std::string& name) {
  const auto& all = stabilisation_descriptions();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].name != name) continue;
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      AnyStabilisation out;
      (void)((i == I ? (out.emplace<I>(), true) : false) || ...);
      return out;
    }
    (std::make_index_sequence<std::variant_size_v<AnyStabilisation>>{});
  }
  throw std::invalid_argument("stabilisation.type \"" + name +
                              "\" is not a registered "
                              "stabilisation");
}

/// The description of `s`.
inline StabilisationDescription describe(const AnyStabilisation& s) {
  return std::visit([](const auto& x) { return x.describe(); }, s);
}

/// The context of the case's [stabilisation] section: its threshold, and its time_step or, if
/// that is 0, the run's step `dt` [s].
inline StabilisationContext stabilisation_context(const StabilisationConfig& config, double dt) {
  return {config.threshold, config.time_step > 0.0 ? config.time_step : dt};
}

/// The per-element coefficients `s` gives an element of squared length h2 [mm²] and material
/// `laws`.
inline ElementCoefficients element_coefficients(const AnyStabilisation& s, double h2,
                                                const MaterialLaws& laws,
                                                const StabilisationContext& context) {
  return std::visit([&](const auto& x) { return x.coefficients(h2, laws, context); }, s);
}

}  // namespace biphasic
