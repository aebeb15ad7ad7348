// The case-file schema as JSON Schema (draft-07), for editors: a TOML language server given this
// schema checks key names, types, ranges and choices as the file is typed and shows each key's
// help. Generated from the same key table as validation and the Markdown reference, so the three
// cannot drift apart.
#include <string>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "case_schema.hpp"

namespace biphasic {

namespace {

using case_schema::KeyInfo;
using case_schema::Kind;
using case_schema::Need;
using nlohmann::json;

/// JSON Schema bounds of a Range on `out` (number or each item of an array of numbers).
void add_range(const case_schema::Range& r, json& out) {
  if (r.min) out[r.min_open ? "exclusiveMinimum" : "minimum"] = *r.min;
  if (r.max) out[r.max_open ? "exclusiveMaximum" : "maximum"] = *r.max;
}

/// The description shown by editors: the help text, then the unit in brackets.
std::string description(const KeyInfo& key) {
  return key.unit.empty() ? key.help : key.help + " [" + key.unit + "]";
}

/// A string, one of `choices` when there are any (free otherwise).
json string_item(const std::vector<std::string>& choices) {
  json s = {{"type", "string"}};
  if (!choices.empty()) s["enum"] = choices;
  return s;
}

/// The schema of one key's value.
json value_schema(const KeyInfo& key) {
  json s = json::object();
  json number = {{"type", "number"}};
  add_range(key.range, number);
  switch (key.kind) {
    case Kind::Integer:
      s["type"] = "integer";
      add_range(key.range, s);
      if (!key.allowed.empty()) s["enum"] = key.allowed;
      break;
    case Kind::Number:
      s = number;
      break;
    case Kind::Boolean:
      s["type"] = "boolean";
      break;
    case Kind::String:
      s["type"] = "string";
      if (key.non_empty) s["minLength"] = 1;
      break;
    case Kind::Choice:
      s["type"] = "string";
      s["enum"] = key.choices;
      break;
    case Kind::Vector3:
      s = {{"type", "array"}, {"items", number}, {"minItems", 3}, {"maxItems", 3}};
      break;
    case Kind::StringList:
      s = {{"type", "array"}, {"items", string_item(key.choices)}};
      break;
    case Kind::Selection:
      s["anyOf"] = json::array(
          {{{"type", "boolean"}}, {{"type", "array"}, {"items", string_item(key.choices)}}});
      break;
    case Kind::Curve:
      s = {
          {"type", "array"},
          {"minItems", 1},
          {"items",
           {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}}}};
      break;
    case Kind::Expression:
      s["type"] = json::array({"string", "number"});
      break;
    case Kind::NumberList:
      s = {{"type", "array"}, {"items", number}};
      break;
  }
  s["description"] = description(key);
  return s;
}

/// An object schema that accepts only its listed properties.
json closed_object(const std::string& what) {
  return {{"type", "object"},
          {"description", what},
          {"properties", json::object()},
          {"additionalProperties", false}};
}

/// Places `value` at the dotted `path` under `root` (an object schema), creating closed table
/// schemas for the sections on the way.
void place(json& root, const std::string& path, json value, bool required) {
  json* table = &root;
  std::size_t start = 0;
  for (std::size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
    const std::string section = path.substr(start, dot - start);
    json& props = (*table)["properties"];
    if (!props.contains(section))
      props[section] = closed_object("[" + path.substr(0, dot) + "] table");
    table = &props[section];
    start = dot + 1;
  }
  const std::string name = path.substr(start);
  (*table)["properties"][name] = std::move(value);
  if (required) (*table)["required"].push_back(name);
}

/// [[boundary]] entries: the keys, and per boundary type which keys it needs or forbids.
json boundary_schema() {
  json item = closed_object("One boundary condition ([[boundary]] entry).");
  std::vector<std::string> required;
  for (const auto& key : case_schema::boundary_keys()) {
    item["properties"][key.path] = value_schema(key);
    if (key.required) required.push_back(key.path);
  }
  item["required"] = required;
  json rules = json::array();
  const auto& types = case_schema::bc_type_names();
  for (std::size_t t = 0; t < types.size(); ++t) {
    json then = json::object();
    for (const auto& key : case_schema::boundary_keys()) {
      if (!key.per_type) continue;
      if (key.need[t] == Need::Required) then["required"].push_back(key.path);
      if (key.need[t] == Need::Forbidden) then["properties"][key.path] = false;
    }
    if (then.empty()) continue;
    rules.push_back({{"if", {{"properties", {{"type", {{"const", types[t]}}}}}}}, {"then", then}});
  }
  if (!rules.empty()) item["allOf"] = rules;
  return {
      {"type", "array"}, {"description", "Boundary conditions, one table each."}, {"items", item}};
}

/// [[region]] entries: a name and any [material] key.
json region_schema() {
  json item = closed_object(
      "Material of a mesh region ([[region]] entry): the keys of [material], each left out "
      "inherited from it.");
  item["properties"]["name"] = {
      {"type", "string"}, {"minLength", 1}, {"description", "Name of the mesh region."}};
  item["required"] = json::array({"name"});
  for (const auto& key : case_schema::global_keys())
    if (key.path.rfind("material.", 0) == 0)
      item["properties"][key.path.substr(9)] = value_schema(key);
  return {{"type", "array"}, {"items", item}};
}

/// [[probe]] entries.
json probe_schema() {
  json item = closed_object("A named probe line ([[probe]] entry).");
  std::vector<std::string> required;
  for (const auto& key : case_schema::probe_keys()) {
    item["properties"][key.path] = value_schema(key);
    if (key.required) required.push_back(key.path);
  }
  item["required"] = required;
  return {{"type", "array"}, {"items", item}};
}

}  // namespace

nlohmann::json case_json_schema() {
  json root = closed_object(
      "A case file of biphasic, the finite-strain biphasic solver (docs/case_file.md). Units: "
      "mm, N, s, MPa.");
  root["$schema"] = "http://json-schema.org/draft-07/schema#";
  root["title"] = "biphasic case file";
  for (const auto& key : case_schema::global_keys()) {
    if (key.kind == Kind::Curve) {
      // [curves]: any name, each a curve.
      json curves = closed_object("Named piecewise-linear load curves.");
      curves["additionalProperties"] = value_schema(key);
      root["properties"]["curves"] = curves;
      continue;
    }
    place(root, key.path, value_schema(key), key.required);
  }
  root["properties"]["boundary"] = boundary_schema();
  root["properties"]["region"] = region_schema();
  root["properties"]["probe"] = probe_schema();
  return root;
}

}  // namespace biphasic
