// Internal: the case-file schema. One table of keys drives validation, defaults (taken from a
// default-constructed Config), the generated Markdown reference and the JSON dump.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "biphasic/io/config.hpp"

namespace biphasic::case_schema {

/// What a key holds in the TOML file.
enum class Kind {
  Integer,     ///< TOML integer
  Number,      ///< TOML float or integer
  Boolean,     ///< true / false
  String,      ///< free string
  Choice,      ///< one string from `choices`
  Vector3,     ///< array of exactly 3 numbers
  StringList,  ///< array of strings, each from `choices`
  Selection,   ///< true (a default set), false (none) or an array of strings from `choices`
  Curve,       ///< array of [t, value] pairs (only under [curves])
  Expression,  ///< formula of x, y, z, t (string; a number is taken as a constant formula)
  NumberList,  ///< array of numbers, each in `range`
};

/// Whether a [[boundary]] key must, may or must not appear for a given boundary type.
enum class Need { Optional, Required, Forbidden };

inline constexpr std::size_t kBcTypeCount = 7;

/// Closed or open bounds on a number; an unset side is unbounded.
struct Range {
  std::optional<double> min;
  std::optional<double> max;
  bool min_open = false;  ///< true: value > min, false: value >= min
  bool max_open = false;  ///< true: value < max, false: value <= max

  bool contains(double x) const;
  /// "> 0", ">= 1", "in (0, 1)", "in [1, 1000]"; empty if unbounded.
  std::string describe() const;
};

/// A key's value once read from TOML (Choice keys hold their string).
using Value = std::variant<std::int64_t, double, bool, std::string, std::array<double, 3>,
                           std::vector<std::string>, std::vector<double>>;

/// Everything about a key except how it is stored.
struct KeyInfo {
  std::string path;  ///< full dotted path, or the key name inside a [[boundary]] entry
  Kind kind = Kind::Number;
  std::string unit;  ///< empty when dimensionless
  std::string help;
  Range range;                            ///< Integer / Number / Vector3 components
  std::vector<std::string> choices;       ///< Choice / StringList
  std::vector<std::int64_t> allowed;      ///< Integer: permitted values (empty = any in range)
  bool required = false;                  ///< must be present (every boundary type)
  bool non_empty = false;                 ///< String: must not be ""
  std::array<Need, kBcTypeCount> need{};  ///< [[boundary]] keys: rule per BcType
  bool per_type = false;                  ///< `need` applies
};

/// A key plus how its value is stored in / fetched from `Target`.
template <class Target>
struct Key : KeyInfo {
  std::function<void(Target&, const Value&)> store;  ///< null: not stored
  std::function<Value(const Target&)> fetch;         ///< null: nothing to report
};

/// Top-level and section keys in file order ([curves] as the single Curve entry "curves.<name>").
const std::vector<Key<Config>>& global_keys();
/// Keys of one [[boundary]] entry.
const std::vector<Key<BoundaryCondition>>& boundary_keys();
/// Keys of one [[probe]] entry.
const std::vector<Key<ProbeConfig>>& probe_keys();

/// Largest number of points on a probe line.
inline constexpr std::int64_t kMaxProbePoints = 100000;

/// Boundary-type names in BcType order.
const std::vector<std::string>& bc_type_names();
const std::string& bc_type_name(BcType type);

/// Shortest round-trip text of a number, TOML style ("6.4", "18.0", "1e-8", "inf").
std::string format_number(double x);
/// A string in TOML basic-string quotes.
std::string quote(const std::string& text);
/// A Value as TOML-like text.
std::string format_value(const Value& value);
nlohmann::json value_to_json(const Value& value);

/// `items` joined by `separator`.
std::string join(const std::vector<std::string>& items, const std::string& separator);

}  // namespace biphasic::case_schema
