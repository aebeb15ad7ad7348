#include "cryer_benchmark.hpp"

#include <algorithm>
#include <cmath>

#include "../common/peak.hpp"
#include "biphasic/analytic/cryer.hpp"

namespace biphasic::verification {

namespace {

/// What the series needs from the case: R, P₀, ν, c.
struct CryerSetup {
  double radius = 0.0;  ///< R [mm]
  double load = 0.0;    ///< P₀ [MPa]
  double nu = 0.0;      ///< drained Poisson ratio λ / (2(λ + μ)) [-]
  double c = 0.0;       ///< k (λ + 2μ) [mm²/s]
};

CryerSetup setup_of(const Config& config) {
  CryerSetup s;
  s.radius = config.mesh.sphere_octant.radius;
  const double lambda = config.material.get("lambda"), mu = config.material.get("mu");
  s.nu = lambda / (2.0 * (lambda + mu));
  s.c = config.material.get("permeability") * (lambda + 2.0 * mu);
  for (const auto& bc : config.bcs)
    if (bc.type == BcType::NormalTraction && bc.boundary == "surface") s.load = bc.value;
  return s;
}

bool is_listed(double T) {
  return std::any_of(kCryerTimes.begin(), kCryerTimes.end(),
                     [&](double x) { return std::abs(x - T) <= 1e-9 * x; });
}

}  // namespace

CryerResult run_cryer(const std::string& label, const std::vector<std::string>& overrides,
                      const ScratchDir& scratch) {
  const BenchmarkRun run = run_benchmark("cryer", overrides, scratch, label);
  const CryerSetup s = setup_of(run.config);
  const nlohmann::json& summary = run.summary;
  // The probe line runs from the centre (s = 0) to the drained surface.
  const std::map<double, LineSnapshot> snapshots = read_line(run.dir);
  const double time_scale = s.radius * s.radius / s.c;  // t = T R²/c

  CryerResult result;
  result.drained_ends = summary["line"]["drained_ends"].get<std::string>();
  std::tie(result.series_peak_time, result.series_peak) = analytic::testing::maximise(
      [&](double T) { return analytic::cryer_center_pressure(s.nu, T); }, 0.01, 0.2);

  const auto out = verification_output("cryer");
  std::optional<CsvWriter> centre, profiles;
  if (out) {
    centre.emplace(*out / (label + "_centre.csv"), "T,p_computed,p_series,oscillation,overshoot");
    profiles.emplace(*out / (label + "_profiles.csv"), "T,r_over_R,p_computed,p_series");
  }
  double peak_oscillation = 0.0, peak_overshoot = 0.0;
  for (const auto& [t, snap] : snapshots) {
    if (t <= 0.0) continue;
    const double T = t / time_scale;
    const double p = snap.p.front() / s.load;
    const double series = analytic::cryer_center_pressure(s.nu, T);
    const nlohmann::json* measures = summary_output(summary, t);
    if (measures == nullptr) {
      ADD_FAILURE() << label << ": no summary output at t = " << t;
      continue;
    }
    const double oscillation = (*measures)["oscillation"].get<double>();
    const double overshoot = (*measures)["overshoot"].get<double>();
    if (T >= kCryerFirstCompared * (1.0 - 1e-9)) {
      result.max_error = std::max(result.max_error, std::abs(p - series));
      result.max_oscillation = std::max(result.max_oscillation, oscillation);
    }
    if (T >= kCryerQuietFrom)
      result.max_oscillation_after_rise = std::max(result.max_oscillation_after_rise, oscillation);
    if (p > result.peak) {
      result.peak = p;
      result.peak_time = T;
      peak_oscillation = oscillation;
      peak_overshoot = overshoot;
    }
    if (centre) centre->row(T, p, series, oscillation, overshoot);
    if (is_listed(T)) {
      ++result.compared_times;
      if (profiles)
        for (std::size_t i = 0; i < snap.s.size(); ++i) {
          const double r = snap.s[i] / s.radius;
          profiles->row(T, r, snap.p[i] / s.load, analytic::cryer_pressure(s.nu, r, T));
        }
    }
  }
  result.oscillation_at_peak = peak_oscillation;
  result.overshoot_at_peak = peak_overshoot;
  if (out) {
    write_errors_csv(*out, label, summary, overrides,
                     "max_centre_error,peak,peak_T,series_peak,series_peak_T,max_oscillation,"
                     "max_oscillation_after_rise,overshoot_at_peak",
                     {result.max_error, result.peak, result.peak_time, result.series_peak,
                      result.series_peak_time, result.max_oscillation,
                      result.max_oscillation_after_rise, result.overshoot_at_peak});
  }
  return result;
}

CryerFirstStep cryer_first_step(double dt, const std::vector<std::string>& overrides,
                                const ScratchDir& scratch, const std::string& label) {
  std::vector<std::string> o = overrides;
  o.insert(o.end(), {"time.integrator=backward_euler", "time.dt=" + std::to_string(dt),
                     "time.t_end=" + std::to_string(dt)});
  const BenchmarkRun run = run_benchmark("cryer", o, scratch, label);
  const CryerSetup s = setup_of(run.config);
  const std::map<double, LineSnapshot> line = read_line(run.dir);
  const LineSnapshot& snap = line.rbegin()->second;
  CryerFirstStep step;
  for (std::size_t i = 0; i < snap.s.size(); ++i) {
    step.r.push_back(snap.s[i] / s.radius);
    step.p.push_back(snap.p[i] / s.load);
  }
  step.oscillation = run.summary["outputs"].back()["oscillation"].get<double>();
  if (const auto out = verification_output("cryer")) {
    CsvWriter csv(*out / ("first_step_" + label + ".csv"), "r_over_R,p_computed");
    for (std::size_t i = 0; i < step.r.size(); ++i) csv.row(step.r[i], step.p[i]);
  }
  return step;
}

}  // namespace biphasic::verification
