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
  s.HA = config.material.lambda + 2.0 * config.material.mu;
  s.c = config.material.permeability * s.HA;
  for (const auto& bc : config.bcs)
    if (bc.type == BcType::NormalTraction && bc.boundary == "top") s.q = bc.value;
  return s;
}

/// Pressure profile (z, p) and top settlement at one output time.
struct Snapshot {
  std::vector<double> z, p;
  double settlement = 0.0;  ///< −u_z at the top [mm]
};

/// line.csv of a run (the probe line is the column edge x = y = 0, bottom to top) by time.
std::map<double, Snapshot> read_snapshots(const fs::path& run_dir) {
  const CsvTable table = read_csv(run_dir / "line.csv");
  std::map<double, std::vector<std::pair<double, std::pair<double, double>>>> rows;
  for (const auto& r : table.rows) rows[r.at("t")].push_back({r.at("z"), {r.at("p"), r.at("uz")}});
  std::map<double, Snapshot> out;
  for (auto& [t, samples] : rows) {
    std::sort(samples.begin(), samples.end());
    Snapshot& s = out[t];
    for (const auto& [z, values] : samples) {
      s.z.push_back(z);
      s.p.push_back(values.first);
    }
    s.settlement = -samples.back().second.second;
  }
  return out;
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
  const std::string file = case_path("terzaghi", "terzaghi.toml");
  const TerzaghiSetup s = setup_of(read_case_file(file, overrides));
  const fs::path run_dir = scratch.path() / label;
  const nlohmann::json summary = run_case_file(file, overrides, run_dir);
  EXPECT_EQ(summary["status"], "completed");
  const std::map<double, Snapshot> snapshots = read_snapshots(run_dir);
  const double time_scale = s.height * s.height / s.c;  // t = T H²/c
  const double final_settlement = s.q * s.height / s.HA;

  const auto out = verification_output("terzaghi");
  std::optional<CsvWriter> profiles, settlement;
  if (out) {
    profiles.emplace(*out / (label + "_profiles.csv"), "T,zeta_over_H,p_computed,p_series");
    settlement.emplace(*out / (label + "_settlement.csv"), "T,U_computed,U_series");
    for (const auto& [t, snap] : snapshots)
      settlement->row(t / time_scale, snap.settlement / final_settlement,
                      analytic::terzaghi_degree_of_consolidation(t / time_scale));
  }

  TerzaghiErrors errors;
  for (double T : kTerzaghiTimes) {
    const double t = T * time_scale;
    const auto it = snapshots.lower_bound(t * (1.0 - 1e-9));
    if (it == snapshots.end() || std::abs(it->first - t) > 1e-9 * t) continue;
    const Snapshot& snap = it->second;
    ++errors.compared_times;
    for (double zeta : kTerzaghiDepths) {
      const double p = interpolate_on_line(snap.z, snap.p, s.height * (1.0 - zeta)) / s.q;
      errors.pressure =
          std::max(errors.pressure, std::abs(p - analytic::terzaghi_pressure(zeta, T)));
    }
    const double U = snap.settlement / final_settlement;
    errors.settlement =
        std::max(errors.settlement, std::abs(U - analytic::terzaghi_degree_of_consolidation(T)));
    if (profiles) {
      for (std::size_t i = snap.z.size(); i-- > 0;) {
        const double zeta = 1.0 - snap.z[i] / s.height;
        profiles->row(T, zeta, snap.p[i] / s.q, analytic::terzaghi_pressure(zeta, T));
      }
    }
  }
  if (out) {
    write_errors_csv(*out, label, summary, overrides, "max_pressure_error,max_settlement_error",
                     {errors.pressure, errors.settlement});
  }
  return errors;
}

}  // namespace biphasic::verification
