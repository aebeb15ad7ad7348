// Helpers shared by the case-file tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "biphasic/io/case_file.hpp"

namespace biphasic::testing_support {

/// Smallest valid case: one displacement condition, everything else default.
inline const std::string kMinimalCase = R"(
format_version = 1

[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -0.08
)";

/// The problems parse_case reports for `text` (source "cases/x.toml"); a test failure if
/// the text is accepted.
inline std::vector<std::string> problems_of(const std::string& text,
                                            const std::vector<std::string>& overrides = {}) {
  try {
    parse_case(text, "cases/x.toml", overrides, ".");
  } catch (const CaseError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "the case was accepted:\n" << text;
  return {};
}

/// Success if one problem contains every one of `parts`.
inline ::testing::AssertionResult has_problem(const std::vector<std::string>& problems,
                                              const std::vector<std::string>& parts) {
  for (const auto& problem : problems) {
    bool all = true;
    for (const auto& part : parts) all = all && problem.find(part) != std::string::npos;
    if (all) return ::testing::AssertionSuccess();
  }
  auto failure = ::testing::AssertionFailure() << "no problem contains all of:";
  for (const auto& part : parts) failure << " [" << part << "]";
  failure << "\nproblems reported:";
  for (const auto& problem : problems) failure << "\n  " << problem;
  return failure;
}

/// A fresh empty folder under the system temp folder, removed on destruction.
class TempDir {
 public:
  TempDir() {
    const auto base = std::filesystem::temp_directory_path();
    for (int i = 0;; ++i) {
      path_ = base / ("biphasic_case_test_" + std::to_string(::getpid()) + "_" + std::to_string(i));
      if (std::filesystem::create_directory(path_)) break;
    }
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Writes `text` to `name` inside the folder (creating subfolders) and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace biphasic::testing_support
