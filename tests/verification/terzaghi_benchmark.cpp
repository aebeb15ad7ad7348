#include "terzaghi_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "biphasic/analytic/terzaghi.hpp"
#include "biphasic/io/line_probe.hpp"

namespace biphasic::verification {

namespace {

/// What the series needs from the case: q, H, H_A, c.
struct TerzaghiSetup {
  double q = 0.0;       ///< step load [MPa]
  double height = 0.0;  ///< drainage length H [mm]
  double HA = 0.0;      ///< λ + 2μ [MPa]
  double c = 0.0;       ///< k H_A [mm²/s]
};

TerzaghiSetup setup_of(const Config& config) {
  TerzaghiSetup s;
  s.height = config.mesh.column.height;
  s.HA = config.material.get("lambda") + 2.0 * config.material.get("mu");
  s.c = config.material.get("permeability") * s.HA;
  for (const auto& bc : config.bcs)
    if (bc.type == BcType::NormalTraction && bc.boundary == "top") s.q = bc.value;
  return s;
}

std::string label_of(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

std::vector<std::string> terzaghi_column(int nz) {
  const std::string width = label_of(1.0 / nz);
  return {"mesh.column.nz=" + std::to_string(nz), "mesh.column.width=" + width,
          "mesh.column.depth=" + width};
}

TerzaghiErrors run_terzaghi(const std::string& label, const std::vector<std::string>& overrides,
                            const ScratchDir& scratch) {
  const BenchmarkRun run = run_benchmark("terzaghi", overrides, scratch, label);
  const TerzaghiSetup s = setup_of(run.config);
  // The probe line is the column edge x = y = 0 from the bottom (s = z) to the drained top.
  const std::map<double, LineSnapshot> snapshots = read_line(run.dir);
  auto settlement_of = [](const LineSnapshot& snap) { return -snap.u.back()[2]; };
  const double time_scale = s.height * s.height / s.c;  // t = T H²/c
  const double final_settlement = s.q * s.height / s.HA;

  const auto out = verification_output("terzaghi");
  std::optional<CsvWriter> profiles, settlement;
  if (out) {
    profiles.emplace(*out / (label + "_profiles.csv"), "T,zeta_over_H,p_computed,p_series");
    settlement.emplace(*out / (label + "_settlement.csv"), "T,U_computed,U_series");
    for (const auto& [t, snap] : snapshots)
      settlement->row(t / time_scale, settlement_of(snap) / final_settlement,
                      analytic::terzaghi_degree_of_consolidation(t / time_scale));
  }

  TerzaghiErrors errors;
  for (double T : kTerzaghiTimes) {
    const double t = T * time_scale;
    const auto it = find_time(snapshots, t);
    if (it == snapshots.end()) continue;
    const LineSnapshot& snap = it->second;
    ++errors.compared_times;
    for (double zeta : kTerzaghiDepths) {
      const double p = interpolate_on_line(snap.s, snap.p, s.height * (1.0 - zeta)) / s.q;
      errors.pressure =
          std::max(errors.pressure, std::abs(p - analytic::terzaghi_pressure(zeta, T)));
    }
    const double U = settlement_of(snap) / final_settlement;
    errors.settlement =
        std::max(errors.settlement, std::abs(U - analytic::terzaghi_degree_of_consolidation(T)));
    if (profiles) {
      for (std::size_t i = snap.s.size(); i-- > 0;) {
        const double zeta = 1.0 - snap.s[i] / s.height;
        profiles->row(T, zeta, snap.p[i] / s.q, analytic::terzaghi_pressure(zeta, T));
      }
    }
  }
  if (out) {
    write_errors_csv(*out, label, run.summary, overrides, "max_pressure_error,max_settlement_error",
                     {errors.pressure, errors.settlement});
  }
  return errors;
}

}  // namespace biphasic::verification
