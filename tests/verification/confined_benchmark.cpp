#include "confined_benchmark.hpp"

#include <algorithm>
#include <cmath>

#include "biphasic/analytic/confined_compression.hpp"

namespace biphasic::verification {

namespace {

/// The ramp of the case: material, thickness, final strain and ramp time.
analytic::ConfinedRamp ramp_of(const Config& config) {
  analytic::ConfinedRamp c;
  c.mu = config.material.get("mu");
  c.lambda = config.material.get("lambda");
  c.permeability = config.material.get("permeability");
  if (config.material.permeability_law == "holmes_mow") {
    c.solid_fraction = config.material.get("solid_fraction");
    c.permeability_kappa = config.material.get("permeability_kappa");
    c.permeability_M = config.material.get("permeability_M");
  } else if (config.material.permeability_law != "constant") {
    ADD_FAILURE() << "the confined reference has constant and Holmes-Mow permeability only";
  }
  c.thickness = config.mesh.column.height;
  const PlatenRamp ramp = top_platen_ramp(config);
  c.strain = -ramp.displacement / c.thickness;
  c.ramp_time = ramp.ramp_time;
  return c;
}

}  // namespace

ConfinedResult run_confined(const std::string& label, const std::vector<std::string>& overrides,
                            const ScratchDir& scratch) {
  const BenchmarkRun run = run_benchmark("confined_compression", overrides, scratch, label);
  const Config& config = run.config;
  const analytic::ConfinedRamp ramp = ramp_of(config);
  const double area = config.mesh.column.width * config.mesh.column.depth;
  const nlohmann::json& summary = run.summary;
  const auto top = read_reactions(run.dir, "top");
  const auto bottom = read_reactions(run.dir, "bottom");

  std::vector<double> times, computed;
  ConfinedResult result;
  for (const auto& [t, force] : top) {
    if (t <= 0.0) continue;
    times.push_back(t);
    computed.push_back(force[2] / area);
    result.max_balance =
        std::max(result.max_balance, std::abs(force[2] + bottom.at(t)[2]) / std::abs(force[2]));
  }
  const std::vector<double> reference = analytic::confined_ramp_stress_neo_hookean(ramp, times);
  for (double t : kConfinedTimes) {
    const auto it = std::find_if(times.begin(), times.end(),
                                 [&](double x) { return std::abs(x - t) <= 1e-9 * t; });
    if (it == times.end()) {
      ADD_FAILURE() << label << ": no output at t = " << t << " s";
      continue;
    }
    const auto i = static_cast<std::size_t>(it - times.begin());
    result.computed.push_back(computed[i]);
    result.neo_hookean.push_back(reference[i]);
    result.linear.push_back(analytic::confined_ramp_stress_linear(ramp, t));
    result.max_error =
        std::max(result.max_error, std::abs(computed[i] - reference[i]) / std::abs(reference[i]));
  }

  if (const auto out = verification_output("confined_compression")) {
    CsvWriter csv(*out / (label + ".csv"), "t,stress_computed,stress_neo_hookean,stress_linear");
    for (std::size_t i = 0; i < times.size(); ++i)
      csv.row(times[i], computed[i], reference[i],
              analytic::confined_ramp_stress_linear(ramp, times[i]));
    write_errors_csv(*out, label, summary, overrides, "max_relative_error,max_top_bottom_imbalance",
                     {result.max_error, result.max_balance});
  }
  return result;
}

}  // namespace biphasic::verification
