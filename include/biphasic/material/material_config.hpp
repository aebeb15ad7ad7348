// The material of a region as the case file gives it: which solid law and which permeability
// law, and the values of their parameters (units: mm, N, s, MPa). The parameters are declared by
// the laws themselves (law_parameters.hpp); this holds only the values the case sets.
#pragma once

#include <map>
#include <string>

namespace biphasic {

/// Name of the default solid law ("neo_hookean") and permeability law ("constant").
std::string default_solid_law();
std::string default_permeability_law();

struct MaterialConfig {
  std::string solid_law = default_solid_law();                ///< material.solid_law
  std::string permeability_law = default_permeability_law();  ///< material.permeability_law

  /// The paper's material: a Neo-Hookean solid (λ, μ [MPa]) with constant permeability k
  /// [mm⁴ N⁻¹ s⁻¹].
  static MaterialConfig neo_hookean(double lambda, double mu, double permeability);

  /// The value of a parameter of any registered law: the one set, else the law's default.
  /// Throws std::invalid_argument if no registered law declares `name`.
  double get(const std::string& name) const;
  /// Sets a parameter of any registered law. Throws std::invalid_argument if no registered law
  /// declares `name` (a misspelt name is never stored).
  void set(const std::string& name, double value);

 private:
  std::map<std::string, double> values_;  ///< parameters set; the rest take their defaults
};

}  // namespace biphasic
