// How a material law declares its case-file keys (docs/model_layer.md, "Adding a law").
//
// Every law type carries, next to its equations,
//   static LawDescription describe();                        its name, summary and parameters
//   static Law from_parameters(const ParameterSource& p);    the law built from the values
// A parameter is a key of a material section ([material] or a [[region]] entry), e.g.
// "permeability_M" is read as material.permeability_M. The case-file schema, its checks (ranges,
// keys of a law that is not chosen), the generated key reference and the JSON dump are derived
// from these declarations (material_laws.hpp), so a law's keys are written in the law's file
// only. Several laws may read the same parameter (k₀ of every permeability law); they then
// declare it identically, normally through one shared LawParameter.
#pragma once

#include <concepts>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace biphasic {

/// Bounds of a parameter's value; an unset side is unbounded.
struct ParameterBounds {
  std::optional<double> min;
  std::optional<double> max;
  bool min_open = false;  ///< true: value > min, false: value >= min
  bool max_open = false;  ///< true: value < max, false: value <= max

  static ParameterBounds any() { return {}; }
  static ParameterBounds above(double a) { return {a, std::nullopt, true, false}; }
  static ParameterBounds at_least(double a) { return {a, std::nullopt, false, false}; }
  static ParameterBounds between_open(double a, double b) { return {a, b, true, true}; }

  bool operator==(const ParameterBounds&) const = default;
};

/// One number a law reads from its material section.
struct LawParameter {
  std::string name;  ///< key inside the section, e.g. "permeability_M"
  double default_value = 0.0;
  ParameterBounds bounds;
  std::string unit;  ///< empty when dimensionless
  std::string help;  ///< what it is, with its symbol; the laws using it are added by the schema

  bool operator==(const LawParameter&) const = default;
};

/// The value of a parameter by name: the section's value, or the declared default.
using ParameterSource = std::function<double(const std::string&)>;

/// A condition across a law's parameters that has failed: the key to blame (a parameter name)
/// and the reason, written with the section prefix given to the check.
struct ParameterProblem {
  std::string key;
  std::string message;
};

/// Everything the case file needs to know of one law.
struct LawDescription {
  std::string name;     ///< the value that selects it, e.g. "holmes_mow"
  std::string summary;  ///< its equation and source, one sentence
  std::vector<LawParameter> parameters;
  /// Checks across parameters beyond each one's bounds (may be empty). `prefix` is the section
  /// ("material.") to write before parameter names in the message.
  std::function<std::optional<ParameterProblem>(const ParameterSource&, const std::string& prefix)>
      check;

  /// Whether the law declares the parameter `parameter`.
  bool reads(const std::string& parameter) const {
    for (const LawParameter& p : parameters) {
      if (p.name == parameter) return true;
    }
    return false;
  }
};

/// A law the case file can select: it describes its keys and is built from their values.
template <class Law>
concept DescribedLaw = requires(const ParameterSource& source) {
  { Law::describe() } -> std::convertible_to<LawDescription>;
  { Law::from_parameters(source) } -> std::convertible_to<Law>;
};

}  // namespace biphasic
