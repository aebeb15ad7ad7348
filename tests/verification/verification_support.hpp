// Helpers shared by the verification benchmarks: running a case of cases/verification through
// run_case, reading its CSV outputs, and writing computed-vs-analytic CSVs to
// $BIPHASIC_VERIFICATION_OUT/<benchmark>/ when that variable is set.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/app/run.hpp"
#include "biphasic/io/case_file.hpp"

namespace biphasic::verification {

namespace fs = std::filesystem;

/// cases/verification/<benchmark>/<file> in the source tree.
inline std::string case_path(const std::string& benchmark, const std::string& file) {
  return std::string(BIPHASIC_SOURCE_DIR) + "/cases/verification/" + benchmark + "/" + file;
}

/// A fresh folder under the system temp folder for one test's runs, removed on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) {
    const auto base = fs::temp_directory_path();
    for (int i = 0;; ++i) {
      path_ = base / ("biphasic_verification_" + tag + "_" + std::to_string(::getpid()) + "_" +
                      std::to_string(i));
      if (fs::create_directory(path_)) break;
    }
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// Reads the case with `overrides` and runs it quietly into `out`; returns the summary.
inline nlohmann::json run_case_file(const std::string& case_file,
                                    const std::vector<std::string>& overrides,
                                    const fs::path& out) {
  const Config config = read_case_file(case_file, overrides);
  RunOptions options;
  options.output_dir = out.string();
  options.quiet = true;
  return run_case(config, options);
}

/// One run of a verification case: its configuration (overrides applied), output folder and
/// summary.
struct BenchmarkRun {
  Config config;
  fs::path dir;
  nlohmann::json summary;
};

/// Runs cases/verification/<benchmark>/<benchmark>.toml with `overrides` quietly into
/// scratch/label and expects it to complete.
inline BenchmarkRun run_benchmark(const std::string& benchmark,
                                  const std::vector<std::string>& overrides,
                                  const ScratchDir& scratch, const std::string& label) {
  BenchmarkRun run;
  run.config = read_case_file(case_path(benchmark, benchmark + ".toml"), overrides);
  run.dir = scratch.path() / label;
  RunOptions options;
  options.output_dir = run.dir.string();
  options.quiet = true;
  run.summary = run_case(run.config, options);
  EXPECT_EQ(run.summary["status"], "completed") << benchmark << ": " << label;
  return run;
}

/// The platen ramp of a case: the z displacement prescribed on "top" [mm] and the time its
/// load curve reaches its second point, the end of the ramp [s].
struct PlatenRamp {
  double displacement = 0.0;
  double ramp_time = 0.0;
};

inline PlatenRamp top_platen_ramp(const Config& config) {
  for (const auto& bc : config.bcs)
    if (bc.type == BcType::Displacement && bc.boundary == "top" && bc.component == 2)
      return {bc.value, config.curves.at(bc.curve).points.at(1).first};
  throw std::runtime_error("no z displacement on \"top\" in " + config.case_file);
}

/// Rows of a CSV file with a header line, as numbers by column name; `text_columns` are kept
/// as strings in `text`.
struct CsvTable {
  std::vector<std::map<std::string, double>> rows;
  std::vector<std::map<std::string, std::string>> text;
};

inline CsvTable read_csv(const fs::path& path, const std::vector<std::string>& text_columns = {}) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    return cells;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  CsvTable table;
  while (std::getline(in, line)) {
    const auto cells = split(line);
    std::map<std::string, double> numbers;
    std::map<std::string, std::string> strings;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) {
      bool is_text = false;
      for (const auto& t : text_columns) is_text = is_text || t == header[i];
      if (is_text)
        strings[header[i]] = cells[i];
      else
        numbers[header[i]] = std::stod(cells[i]);
    }
    table.rows.push_back(std::move(numbers));
    table.text.push_back(std::move(strings));
  }
  return table;
}

/// Reaction force of `boundary` at every output time of a run's reactions.csv [s → N].
inline std::map<double, std::array<double, 3>> read_reactions(const fs::path& run_dir,
                                                              const std::string& boundary) {
  const CsvTable table = read_csv(run_dir / "reactions.csv", {"boundary"});
  std::map<double, std::array<double, 3>> out;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    if (table.text[i].at("boundary") != boundary) continue;
    const auto& r = table.rows[i];
    out[r.at("t")] = {r.at("Fx"), r.at("Fy"), r.at("Fz")};
  }
  return out;
}

/// The probe line of a run at one output time, nodes sorted by arc length s from line_start.
struct LineSnapshot {
  std::vector<double> s;                 ///< [mm]
  std::vector<double> p;                 ///< [MPa]
  std::vector<std::array<double, 3>> u;  ///< displacement [mm]
};

/// A run's line.csv by output time [s].
inline std::map<double, LineSnapshot> read_line(const fs::path& run_dir) {
  const CsvTable table = read_csv(run_dir / "line.csv");
  std::map<double, std::vector<std::map<std::string, double>>> rows;
  for (const auto& r : table.rows) rows[r.at("t")].push_back(r);
  std::map<double, LineSnapshot> out;
  for (auto& [t, samples] : rows) {
    std::sort(samples.begin(), samples.end(),
              [](const auto& a, const auto& b) { return a.at("s") < b.at("s"); });
    LineSnapshot& snap = out[t];
    for (const auto& r : samples) {
      snap.s.push_back(r.at("s"));
      snap.p.push_back(r.at("p"));
      snap.u.push_back({r.at("ux"), r.at("uy"), r.at("uz")});
    }
  }
  return out;
}

/// The output of `summary` at time t (to 1e-9 relative), or nullptr.
inline const nlohmann::json* summary_output(const nlohmann::json& summary, double t) {
  for (const auto& o : summary["outputs"])
    if (std::abs(o["t"].get<double>() - t) <= 1e-9 * std::max(1.0, std::abs(t))) return &o;
  return nullptr;
}

/// The output of a time series (map by time) at t, to 1e-9 relative, or end().
template <class Map>
typename Map::const_iterator find_time(const Map& series, double t) {
  const auto it = series.lower_bound(t - 1e-9 * std::abs(t));
  return it != series.end() && std::abs(it->first - t) <= 1e-9 * std::abs(t) ? it : series.end();
}

/// $BIPHASIC_VERIFICATION_OUT/<benchmark>/ (created), or nothing when the variable is unset.
inline std::optional<fs::path> verification_output(const std::string& benchmark) {
  const char* root = std::getenv("BIPHASIC_VERIFICATION_OUT");
  if (root == nullptr || *root == '\0') return std::nullopt;
  const fs::path dir = fs::path(root) / benchmark;
  fs::create_directories(dir);
  return dir;
}

/// A CSV file written row by row at full precision.
class CsvWriter {
 public:
  CsvWriter(const fs::path& path, const std::string& header) : out_(path) {
    if (!out_) throw std::runtime_error("cannot write " + path.string());
    out_.precision(17);
    out_ << header << '\n';
  }
  template <class... Cells>
  void row(const Cells&... cells) {
    std::size_t i = 0;
    ((out_ << (i++ == 0 ? "" : ",") << cells), ...);
    out_ << '\n';
  }

 private:
  std::ofstream out_;
};

/// Writes <dir>/<label>_errors.csv: one row with the run's label, unknowns and steps (from its
/// summary), `values` under the `columns` (comma-separated names), and the overrides.
inline void write_errors_csv(const fs::path& dir, const std::string& label,
                             const nlohmann::json& summary,
                             const std::vector<std::string>& overrides, const std::string& columns,
                             const std::vector<double>& values) {
  std::ofstream out(dir / (label + "_errors.csv"));
  out.precision(17);
  out << "run,unknowns,steps," << columns << ",overrides\n"
      << label << ',' << summary["mesh"]["unknowns"].get<long>() << ','
      << summary["counters"]["steps"].get<long>();
  for (double v : values) out << ',' << v;
  out << ",\"";
  for (std::size_t i = 0; i < overrides.size(); ++i) out << (i ? " " : "") << overrides[i];
  out << "\"\n";
}

}  // namespace biphasic::verification
