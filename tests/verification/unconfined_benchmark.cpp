#include "unconfined_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "biphasic/analytic/unconfined_compression.hpp"
#include "biphasic/io/line_probe.hpp"

namespace biphasic::verification {

namespace {

/// What the series needs from the case.
struct UnconfinedSetup {
  double radius = 0.0;     ///< a [mm]
  double height = 0.0;     ///< [mm]
  double strain = 0.0;     ///< ε₀ = −ū_z(top) / height [-]
  double ramp_time = 0.0;  ///< t₀ [s]
  double nu = 0.0;         ///< drained Poisson ratio [-]
  double young = 0.0;      ///< drained Young's modulus E [MPa]
  double mu = 0.0;         ///< [MPa]
  double c = 0.0;          ///< k (λ + 2μ) [mm²/s]
};

UnconfinedSetup setup_of(const Config& config) {
  UnconfinedSetup s;
  s.radius = config.mesh.cylinder.radius;
  s.height = config.mesh.cylinder.height;
  const double lambda = config.material.get("lambda"), mu = config.material.get("mu");
  s.mu = mu;
  s.nu = lambda / (2.0 * (lambda + mu));
  s.young = mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
  s.c = config.material.get("permeability") * (lambda + 2.0 * mu);
  const PlatenRamp ramp = top_platen_ramp(config);
  s.strain = -ramp.displacement / s.height;
  s.ramp_time = ramp.ramp_time;
  return s;
}

}  // namespace

UnconfinedResult run_unconfined(const std::string& label, const std::vector<std::string>& overrides,
                                const ScratchDir& scratch) {
  const BenchmarkRun run = run_benchmark("unconfined_compression", overrides, scratch, label);
  const UnconfinedSetup s = setup_of(run.config);
  const nlohmann::json& summary = run.summary;
  const auto top = read_reactions(run.dir, "top");
  const auto bottom = read_reactions(run.dir, "bottom");
  // The probe line is the axis from the bottom (s = 0) to the top platen.
  const std::map<double, LineSnapshot> line = read_line(run.dir);
  const analytic::UnconfinedCompression series(s.nu);
  const double time_scale = s.radius * s.radius / s.c;  // t = τ a²/c
  const double tau0 = s.ramp_time / time_scale;
  const double force_scale = std::numbers::pi * s.radius * s.radius / 4.0 * s.strain * s.young;
  const double pressure_scale = s.mu * s.strain;

  UnconfinedResult result;
  result.drained_ends = summary["line"]["drained_ends"].get<std::string>();
  const auto out = verification_output("unconfined_compression");
  std::optional<CsvWriter> csv;
  if (out)
    csv.emplace(*out / (label + ".csv"),
                "tau,force_computed,force_series,pressure_computed,pressure_series");
  for (const auto& [t, force] : top) {
    if (t <= 0.0) continue;
    const double tau = t / time_scale;
    const auto snap = find_time(line, t);
    const nlohmann::json* measures = summary_output(summary, t);
    if (snap == line.end() || measures == nullptr) {
      ADD_FAILURE() << label << ": no line output at t = " << t;
      continue;
    }
    // The quarter's top reaction pushes down on the body: F_z < 0 in compression.
    const double F = -force[2] / force_scale;
    const double F_series = series.ramp_force(tau, tau0);
    const double p =
        interpolate_on_line(snap->second.s, snap->second.p, 0.5 * s.height) / pressure_scale;
    const double p_series = series.ramp_pressure(0.0, tau, tau0);
    result.max_balance =
        std::max(result.max_balance, std::abs(force[2] + bottom.at(t)[2]) / std::abs(force[2]));
    result.peak_pressure = std::max(result.peak_pressure, p);
    result.series_peak_pressure = std::max(result.series_peak_pressure, p_series);
    if (tau >= kUnconfinedFirstCompared * (1.0 - 1e-9)) {
      result.force_error = std::max(result.force_error, std::abs(F - F_series));
      result.pressure_error = std::max(result.pressure_error, std::abs(p - p_series));
      result.max_oscillation =
          std::max(result.max_oscillation, (*measures)["oscillation"].get<double>());
    }
    if (std::any_of(kUnconfinedTimes.begin(), kUnconfinedTimes.end(),
                    [&](double x) { return std::abs(x - tau) <= 1e-9 * x; })) {
      result.force.push_back(F);
      result.force_series.push_back(F_series);
      result.pressure.push_back(p);
      result.pressure_series.push_back(p_series);
    }
    if (csv) csv->row(tau, F, F_series, p, p_series);
  }
  if (out) {
    write_errors_csv(*out, label, summary, overrides,
                     "max_force_error,max_pressure_error,peak_pressure,series_peak_pressure",
                     {result.force_error, result.pressure_error, result.peak_pressure,
                      result.series_peak_pressure});
  }
  return result;
}

}  // namespace biphasic::verification
