// Reading a case file: TOML parsing, --set overrides, validation against the schema in
// case_schema.cpp, and resolution into a Config.
#include "biphasic/io/case_file.hpp"

#include <toml++/toml.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "biphasic/material/material_laws.hpp"
#include "biphasic/time/time_integrator.hpp"
#include "case_schema.hpp"

namespace biphasic {

namespace {

using namespace case_schema;

const std::string kSetSource = "--set";

/// Collects problems as "<source>: <key> = <value>: <what>"; the source is "--set" for keys
/// set by an override, the case file otherwise.
class Problems {
 public:
  explicit Problems(std::string source) : source_(std::move(source)) {}

  void mark_overridden(const std::string& key) { overridden_.insert(key); }
  const std::string& source_of(const std::string& key) const {
    return overridden_.count(key) > 0 ? kSetSource : source_;
  }
  const std::string& source() const { return source_; }

  void bad_value(const std::string& key, const std::string& shown, const std::string& what) {
    const std::string k = aliased(key);
    bad_.insert(k);
    list_.push_back(source_of(k) + ": " + k + " = " + shown + ": " + aliased_text(what));
  }
  void bad_key(const std::string& key, const std::string& what) {
    const std::string k = aliased(key);
    bad_.insert(k);
    list_.push_back(source_of(k) + ": " + k + ": " + aliased_text(what));
  }
  void add(std::string message) { list_.push_back(std::move(message)); }

  bool is_bad(const std::string& key) const { return bad_.count(aliased(key)) > 0; }
  /// While set, keys and message text starting with `from` (e.g. "material.") are reported
  /// with `to` (e.g. "region[0].") instead: the [material] checks run on a [[region]] entry.
  void set_alias(std::string from, std::string to) {
    alias_from_ = std::move(from);
    alias_to_ = std::move(to);
  }
  bool empty() const { return list_.empty(); }
  std::vector<std::string> take() { return std::move(list_); }

 private:
  std::string source_;
  std::set<std::string> overridden_;
  std::set<std::string> bad_;
  std::vector<std::string> list_;
  std::string alias_from_, alias_to_;

  std::string aliased(const std::string& key) const {
    if (alias_from_.empty() || key.rfind(alias_from_, 0) != 0) return key;
    return alias_to_ + key.substr(alias_from_.size());
  }
  std::string aliased_text(std::string text) const {
    if (alias_from_.empty()) return text;
    for (auto at = text.find(alias_from_); at != std::string::npos;
         at = text.find(alias_from_, at + alias_to_.size())) {
      text.replace(at, alias_from_.size(), alias_to_);
    }
    return text;
  }
};

// ---- small helpers ------------------------------------------------------------------------

std::string trim(const std::string& text) {
  const char* space = " \t\r\n";
  auto first = text.find_first_not_of(space);
  if (first == std::string::npos) return "";
  auto last = text.find_last_not_of(space);
  return text.substr(first, last - first + 1);
}

std::string last_segment(const std::string& path) {
  auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The candidate the user most likely meant by `unknown`, or "" if none is close: a key with
/// the same last segment in another section, else the nearest by edit distance.
std::string suggest(const std::string& unknown, const std::vector<std::string>& candidates) {
  const std::string last = last_segment(unknown);
  for (const auto& c : candidates) {
    if (c != unknown && last_segment(c) == last) return c;
  }
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, last.size() / 3) + 1;
  for (const auto& c : candidates) {
    if (c == unknown) continue;
    const std::size_t d = edit_distance(unknown, c);
    if (d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string unknown_key_message(const std::string& key, const std::string& suggestion) {
  std::string out = "unknown key '" + key + "'";
  if (!suggestion.empty()) out += " (did you mean '" + suggestion + "'?)";
  return out;
}

/// A TOML node as compact TOML-like text, shortened if long.
std::string show(const toml::node& node) {
  std::string out;
  if (const auto* s = node.as_string()) {
    out = quote(s->get());
  } else if (const auto* i = node.as_integer()) {
    out = std::to_string(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    out = format_number(f->get());
  } else if (const auto* b = node.as_boolean()) {
    out = b->get() ? "true" : "false";
  } else if (const auto* a = node.as_array()) {
    std::vector<std::string> items;
    for (const auto& item : *a) items.push_back(show(item));
    out = "[" + join(items, ", ") + "]";
  } else if (const auto* t = node.as_table()) {
    std::vector<std::string> items;
    for (const auto& [k, v] : *t) items.push_back(std::string(k.str()) + " = " + show(v));
    out = items.empty() ? "{}" : "{ " + join(items, ", ") + " }";
  } else {
    std::ostringstream stream;
    if (const auto* d = node.as_date())
      stream << *d;
    else if (const auto* tm = node.as_time())
      stream << *tm;
    else if (const auto* dt = node.as_date_time())
      stream << *dt;
    out = stream.str();
  }
  constexpr std::size_t kMaxShown = 80;
  if (out.size() > kMaxShown) out = out.substr(0, kMaxShown - 3) + "...";
  return out;
}

std::optional<double> as_number(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

std::string with_unit(const std::string& text, const KeyInfo& key) {
  return key.unit.empty() ? text : text + " (" + key.unit + ")";
}

/// A value read from TOML, or why it is not acceptable.
struct Read {
  std::optional<Value> value;
  std::string problem;
};

Read fail(std::string problem) { return Read{std::nullopt, std::move(problem)}; }

Read read_integer(const toml::node& node, const KeyInfo& key) {
  const auto* integer = node.as_integer();
  if (integer == nullptr) return fail("expected an integer");
  const std::int64_t v = integer->get();
  if (!key.allowed.empty() &&
      std::find(key.allowed.begin(), key.allowed.end(), v) == key.allowed.end()) {
    if (key.allowed.size() == 1) return fail("must be " + std::to_string(key.allowed[0]));
    std::vector<std::string> items;
    for (auto a : key.allowed) items.push_back(std::to_string(a));
    return fail("must be one of " + join(items, ", "));
  }
  if (!key.range.contains(static_cast<double>(v))) {
    return fail(with_unit("must be " + key.range.describe(), key));
  }
  if (v > INT_MAX || v < INT_MIN)
    return fail("is too large (limit " + std::to_string(INT_MAX) + ")");
  return Read{Value{v}, {}};
}

Read read_number(const toml::node& node, const KeyInfo& key) {
  const auto v = as_number(node);
  if (!v) return fail("expected a number");
  if (!std::isfinite(*v)) return fail("must be a finite number");
  if (!key.range.contains(*v)) return fail(with_unit("must be " + key.range.describe(), key));
  return Read{Value{*v}, {}};
}

Read read_vector(const toml::node& node, const KeyInfo& key) {
  const auto* array = node.as_array();
  if (array == nullptr || array->size() != 3) return fail("expected an array of 3 numbers");
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto v = as_number((*array)[i]);
    if (!v) return fail("expected an array of 3 numbers");
    if (!std::isfinite(*v)) return fail("components must be finite numbers");
    if (!key.range.contains(*v)) {
      return fail(with_unit("components must be " + key.range.describe(), key));
    }
    out[i] = *v;
  }
  return Read{Value{out}, {}};
}

Read read_number_list(const toml::node& node, const KeyInfo& key) {
  const auto* array = node.as_array();
  if (array == nullptr) return fail("expected an array of numbers");
  std::vector<double> out;
  for (const auto& item : *array) {
    const auto v = as_number(item);
    if (!v) return fail("expected an array of numbers");
    if (!std::isfinite(*v)) return fail("entries must be finite numbers");
    if (!key.range.contains(*v))
      return fail(with_unit("entries must be " + key.range.describe(), key));
    out.push_back(*v);
  }
  return Read{Value{out}, {}};
}

Read read_string_list(const toml::node& node, const KeyInfo& key) {
  const auto* array = node.as_array();
  if (array == nullptr) return fail("expected an array of strings");
  std::vector<std::string> out;
  for (const auto& item : *array) {
    const auto* s = item.as_string();
    if (s == nullptr) return fail("expected an array of strings");
    const std::string& text = s->get();
    if (!key.choices.empty() &&
        std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end()) {
      return fail(quote(text) + " is not one of " + join(key.choices, ", "));
    }
    if (std::find(out.begin(), out.end(), text) != out.end()) {
      return fail(quote(text) + " is listed twice");
    }
    out.push_back(text);
  }
  return Read{Value{out}, {}};
}

/// A formula: a string that parses, or a number (taken as that constant).
Read read_expression(const toml::node& node) {
  std::string text;
  if (const auto* s = node.as_string()) {
    text = s->get();
  } else if (const auto v = as_number(node)) {
    if (!std::isfinite(*v)) return fail("must be a finite number");
    text = format_number(*v);
  } else {
    return fail("expected a formula (a string such as \"0.1 * sin(pi * x) * t\") or a number");
  }
  try {
    Expression::parse(text);
  } catch (const ExpressionError& error) {
    return fail(error.what());
  }
  return Read{Value{text}, {}};
}

/// Reads `node` as the kind of value `key` holds and checks its range or choices.
Read read_value(const toml::node& node, const KeyInfo& key) {
  switch (key.kind) {
    case Kind::Integer:
      return read_integer(node, key);
    case Kind::Number:
      return read_number(node, key);
    case Kind::Boolean: {
      const auto* b = node.as_boolean();
      if (b == nullptr) return fail("expected true or false");
      return Read{Value{b->get()}, {}};
    }
    case Kind::String:
    case Kind::Choice: {
      const auto* s = node.as_string();
      if (s == nullptr) return fail("expected a string");
      const std::string& text = s->get();
      if (key.non_empty && text.empty()) return fail("must not be empty");
      if (key.kind == Kind::Choice &&
          std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end()) {
        return fail("must be one of " + join(key.choices, ", "));
      }
      return Read{Value{text}, {}};
    }
    case Kind::Vector3:
      return read_vector(node, key);
    case Kind::StringList:
      return read_string_list(node, key);
    case Kind::NumberList:
      return read_number_list(node, key);
    case Kind::Selection: {
      if (const auto* b = node.as_boolean()) return Read{Value{b->get()}, {}};
      if (node.as_array() == nullptr)
        return fail("expected true or false, or an array of names (each one of " +
                    join(key.choices, ", ") + ")");
      return read_string_list(node, key);
    }
    case Kind::Expression:
      return read_expression(node);
    case Kind::Curve:
      break;
  }
  return fail("cannot be read");
}

/// The node at dotted `path` below `root`, or nullptr if it or a parent table is absent.
const toml::node* find_path(const toml::table& root, const std::string& path) {
  const toml::table* table = &root;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const toml::node* node = table->get(path.substr(start, dot - start));
    if (node == nullptr || dot == std::string::npos) return node;
    table = node->as_table();
    if (table == nullptr) return nullptr;
    start = dot + 1;
  }
}

// ---- what the schema knows --------------------------------------------------------------

struct KnownPaths {
  std::set<std::string> leaves;             ///< global keys that hold values
  std::set<std::string> tables;             ///< sections (and subsections) of global keys
  std::vector<std::string> candidates;      ///< everything a top-level key may be, for suggestions
  std::vector<std::string> boundary_names;  ///< keys of a [[boundary]] entry
  std::vector<std::string> probe_names;     ///< keys of a [[probe]] entry
  std::vector<std::string> region_names;    ///< keys of a [[region]] entry
};

const KnownPaths& known_paths() {
  static const KnownPaths known = [] {
    KnownPaths k;
    for (const auto& key : global_keys()) {
      if (key.kind == Kind::Curve) continue;
      k.leaves.insert(key.path);
      for (auto dot = key.path.find('.'); dot != std::string::npos;
           dot = key.path.find('.', dot + 1)) {
        k.tables.insert(key.path.substr(0, dot));
      }
    }
    k.candidates.assign(k.leaves.begin(), k.leaves.end());
    k.candidates.insert(k.candidates.end(), k.tables.begin(), k.tables.end());
    k.candidates.push_back("curves");
    k.candidates.push_back("boundary");
    for (const auto& key : boundary_keys()) k.boundary_names.push_back(key.path);
    k.candidates.push_back("probe");
    for (const auto& key : probe_keys()) k.probe_names.push_back(key.path);
    k.candidates.push_back("region");
    k.region_names.push_back("name");
    for (const auto& key : global_keys())
      if (key.path.rfind("material.", 0) == 0) k.region_names.push_back(key.path.substr(9));
    return k;
  }();
  return known;
}

std::vector<std::string> prefixed(const std::string& prefix,
                                  const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& n : names) out.push_back(prefix + n);
  return out;
}

/// Reports keys the schema does not know, at every level of the global sections.
void check_unknown_keys(const toml::table& table, const std::string& prefix, Problems& problems) {
  const auto& known = known_paths();
  for (const auto& [k, node] : table) {
    const std::string path =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (known.leaves.count(path) > 0 || path == "curves" || path == "boundary" || path == "probe" ||
        path == "region")
      continue;
    if (known.tables.count(path) > 0) {
      if (const auto* sub = node.as_table()) {
        check_unknown_keys(*sub, path, problems);
      } else {
        problems.bad_value(path, show(node), "expected a table ([" + path + "])");
      }
      continue;
    }
    problems.add(problems.source() + ": " +
                 unknown_key_message(path, suggest(path, known.candidates)));
  }
}

// ---- overrides ----------------------------------------------------------------------------

/// Parses the text after '=' as a TOML value; text that is not TOML is taken as a string.
toml::table override_value(const std::string& text) {
  try {
    toml::table parsed = toml::parse("v = " + text, kSetSource);
    if (parsed.size() == 1 && parsed.contains("v")) return parsed;
  } catch (const toml::parse_error&) {
  }
  toml::table bare;
  bare.insert_or_assign("v", text);
  return bare;
}

/// Applies one "key=value"; returns a problem, or "" when applied.
std::string apply_override(toml::table& root, const std::string& argument, Problems& problems) {
  const std::string where = kSetSource + " " + argument + ": ";
  const auto eq = argument.find('=');
  if (eq == std::string::npos) return where + "expected key=value";
  const std::string key = trim(argument.substr(0, eq));
  if (key.empty()) return where + "expected key=value (the key is empty)";
  const toml::table parsed = override_value(trim(argument.substr(eq + 1)));
  const toml::node& value = *parsed.get("v");
  const auto& known = known_paths();

  // Entries of an array of tables: boundary[i].key, probe[i].key.
  for (const auto& [array_name, names] : {std::pair{std::string("boundary"), &known.boundary_names},
                                          std::pair{std::string("probe"), &known.probe_names},
                                          std::pair{std::string("region"), &known.region_names}}) {
    if (key.rfind(array_name + "[", 0) != 0) continue;
    const auto close = key.find(']');
    const std::size_t first = array_name.size() + 1;
    const std::string index_text =
        close == std::string::npos ? std::string{} : key.substr(first, close - first);
    std::size_t index = 0;
    const auto [end, error] =
        std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
    if (index_text.empty() || error != std::errc{} ||
        end != index_text.data() + index_text.size()) {
      return where + "'" + key + "' needs " + array_name + "[i].key with i a number from 0";
    }
    const std::string name =
        close + 1 < key.size() && key[close + 1] == '.' ? key.substr(close + 2) : std::string{};
    const std::string entry = array_name + "[" + std::to_string(index) + "]";
    if (std::find(names->begin(), names->end(), name) == names->end()) {
      const std::string full = entry + "." + name;
      return where + unknown_key_message(full, suggest(full, prefixed(entry + ".", *names)));
    }
    auto* array = root[array_name].as_array();
    const std::size_t count = array == nullptr ? 0 : array->size();
    if (index >= count) {
      return where + "index " + std::to_string(index) + " is out of range (the case has " +
             std::to_string(count) + " [[" + array_name + "]] entr" + (count == 1 ? "y)" : "ies)");
    }
    auto* table = (*array)[index].as_table();
    if (table == nullptr) return where + entry + " is not a table";
    table->insert_or_assign(name, value);
    problems.mark_overridden(entry + "." + name);
    return "";
  }

  std::vector<std::string> parts;
  if (key.rfind("curves.", 0) == 0 && key.size() > 7) {
    parts = {"curves", key.substr(7)};
  } else if (known.leaves.count(key) > 0) {
    std::size_t start = 0;
    for (auto dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
      parts.push_back(key.substr(start, dot - start));
      start = dot + 1;
    }
    parts.push_back(key.substr(start));
  } else if (known.tables.count(key) > 0 || key == "curves" || key == "boundary" ||
             key == "probe" || key == "region") {
    return where + "'" + key + "' is a table; set the keys inside it instead (e.g. " +
           (key == "curves"     ? std::string("curves.ramp")
            : key == "boundary" ? std::string("boundary[0].value")
            : key == "probe"    ? std::string("probe[0].points")
            : key == "region"   ? std::string("region[0].permeability")
                                : *known.leaves.lower_bound(key + ".")) +
           ")";
  } else {
    std::vector<std::string> candidates = known.candidates;
    candidates.push_back("curves.<name>");
    return where + unknown_key_message(key, suggest(key, candidates));
  }

  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i]);
    if (next == nullptr) {
      next = table->insert_or_assign(parts[i], toml::table{}).first->second.as_table();
    }
    table = next->as_table();
    if (table == nullptr) return where + "'" + parts[i] + "' in the case file is not a table";
  }
  table->insert_or_assign(parts.back(), value);
  problems.mark_overridden(key);
  return "";
}

// ---- sections ------------------------------------------------------------------------------

void read_global_keys(const toml::table& root, Config& config, Problems& problems) {
  for (const auto& key : global_keys()) {
    if (key.kind == Kind::Curve) continue;
    const toml::node* node = find_path(root, key.path);
    if (node == nullptr) {
      if (key.required) problems.bad_key(key.path, "required key is missing");
      continue;
    }
    const Read read = read_value(*node, key);
    if (!read.value) {
      problems.bad_value(key.path, show(*node), read.problem);
    } else if (key.store) {
      key.store(config, *read.value);
    }
  }
}

/// Reads [curves]; `names` receives every curve name given, valid or not.
void read_curves(const toml::table& root, Config& config, std::set<std::string>& names,
                 Problems& problems) {
  const toml::node* node = root.get("curves");
  if (node == nullptr) return;
  const auto* table = node->as_table();
  if (table == nullptr) {
    problems.bad_value("curves", show(*node), "expected a table of named curves ([curves])");
    return;
  }
  for (const auto& [k, value] : *table) {
    const std::string name(k.str());
    const std::string key = "curves." + name;
    names.insert(name);
    const auto* array = value.as_array();
    if (array == nullptr) {
      problems.bad_value(key, show(value), "expected an array of [t, value] points");
      continue;
    }
    if (array->empty()) {
      problems.bad_value(key, show(value), "needs at least one [t, value] point");
      continue;
    }
    LoadCurve curve;
    std::string problem;
    for (const auto& item : *array) {
      const auto* point = item.as_array();
      std::optional<double> t;
      std::optional<double> v;
      if (point != nullptr && point->size() == 2) {
        t = as_number((*point)[0]);
        v = as_number((*point)[1]);
      }
      if (!t || !v) {
        problem = "expected [t, value] pairs of numbers, got " + show(item);
        break;
      }
      if (!std::isfinite(*t) || !std::isfinite(*v)) {
        problem = "point " + show(item) + " is not finite";
        break;
      }
      if (!curve.points.empty() && !(*t > curve.points.back().first)) {
        problem = "times must be strictly increasing, but t = " + format_number(*t) +
                  " follows t = " + format_number(curve.points.back().first);
        break;
      }
      curve.points.emplace_back(*t, *v);
    }
    if (problem.empty()) {
      config.curves[name] = std::move(curve);
    } else {
      problems.bad_value(key, show(value), problem);
    }
  }
}

std::optional<BcType> read_bc_type(const toml::table& entry) {
  const toml::node* node = entry.get("type");
  if (node == nullptr || node->as_string() == nullptr) return std::nullopt;
  const auto& names = bc_type_names();
  const auto it = std::find(names.begin(), names.end(), node->as_string()->get());
  if (it == names.end()) return std::nullopt;
  return static_cast<BcType>(it - names.begin());
}

void read_boundaries(const toml::table& root, const std::set<std::string>& curve_names,
                     Config& config, Problems& problems) {
  const toml::node* node = root.get("boundary");
  if (node == nullptr) {
    problems.bad_key("boundary", "at least one [[boundary]] entry is required");
    return;
  }
  const auto* array = node->as_array();
  if (array == nullptr) {
    problems.bad_value("boundary", show(*node), "expected [[boundary]] tables");
    return;
  }
  if (array->empty()) {
    problems.bad_key("boundary", "at least one [[boundary]] entry is required");
    return;
  }
  const auto& known = known_paths();
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string entry = "boundary[" + std::to_string(i) + "]";
    const auto* table = (*array)[i].as_table();
    if (table == nullptr) {
      problems.bad_value(entry, show((*array)[i]), "expected a table");
      continue;
    }
    for (const auto& [k, value] : *table) {
      const std::string name(k.str());
      if (std::find(known.boundary_names.begin(), known.boundary_names.end(), name) ==
          known.boundary_names.end()) {
        const std::string full = entry + "." + name;
        problems.add(
            problems.source_of(full) + ": " +
            unknown_key_message(full, suggest(full, prefixed(entry + ".", known.boundary_names))));
      }
    }
    const std::optional<BcType> type = read_bc_type(*table);
    BoundaryCondition bc;
    for (const auto& key : boundary_keys()) {
      const std::string full = entry + "." + key.path;
      const Need need =
          key.per_type && type ? key.need[static_cast<std::size_t>(*type)] : Need::Optional;
      const toml::node* value = table->get(key.path);
      if (value == nullptr) {
        if (key.required) {
          problems.bad_key(full, "required key is missing");
        } else if (need == Need::Required) {
          problems.bad_key(full, "required for type " + quote(bc_type_name(*type)));
        }
        continue;
      }
      if (need == Need::Forbidden) {
        problems.bad_value(full, show(*value),
                           "not allowed for type " + quote(bc_type_name(*type)));
        continue;
      }
      const Read read = read_value(*value, key);
      if (!read.value) {
        problems.bad_value(full, show(*value), read.problem);
      } else {
        key.store(bc, *read.value);
      }
    }
    if (!bc.curve.empty() && curve_names.count(bc.curve) == 0) {
      const std::vector<std::string> defined(curve_names.begin(), curve_names.end());
      problems.bad_value(entry + ".curve", quote(bc.curve),
                         defined.empty() ? "no such curve (no curves are defined)"
                                         : "no such curve (defined: " + join(defined, ", ") + ")");
    }
    config.bcs.push_back(bc);
  }
}

/// Reads [[probe]] entries: keys as the schema says, names usable in a file name and distinct,
/// start != end, points != 1.
void read_probes(const toml::table& root, Config& config, Problems& problems) {
  const toml::node* node = root.get("probe");
  if (node == nullptr) return;
  const auto* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    problems.bad_value("probe", show(*node), "expected [[probe]] tables");
    return;
  }
  const auto& known = known_paths();
  std::set<std::string> names;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string entry = "probe[" + std::to_string(i) + "]";
    const auto& table = *(*array)[i].as_table();
    for (const auto& [k, value] : table) {
      const std::string name(k.str());
      if (std::find(known.probe_names.begin(), known.probe_names.end(), name) ==
          known.probe_names.end()) {
        const std::string full = entry + "." + name;
        problems.add(
            problems.source_of(full) + ": " +
            unknown_key_message(full, suggest(full, prefixed(entry + ".", known.probe_names))));
      }
    }
    ProbeConfig probe;
    bool complete = true;
    for (const auto& key : probe_keys()) {
      const std::string full = entry + "." + key.path;
      const toml::node* value = table.get(key.path);
      if (value == nullptr) {
        if (key.required) {
          problems.bad_key(full, "required key is missing");
          complete = false;
        }
        continue;
      }
      const Read read = read_value(*value, key);
      if (!read.value) {
        problems.bad_value(full, show(*value), read.problem);
        complete = false;
      } else {
        key.store(probe, *read.value);
      }
    }
    if (!problems.is_bad(entry + ".name") && !probe.name.empty()) {
      const bool usable = std::all_of(probe.name.begin(), probe.name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
      });
      if (!usable) {
        problems.bad_value(entry + ".name", quote(probe.name),
                           "may hold only letters, digits, '_' and '-' (it names the file "
                           "probe_<name>.csv)");
        complete = false;
      } else if (!names.insert(probe.name).second) {
        problems.bad_value(entry + ".name", quote(probe.name), "another [[probe]] has this name");
        complete = false;
      }
    }
    if (!problems.is_bad(entry + ".start") && !problems.is_bad(entry + ".end") &&
        table.get("start") != nullptr && table.get("end") != nullptr && probe.start == probe.end) {
      problems.bad_value(entry + ".end", format_value(probe.end), "must differ from start");
      complete = false;
    }
    if (probe.points == 1) {
      problems.bad_value(entry + ".points", "1",
                         "must be 0 (mesh nodes, or 101 points) or at least 2");
      complete = false;
    }
    if (complete) config.output.probes.push_back(probe);
  }
}

std::string resolve_against(const std::string& file, const std::string& base_dir) {
  std::filesystem::path path(file);
  if (path.is_relative() && !base_dir.empty()) path = std::filesystem::path(base_dir) / path;
  return path.lexically_normal().string();
}

/// The value at `path` as written, or `fallback` (the default in use) when absent.
std::string shown_at(const toml::table& root, const std::string& path,
                     const std::string& fallback) {
  const toml::node* node = find_path(root, path);
  return node == nullptr ? fallback : show(*node);
}

// A key that applies only to some values of a choice key (mesh.source,
// material.permeability_law): `owner` names those values for the message.
template <class Choice>
struct OwnedKey {
  const char* path;
  std::vector<Choice> owners;
  const char* owner;
};

// Each key of `rules` given although `chosen` is not one of its owners is an input error naming
// the values it applies to and the one chosen (shown as written, or `chosen_default`).
template <class Choice>
void refuse_keys_of_other_choices(const toml::table& root, Problems& problems,
                                  const char* choice_key, const char* chosen_default, Choice chosen,
                                  const std::vector<OwnedKey<Choice>>& rules) {
  if (problems.is_bad(choice_key)) return;
  const std::string shown = shown_at(root, choice_key, chosen_default);
  for (const OwnedKey<Choice>& rule : rules) {
    const toml::node* node = find_path(root, rule.path);
    if (node == nullptr || problems.is_bad(rule.path) ||
        std::find(rule.owners.begin(), rule.owners.end(), chosen) != rule.owners.end()) {
      continue;
    }
    problems.bad_value(
        rule.path, show(*node),
        std::string("applies only to ") + rule.owner + ", not to " + choice_key + " = " + shown);
  }
}

/// `"a"`, `"a" and "b"`, `"a", "b" and "c"`.
std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + quote(names[i]);
  }
  return out;
}

/// The material section's law choices and parameters against the registered laws
/// (material_laws.hpp): a parameter no chosen law reads is an error naming the laws that read
/// it (it would be ignored), and each chosen law's own checks across its parameters run.
void check_material_laws(const toml::table& root, const MaterialConfig& material,
                         Problems& problems) {
  const auto& families = material_law_families();
  for (const LawFamily& family : families) {
    if (problems.is_bad("material." + family.key)) return;
  }
  auto chosen_law = [&material](const LawFamily& family) -> const LawDescription* {
    for (const LawDescription& law : family.laws) {
      if (law.name == material.*family.chosen) return &law;
    }
    return nullptr;
  };
  std::set<std::string> visited;
  for (const LawFamily& family : families) {
    for (const LawDescription& law : family.laws) {
      for (const LawParameter& parameter : law.parameters) {
        const std::string path = "material." + parameter.name;
        const toml::node* node = find_path(root, path);
        if (!visited.insert(parameter.name).second || node == nullptr || problems.is_bad(path))
          continue;
        std::vector<std::string> owners, chosen;
        bool read = false;
        for (const LawFamily& f : families) {
          std::vector<std::string> readers;
          for (const LawDescription& l : f.laws) {
            if (l.reads(parameter.name)) readers.push_back(l.name);
          }
          if (readers.empty()) continue;
          const LawDescription* c = chosen_law(f);
          read = read || (c != nullptr && c->reads(parameter.name));
          owners.push_back("material." + f.key + " = " + quoted_list(readers));
          chosen.push_back("material." + f.key + " = " +
                           shown_at(root, "material." + f.key, quote(f.laws.front().name)));
        }
        if (read) continue;
        std::string owner_text, chosen_text;
        for (std::size_t i = 0; i < owners.size(); ++i) {
          owner_text += (i == 0 ? "" : " or ") + owners[i];
          chosen_text += (i == 0 ? "" : " or ") + chosen[i];
        }
        problems.bad_value(path, show(*node),
                           "applies only to " + owner_text + ", not to " + chosen_text);
      }
    }
  }
  const ParameterSource source = [&material](const std::string& name) {
    return material.get(name);
  };
  for (const LawFamily& family : families) {
    const LawDescription* law = chosen_law(family);
    if (law == nullptr || !law->check) continue;
    const bool clean = std::none_of(
        law->parameters.begin(), law->parameters.end(),
        [&problems](const LawParameter& p) { return problems.is_bad("material." + p.name); });
    if (!clean) continue;
    if (const auto problem = law->check(source, "material.")) {
      const std::string path = "material." + problem->key;
      problems.bad_value(path, shown_at(root, path, format_number(material.get(problem->key))),
                         problem->message);
    }
  }
}

/// mesh.column.region_names and region_tops: equal lengths, tops increasing, each a layer
/// interface (column_layer_z), the last = the height.
void check_column_regions(const toml::table& root, const ColumnSpec& column, Problems& problems) {
  const auto& names = column.region_names;
  const auto& tops = column.region_tops;
  if (names.empty() && tops.empty()) return;
  const std::string shown = shown_at(root, "mesh.column.region_tops", format_value(tops));
  if (names.size() != tops.size()) {
    problems.bad_value("mesh.column.region_tops", shown,
                       "needs one top per name of mesh.column.region_names (" +
                           std::to_string(names.size()) + " names, " + std::to_string(tops.size()) +
                           " tops)");
    return;
  }
  std::vector<double> z;
  try {
    z = column_layer_z(column);
  } catch (const std::exception&) {
    return;  // the layer keys themselves are reported
  }
  const double tolerance = 1e-9 * column.height;
  for (std::size_t r = 0; r < tops.size(); ++r) {
    const bool interface = std::any_of(
        z.begin() + 1, z.end(), [&](double zk) { return std::abs(zk - tops[r]) <= tolerance; });
    std::string why;
    if (r > 0 && !(tops[r] > tops[r - 1])) {
      why = "must increase (entry " + std::to_string(r) + ")";
    } else if (!interface) {
      why = "entry " + std::to_string(r) + " = " + format_number(tops[r]) +
            " mm is not a layer interface of the column (mesh.column.nz, grading)";
    } else if (r + 1 == tops.size() && std::abs(tops[r] - column.height) > tolerance) {
      why = "the last entry must be mesh.column.height = " + format_number(column.height) + " mm";
    }
    if (!why.empty()) {
      problems.bad_value("mesh.column.region_tops", shown, why);
      return;
    }
  }
}

/// Keys that belong to one or more mesh sources: given with another generated source they would
/// be silently ignored, so they are an error. (The quarter cylinder's keys are tolerated with
/// mesh.source = "file", as they always were.)
void check_mesh_source_keys(const toml::table& root, const Config& config, Problems& problems) {
  using S = MeshSource;
  constexpr const char* kCylinder = "mesh.source = \"quarter_cylinder\"";
  static const std::vector<OwnedKey<S>> rules{
      {"mesh.radius", {S::QuarterCylinder, S::File}, kCylinder},
      {"mesh.height", {S::QuarterCylinder, S::File}, kCylinder},
      {"mesh.lc", {S::QuarterCylinder, S::File}, kCylinder},
      {"mesh.grading_faces", {S::QuarterCylinder, S::File}, kCylinder},
      {"mesh.grading_ratio", {S::QuarterCylinder, S::File}, kCylinder},
      {"mesh.grading_distance", {S::QuarterCylinder, S::File}, kCylinder},
      {"mesh.layers", {S::QuarterCylinder}, kCylinder},
      {"mesh.layer_grading_faces", {S::QuarterCylinder}, kCylinder},
      {"mesh.layer_grading_ratio", {S::QuarterCylinder}, kCylinder},
      {"mesh.write_msh",
       {S::QuarterCylinder, S::SphereOctant, S::File},
       "meshes generated by gmsh (quarter_cylinder, sphere_octant)"},
      {"mesh.column", {S::Column}, "mesh.source = \"column\""},
      {"mesh.sphere_octant", {S::SphereOctant}, "mesh.source = \"sphere_octant\""},
      {"mesh.section", {S::Section}, "mesh.source = \"section\""},
  };
  refuse_keys_of_other_choices(root, problems, "mesh.source", "\"quarter_cylinder\"",
                               config.mesh.source, rules);
  if (problems.is_bad("mesh.source")) return;

  // Too few layers for a grading toward one face (2) or both (3): generate_column's rule, which
  // column_layer_z applies to the column and to the swept quarter cylinder alike.
  auto check_graded_layers = [&](const char* layers_key, int layers, const char* faces_key,
                                 const std::vector<std::string>& faces, const char* ratio_key,
                                 double ratio) {
    if (problems.is_bad(layers_key) || problems.is_bad(faces_key) || problems.is_bad(ratio_key) ||
        ratio <= 1.0 || faces.empty())
      return;
    const int needed = faces.size() == 2 ? 3 : 2;
    if (layers < needed) {
      problems.bad_value(layers_key, std::to_string(layers),
                         "must be >= " + std::to_string(needed) + " to grade the layers toward " +
                             format_value(faces));
    }
  };

  // A swept quarter cylinder is graded by its layers, not by the unstructured size field.
  const QuarterCylinderSpec& cylinder = config.mesh.cylinder;
  if (config.mesh.source == S::QuarterCylinder && !problems.is_bad("mesh.layers")) {
    if (cylinder.layers > 0 && !cylinder.grading_faces.empty()) {
      problems.bad_value("mesh.grading_faces", format_value(cylinder.grading_faces),
                         "a swept mesh (mesh.layers > 0) is graded by mesh.layer_grading_faces");
    }
    if (cylinder.layers == 0 && !cylinder.layer_grading_faces.empty()) {
      problems.bad_value("mesh.layer_grading_faces", format_value(cylinder.layer_grading_faces),
                         "needs a swept mesh (mesh.layers > 0)");
    }
    if (cylinder.layers > 0) {
      check_graded_layers("mesh.layers", cylinder.layers, "mesh.layer_grading_faces",
                          cylinder.layer_grading_faces, "mesh.layer_grading_ratio",
                          cylinder.layer_grading_ratio);
    }
  }
  const ColumnSpec& column = config.mesh.column;
  if (config.mesh.source == S::Column && !problems.is_bad("mesh.column.region_names") &&
      !problems.is_bad("mesh.column.region_tops")) {
    check_column_regions(root, column, problems);
  }
  if (config.mesh.source == S::Section) {
    const SectionRectangleSpec& section = config.mesh.section;
    auto toward = [&](std::initializer_list<const char*> ends) {
      std::vector<std::string> out;
      for (const char* end : ends)
        if (std::find(section.grading_curves.begin(), section.grading_curves.end(), end) !=
            section.grading_curves.end())
          out.push_back(end);
      return out;
    };
    check_graded_layers("mesh.section.nr", section.nr, "mesh.section.grading_curves",
                        toward({"axis", "lateral"}), "mesh.section.grading_ratio",
                        section.grading_ratio);
    check_graded_layers("mesh.section.nz", section.nz, "mesh.section.grading_curves",
                        toward({"bottom", "top"}), "mesh.section.grading_ratio",
                        section.grading_ratio);
  }
  if (config.mesh.source == S::Column) {
    check_graded_layers("mesh.column.nz", column.nz, "mesh.column.grading_faces",
                        column.grading_faces, "mesh.column.grading_ratio", column.grading_ratio);
    // generate_column's limit, named by the keys before any work (with the memory estimate
    // ignored, nothing else stops such a column before the generator).
    // In double: three counts up to 2^31 each would overflow 64 bits.
    const double cells = static_cast<double>(column.nx) * column.ny * column.nz;
    if (!problems.is_bad("mesh.column.nx") && !problems.is_bad("mesh.column.ny") &&
        !problems.is_bad("mesh.column.nz") && cells > static_cast<double>(kMaxColumnCells)) {
      char count[32];
      std::snprintf(count, sizeof count, "%.0f", cells);
      problems.bad_key("mesh.column.nx, mesh.column.ny, mesh.column.nz",
                       std::to_string(column.nx) + " * " + std::to_string(column.ny) + " * " +
                           std::to_string(column.nz) + " = " + count +
                           " cells is more than the limit of " + std::to_string(kMaxColumnCells));
    }
  }
}

/// Every boundary in output.reactions must carry a displacement, symmetry or rigid-platen
/// condition (else nothing holds it and its reaction is zero by definition).
void check_reaction_boundaries(const toml::table& root, const Config& config, Problems& problems) {
  if (problems.is_bad("output.reactions")) return;
  for (const std::string& name : config.output.reactions) {
    const bool held = std::any_of(config.bcs.begin(), config.bcs.end(), [&](const auto& bc) {
      return bc.boundary == name && (bc.type == BcType::Displacement ||
                                     bc.type == BcType::Symmetry || bc.type == BcType::RigidPlaten);
    });
    if (!held) {
      problems.bad_value(
          "output.reactions",
          shown_at(root, "output.reactions", format_value(config.output.reactions)),
          quote(name) + " has no displacement, symmetry or rigid_platen condition, so no reaction");
    }
  }
}

/// Reads [[region]] entries: a name, distinct and not empty, and the keys of [material], each
/// omitted key inherited from [material]. The [material] checks run on the entry with its keys
/// named region[i].key: the entry is read as a [material] table (its choice keys, when it does
/// not give them, taken from [material]) under the alias "material." → "region[i].".
void read_regions(const toml::table& root, Config& config, Problems& problems) {
  const toml::node* node = root.get("region");
  if (node == nullptr) return;
  const auto* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    problems.bad_value("region", show(*node), "expected [[region]] tables");
    return;
  }
  const auto& known = known_paths();
  std::set<std::string> names;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string entry = "region[" + std::to_string(i) + "]";
    const auto& table = *(*array)[i].as_table();
    for (const auto& [k, value] : table) {
      const std::string name(k.str());
      if (std::find(known.region_names.begin(), known.region_names.end(), name) ==
          known.region_names.end()) {
        const std::string full = entry + "." + name;
        problems.add(
            problems.source_of(full) + ": " +
            unknown_key_message(full, suggest(full, prefixed(entry + ".", known.region_names))));
      }
    }
    RegionConfig region;
    bool named = false;
    const toml::node* name_node = table.get("name");
    if (name_node == nullptr) {
      problems.bad_key(entry + ".name", "required key is missing");
    } else if (name_node->as_string() == nullptr || name_node->as_string()->get().empty()) {
      problems.bad_value(entry + ".name", show(*name_node),
                         "expected the name of a mesh region (a non-empty string)");
    } else {
      region.name = name_node->as_string()->get();
      named = names.insert(region.name).second;
      if (!named) {
        problems.bad_value(entry + ".name", quote(region.name), "another [[region]] has this name");
      }
    }

    toml::table material = table;
    material.erase("name");
    for (const LawFamily& family : material_law_families()) {
      const std::string path = "material." + family.key;
      const toml::node* inherited = find_path(root, path);
      if (material.get(family.key) == nullptr && inherited != nullptr && !problems.is_bad(path) &&
          inherited->as_string() != nullptr) {
        material.insert_or_assign(family.key, inherited->as_string()->get());
      }
    }
    toml::table shaped;
    shaped.insert_or_assign("material", std::move(material));
    Config one;
    one.material = config.material;
    problems.set_alias("material.", entry + ".");
    for (const auto& key : global_keys()) {
      if (key.path.rfind("material.", 0) != 0) continue;
      const toml::node* value = find_path(shaped, key.path);
      if (value == nullptr) continue;
      const Read read = read_value(*value, key);
      if (!read.value) {
        problems.bad_value(key.path, show(*value), read.problem);
      } else if (key.store) {
        key.store(one, *read.value);
      }
    }
    check_material_laws(shaped, one.material, problems);
    problems.set_alias("", "");
    region.material = one.material;
    if (named) config.regions.push_back(region);
  }
}

/// A two-dimensional model needs a section mesh (mesh.source = "section" or a .msh file of
/// triangles) and data in the plane: no z components, probe points at z = 0; a section mesh
/// needs a two-dimensional model.
void check_model(const toml::table& root, const Config& config, Problems& problems) {
  if (problems.is_bad("model") || problems.is_bad("mesh.source")) return;
  const bool planar = is_two_dimensional(config.model);
  const std::string model = quote(to_string(config.model));
  if (!planar) {
    if (config.mesh.source == MeshSource::Section)
      problems.bad_value("mesh.source", "\"section\"",
                         "needs a two-dimensional model (model = \"axisymmetric\" or "
                         "\"plane_strain\")");
    return;
  }
  if (config.mesh.source != MeshSource::Section && config.mesh.source != MeshSource::File) {
    problems.bad_value("mesh.source", shown_at(root, "mesh.source", "\"quarter_cylinder\""),
                       "model = " + model + " needs a section mesh: \"section\" or \"file\"");
  }
  if (config.stabilisation.gls_quadrature == GlsQuadrature::OnePoint)
    problems.bad_value("stabilisation.gls_quadrature", "\"one_point\"",
                       "model = " + model + " integrates the GLS term with its full rule only");
  for (std::size_t i = 0; i < config.bcs.size(); ++i) {
    const BoundaryCondition& bc = config.bcs[i];
    const std::string entry = "boundary[" + std::to_string(i) + "]";
    if ((bc.type == BcType::Displacement || bc.type == BcType::RigidPlaten) && bc.component == 2)
      problems.bad_value(entry + ".component", "\"z\"",
                         "model = " + model + " has components x and y only");
    if (bc.type == BcType::Traction && bc.vector[2] != 0.0)
      problems.bad_value(entry + ".vector", format_value(bc.vector),
                         "model = " + model + " has no z component");
  }
  if (!config.loads.body_force[2].is_zero())
    problems.bad_value("body_force.z", quote(config.loads.body_force[2].text()),
                       "model = " + model + " has no z component");
  for (const char* key : {"output.line_start", "output.line_end"}) {
    const auto& x =
        std::string(key) == "output.line_start" ? config.output.line_start : config.output.line_end;
    if (config.output.line && x[2] != 0.0 && !problems.is_bad(key))
      problems.bad_value(key, shown_at(root, key, format_value(x)),
                         "model = " + model + ": points lie in the plane z = 0");
  }
}

/// The iterative solver's block preconditioner treats every tied row as a Dirichlet row and has
/// no place for a platen's force row (dense over the platen's neighbourhood, it would sit in the
/// displacement block's multigrid): rigid platens need a direct solver, on any number of
/// processes.
void check_platen_solver(const toml::table& root, const Config& config, Problems& problems) {
  if (problems.is_bad("linear_solver.type") ||
      config.linear_solver.type != LinearSolverType::Iterative)
    return;
  for (std::size_t i = 0; i < config.bcs.size(); ++i)
    if (config.bcs[i].type == BcType::RigidPlaten) {
      problems.bad_value("linear_solver.type",
                         shown_at(root, "linear_solver.type", "\"iterative\""),
                         "boundary[" + std::to_string(i) +
                             "] is a rigid_platen, which needs a direct solver (\"klu\", "
                             "\"umfpack\" or \"mumps\"; on several processes \"mumps\" or "
                             "\"superlu_dist\")");
      return;
    }
}

/// Out-of-core MUMPS factors need MUMPS and a folder MUMPS can write to; the folder defaults to
/// $TMPDIR, else /tmp, and is made absolute here (every process of an MPI run checks its own).
void check_out_of_core(const toml::table& root, const std::string& base_dir,
                       LinearSolverConfig& solver, Problems& problems) {
  if (problems.is_bad("linear_solver.out_of_core") ||
      problems.is_bad("linear_solver.out_of_core_directory"))
    return;
  const std::string given = solver.out_of_core_directory;
  if (!solver.out_of_core) {
    if (!given.empty())
      problems.bad_value("linear_solver.out_of_core_directory", quote(given),
                         "applies only with linear_solver.out_of_core = true");
    return;
  }
  if (!problems.is_bad("linear_solver.type") && solver.type != LinearSolverType::Mumps) {
    problems.bad_value("linear_solver.out_of_core", "true",
                       "applies to linear_solver.type = \"mumps\" only, not to " +
                           shown_at(root, "linear_solver.type", "its default") +
                           " (MUMPS writes its factors to files)");
    return;
  }
  const char* tmpdir = std::getenv("TMPDIR");
  const bool from_env = given.empty() && tmpdir && *tmpdir != '\0';
  const std::string folder = !given.empty() ? resolve_against(given, base_dir)
                             : from_env     ? std::string(tmpdir)
                                            : std::string("/tmp");
  const std::string shown = !given.empty() ? quote(given)
                            : from_env     ? quote(folder) + " (the default, from $TMPDIR)"
                                           : quote(folder) + " (the default)";
  std::error_code error;
  const auto status = std::filesystem::status(folder, error);
  if (!std::filesystem::exists(status)) {
    problems.bad_value("linear_solver.out_of_core_directory", shown,
                       "folder not found (looked for " + folder + ")");
  } else if (!std::filesystem::is_directory(status)) {
    problems.bad_value("linear_solver.out_of_core_directory", shown, "is not a folder");
  } else if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    problems.bad_value("linear_solver.out_of_core_directory", shown,
                       "is not writable by this user");
  } else if (folder.size() > 255) {
    problems.bad_value(
        "linear_solver.out_of_core_directory", shown,
        "is " + std::to_string(folder.size()) + " characters long; MUMPS takes at most 255");
  }
  solver.out_of_core_directory = folder;
}

void check_cross_fields(const toml::table& root, const std::string& base_dir, Config& config,
                        Problems& problems) {
  check_out_of_core(root, base_dir, config.linear_solver, problems);
  check_mesh_source_keys(root, config, problems);
  check_model(root, config, problems);
  check_reaction_boundaries(root, config, problems);
  check_platen_solver(root, config, problems);
  if (!problems.is_bad("time.dt") && !problems.is_bad("time.t_end") &&
      config.time.dt > config.time.t_end) {
    problems.bad_value("time.dt", shown_at(root, "time.dt", format_number(config.time.dt)),
                       "must be <= time.t_end = " +
                           shown_at(root, "time.t_end", format_number(config.time.t_end)) + " (s)");
  } else if (!problems.is_bad("time.dt") && !problems.is_bad("time.t_end") &&
             interval_count(config.time.t_end, config.time.dt) > kMaxOutputIntervals) {
    const long long count = interval_count(config.time.t_end, config.time.dt);
    problems.bad_value(
        "time.dt", shown_at(root, "time.dt", format_number(config.time.dt)),
        "gives time.t_end / time.dt = " + format_number(config.time.t_end) + " s / " +
            format_number(config.time.dt) + " s = " +
            (count == std::numeric_limits<long long>::max() ? std::string("more than 9e18")
                                                            : std::to_string(count)) +
            " steps, more than the " + std::to_string(kMaxOutputIntervals) +
            " a run may have; use a larger time.dt or a shorter time.t_end");
  }

  if (!problems.is_bad("time.volume_rate") && !problems.is_bad("time.integrator") &&
      uses_ida(config.time.integrator) && config.time.volume_rate == VolumeRate::Conservative) {
    problems.bad_value("time.volume_rate", shown_at(root, "time.volume_rate", "\"conservative\""),
                       "applies only to time.integrator = \"backward_euler\", not to " +
                           shown_at(root, "time.integrator", "\"bdf\"") +
                           " (BDF's dJ/dt is the exact rate of its own solution)");
  }

  check_material_laws(root, config.material, problems);

  if (!problems.is_bad("output.line_points") && config.output.line_points == 1) {
    problems.bad_value("output.line_points", "1",
                       "must be 0 (mesh nodes, or 101 points) or at least 2");
  }
  if (!problems.is_bad("output.line_start") && !problems.is_bad("output.line_end") &&
      config.output.line_start == config.output.line_end) {
    problems.bad_value("output.line_end",
                       shown_at(root, "output.line_end", format_value(config.output.line_end)),
                       "must differ from output.line_start");
  }

  // mesh.write_msh is written inside the output folder and nowhere else.
  if (const std::string& msh = config.mesh.cylinder.write_msh;
      !problems.is_bad("mesh.write_msh") && !msh.empty()) {
    const std::filesystem::path path(msh);
    const bool leaves = std::any_of(path.begin(), path.end(),
                                    [](const std::filesystem::path& part) { return part == ".."; });
    if (path.has_root_path()) {
      problems.bad_value("mesh.write_msh", quote(msh),
                         "must be a path relative to the output folder, not an absolute one");
    } else if (leaves) {
      problems.bad_value("mesh.write_msh", quote(msh),
                         "must stay inside the output folder (no '..' component)");
    } else if (path.extension() != ".msh" || path.stem().empty()) {
      problems.bad_value("mesh.write_msh", quote(msh), "must name a .msh file");
    }
  }

  if (!problems.is_bad("mesh.file") && !config.mesh.file.empty()) {
    const std::string given = config.mesh.file;
    config.mesh.file = resolve_against(given, base_dir);
    if (config.mesh.source == MeshSource::File && !problems.is_bad("mesh.source")) {
      std::error_code error;
      const auto status = std::filesystem::status(config.mesh.file, error);
      if (!std::filesystem::exists(status)) {
        problems.bad_value("mesh.file", quote(given),
                           "file not found (looked for " + config.mesh.file + ")");
      } else if (std::filesystem::is_directory(status)) {
        problems.bad_value("mesh.file", quote(given), "is a folder, not a mesh file");
      }
    }
  } else if (config.mesh.source == MeshSource::File && !problems.is_bad("mesh.source") &&
             !problems.is_bad("mesh.file")) {
    if (find_path(root, "mesh.file") == nullptr) {
      problems.bad_key("mesh.file", "required when mesh.source = \"file\"");
    } else {
      problems.bad_value("mesh.file", "\"\"", "required when mesh.source = \"file\"");
    }
  }
}

}  // namespace

CaseError::CaseError(std::vector<std::string> problems)
    : std::runtime_error(join(problems, "\n")), problems_(std::move(problems)) {}

const std::vector<std::string>& CaseError::problems() const { return problems_; }

std::string CaseError::report() const {
  std::string text = "the case has " + std::to_string(problems_.size()) + " problem(s):";
  for (const std::string& p : problems_) text += "\n  " + p;
  return text;
}

Config parse_case(const std::string& toml_text, const std::string& source_name,
                  const std::vector<std::string>& overrides, const std::string& base_dir) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    throw CaseError({source_name + ":" + std::to_string(begin.line) + ":" +
                     std::to_string(begin.column) +
                     ": TOML syntax error: " + std::string(error.description())});
  }

  Problems problems(source_name);
  for (const auto& argument : overrides) {
    std::string problem = apply_override(root, argument, problems);
    if (!problem.empty()) problems.add(std::move(problem));
  }

  Config config;
  config.case_file = source_name;
  check_unknown_keys(root, "", problems);
  read_global_keys(root, config, problems);
  std::set<std::string> curve_names;
  read_curves(root, config, curve_names, problems);
  read_boundaries(root, curve_names, config, problems);
  read_probes(root, config, problems);
  check_cross_fields(root, base_dir, config, problems);
  read_regions(root, config, problems);

  if (!problems.empty()) throw CaseError(problems.take());
  return config;
}

Config read_case_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw CaseError(
        {path + ": " +
         (std::filesystem::exists(path, error) ? "not a regular file" : "case file not found")});
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw CaseError({path + ": cannot read the case file"});
  std::string base_dir = std::filesystem::path(path).parent_path().string();
  if (base_dir.empty()) base_dir = ".";
  return parse_case(text.str(), path, overrides, base_dir);
}

void check_boundaries(const Config& config, const std::vector<std::string>& mesh_boundary_names) {
  const std::string source = config.case_file.empty() ? std::string{} : config.case_file + ": ";
  const std::string available = mesh_boundary_names.empty()
                                    ? "the mesh has no named boundaries"
                                    : "mesh boundaries: " + join(mesh_boundary_names, ", ");
  auto in_mesh = [&](const std::string& name) {
    return std::find(mesh_boundary_names.begin(), mesh_boundary_names.end(), name) !=
           mesh_boundary_names.end();
  };
  std::vector<std::string> problems;
  for (std::size_t i = 0; i < config.bcs.size(); ++i) {
    const auto& bc = config.bcs[i];
    if (!in_mesh(bc.boundary)) {
      problems.push_back(source + "boundary[" + std::to_string(i) + "].name = " +
                         quote(bc.boundary) + ": no such boundary in the mesh (" + available + ")");
    }
  }
  for (const auto& face : config.mesh.cylinder.grading_faces) {
    if (!in_mesh(face)) {
      problems.push_back(
          source + "mesh.grading_faces = " + format_value(config.mesh.cylinder.grading_faces) +
          ": " + quote(face) + " is not a boundary of the mesh (" + available + ")");
    }
  }
  if (!problems.empty()) throw CaseError(std::move(problems));
}

}  // namespace biphasic
