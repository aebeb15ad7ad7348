#include "oscillation_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "biphasic/io/line_probe.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/study/measures.hpp"
#include "biphasic/time/bdf_integrator.hpp"

namespace biphasic::verification {

namespace {

const std::vector<double> kSweep{0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.15, 1.0 / 6, 0.2,
                                 0.25,  0.3,   0.35,  0.4,  0.45, 0.5,  0.6, 0.8,  1.0,     2.0};
constexpr double kVanished = 1e-3;

/// The load q of the case (normal traction on "top").
double load_of(const Config& config) {
  for (const auto& bc : config.bcs)
    if (bc.type == BcType::NormalTraction) return bc.value;
  throw std::runtime_error("oscillation case without a normal traction");
}

}  // namespace

FirstStepOvershoot first_step_overshoot(const Mesh& mesh, Config config, double r) {
  const double h = config.mesh.column.height / config.mesh.column.nz;
  const double c = config.material.get("permeability") *
                   (config.material.get("lambda") + 2.0 * config.material.get("mu"));
  config.time.dt = r * h * h / c;
  config.time.t_end = config.time.dt;
  BiphasicProblem problem(mesh, config);
  const auto integrator = make_time_integrator(problem, config.time, config.linear_solver, "");
  std::vector<double> y(problem.size(), 0.0);
  problem.apply_dirichlet(0.0, y.data(), nullptr);
  integrator->run(0.0, y, nullptr);

  const double q = load_of(config);
  std::map<long long, std::pair<double, int>> levels;  // layer index → (Σp, count)
  FirstStepOvershoot out{-1.0, -1.0};
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    const double p = y[problem.pattern().p_dof(v)];
    out.vertices = std::max(out.vertices, (p - q) / q);
    auto& level = levels[std::llround(mesh.nodes[v][2] / h)];
    level.first += p;
    ++level.second;
  }
  for (const auto& [k, sum] : levels)
    out.level_mean = std::max(out.level_mean, (sum.first / sum.second - q) / q);

  const LineProbe edge(mesh, {0.0, 0.0, 0.0}, {0.0, 0.0, config.mesh.column.height}, 1e-9);
  const std::vector<double> p_vertices(y.begin() + problem.num_u(), y.end());
  out.line_oscillation =
      line_measures(edge.s(), edge.pressure(p_vertices), drained_ends(edge, problem)).oscillation;
  return out;
}

OscillationSweep sweep_first_step(int nz) {
  const std::string width = std::to_string(1.0 / nz);
  const Config base = read_case_file(case_path("oscillation", "oscillation.toml"),
                                     {"mesh.column.nz=" + std::to_string(nz),
                                      "mesh.column.width=" + width, "mesh.column.depth=" + width});
  const Mesh mesh = build_mesh(base, "");
  OscillationSweep sweep;
  sweep.r = kSweep;
  for (const auto& [name, type] : {std::pair{"none", "none"}, std::pair{"gls", "gls"},
                                   std::pair{"flux_perturbation", "flux_perturbation"}}) {
    Config config = base;
    config.stabilisation.type = type;
    auto& values = sweep.overshoot[name];
    for (double r : kSweep) values.push_back(first_step_overshoot(mesh, config, r));
    // Bisection between the last r that overshoots and the first after which none does.
    auto threshold = [&](double FirstStepOvershoot::*measure) {
      std::size_t first_clean = values.size();
      while (first_clean > 0 && values[first_clean - 1].*measure < kVanished) --first_clean;
      if (first_clean == 0) return kSweep.front();
      if (first_clean == values.size()) return std::numeric_limits<double>::infinity();
      double lo = kSweep[first_clean - 1], hi = kSweep[first_clean];
      while (hi - lo > 1e-3 * hi) {
        const double mid = 0.5 * (lo + hi);
        (first_step_overshoot(mesh, config, mid).*measure < kVanished ? hi : lo) = mid;
      }
      return hi;
    };
    sweep.threshold[name] = threshold(&FirstStepOvershoot::vertices);
    sweep.level_threshold[name] = threshold(&FirstStepOvershoot::level_mean);
  }

  if (const auto out = verification_output("oscillation")) {
    const std::string suffix = "_nz" + std::to_string(nz) + ".csv";
    CsvWriter csv(*out / ("overshoot" + suffix),
                  "r,stabilisation,overshoot,level_mean_overshoot,line_oscillation");
    for (const auto& [name, values] : sweep.overshoot)
      for (std::size_t i = 0; i < kSweep.size(); ++i)
        csv.row(kSweep[i], name, values[i].vertices, values[i].level_mean,
                values[i].line_oscillation);
    CsvWriter thresholds(*out / ("thresholds" + suffix),
                         "stabilisation,r_vanishes,r_vanishes_level_mean");
    for (const auto& [name, r] : sweep.threshold)
      thresholds.row(name, r, sweep.level_threshold.at(name));
  }
  return sweep;
}

}  // namespace biphasic::verification
