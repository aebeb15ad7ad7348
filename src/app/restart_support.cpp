#include "biphasic/app/restart_support.hpp"

#include <fstream>
#include <sstream>

namespace biphasic {

namespace {

std::string number_text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

void accept_checkpoint(const Checkpoint& c, const std::string& path, std::uint64_t case_hash,
                       std::size_t unknowns, const TimeConfig& time) {
  if (c.case_hash != case_hash) {
    throw CheckpointError("checkpoint " + path +
                          " belongs to another case or mesh: a restart needs the case file, "
                          "--set overrides and mesh of the earlier run (only time.t_end may "
                          "change)");
  }
  if (c.y.size() != unknowns) {
    throw CheckpointError("checkpoint " + path + " holds " + std::to_string(c.y.size()) +
                          " unknowns, the case has " + std::to_string(unknowns));
  }
  if (c.t > time.t_end + 1e-9 * time.dt) {
    throw CheckpointError("checkpoint " + path + " is at t = " + number_text(c.t) +
                          " s, after time.t_end = " + number_text(time.t_end) + " s");
  }
}

nlohmann::json read_earlier_summary(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw CheckpointError("nothing to restart: no " + path.string());
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw CheckpointError("cannot restart: " + path.string() + " is damaged (" + e.what() + ")");
  }
}

void record_restart(nlohmann::json& summary, const Checkpoint& c,
                    const std::vector<std::string>& overrides) {
  summary["restarts"].push_back({{"t", c.t}, {"step", c.step}, {"overrides", overrides}});
}

std::string restart_note(const Checkpoint& c, const std::string& path) {
  return "restart from " + path + ": output step " + std::to_string(c.step) +
         " at t = " + number_text(c.t) + " s";
}

nlohmann::json measures_json(const LineMeasures& m) {
  nlohmann::json j{{"p_mid", m.p_mid}, {"p_max", m.p_max}, {"p_min", m.p_min}};
  j["overshoot"] = m.defined ? nlohmann::json(m.overshoot) : nlohmann::json(nullptr);
  j["undershoot"] = m.defined ? nlohmann::json(m.undershoot) : nlohmann::json(nullptr);
  j["oscillation"] = m.defined ? nlohmann::json(m.oscillation) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json write_reactions(ReactionCsv& csv, double t, const std::vector<std::string>& names,
                               const std::vector<std::array<double, 3>>& forces) {
  csv.write(t, names, forces);
  nlohmann::json r = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size(); ++i) r[names[i]] = forces[i];
  return r;
}

nlohmann::json platens_description(const RigidPlatens& platens) {
  nlohmann::json list = nlohmann::json::array();
  for (const RigidPlaten& platen : platens.platens())
    list.push_back({{"boundary", platen.boundary},
                    {"component", platen.component},
                    {"area", platen.area},
                    {"unknown", platen.master}});
  return list;
}

nlohmann::json write_platens(PlatenCsv& csv, const RigidPlatens& platens, double t,
                             const double* y) {
  nlohmann::json r = nlohmann::json::object();
  for (std::size_t k = 0; k < platens.platens().size(); ++k) {
    const RigidPlaten& platen = platens.platens()[k];
    const double w = y[static_cast<std::size_t>(platen.master)];
    const double force = platens.force(k, t);
    csv.write(t, platen.boundary, w, force);
    r[platen.boundary] = {{"displacement", w}, {"force", force}};
  }
  return r;
}

nlohmann::json step_record(const StepInfo& info) {
  return {{"step", info.step},
          {"t", info.t},
          {"dt", info.dt},
          {"order", info.order},
          {"internal_steps", info.internal_steps},
          {"sub_steps", info.sub_steps},
          {"newton_iterations", info.newton_iterations},
          {"jacobian_evaluations", info.setups},
          {"residual_u", info.residual_u},
          {"residual_p", info.residual_p}};
}

}  // namespace biphasic
