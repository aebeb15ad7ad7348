// Case files: TOML input describing one run, validated against a schema and resolved into a
// Config (units: mm, N, s, MPa).
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/io/config.hpp"

namespace biphasic {

/// Every problem found in a case file, reported together.
class CaseError : public std::runtime_error {
 public:
  /// what() is the problems joined by '\n'.
  explicit CaseError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const;
  /// The report a user reads: "the case has N problem(s):", then each problem on its own line,
  /// indented by two spaces (no final newline).
  std::string report() const;

 private:
  std::vector<std::string> problems_;
};

/// Reads, validates and resolves a TOML case file; `overrides` are "key=value" strings from
/// --set, applied before validation. Throws CaseError listing every problem; nothing partial.
Config read_case_file(const std::string& path, const std::vector<std::string>& overrides = {});

/// Same from text; `source_name` is used in messages in place of the file name and stored as
/// Config::case_file; a relative mesh.file is resolved against `base_dir`.
Config parse_case(const std::string& toml_text, const std::string& source_name,
                  const std::vector<std::string>& overrides = {},
                  const std::string& base_dir = ".");

/// Markdown reference of every key (type, default, range/choices, unit, help), from the schema.
std::string case_schema_markdown();

/// The same schema as JSON Schema (draft-07) for editors and validators: every key with its
/// type, range, choices, and help and unit as its description; unknown keys are not allowed;
/// [[boundary]] entries with the keys each type needs or forbids.
nlohmann::json case_json_schema();

/// The resolved configuration as JSON (stored in the run summary), with every key and value,
/// laid out like the case file (plus "case_file").
nlohmann::json config_to_json(const Config& config);

/// Throws CaseError if a boundary condition or mesh.grading_faces names a boundary the mesh
/// lacks; the message lists the mesh's boundary names.
void check_boundaries(const Config& config, const std::vector<std::string>& mesh_boundary_names);

}  // namespace biphasic
