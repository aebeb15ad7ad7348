// What a run on one process (run.cpp) and a run on several (distributed_run.cpp) share to write
// and continue checkpoints: the checkpoint's name and fingerprint, its checks, the summary of
// the run being continued and the records the checkpoint carries on (the summary's entries, and
// the output rows of reactions.csv and platens.csv that go with them). Both write the same
// checkpoint.bin, so that either can continue the other's run (docs/output_and_restart.md).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/io/platen_csv.hpp"
#include "biphasic/io/reaction_csv.hpp"
#include "biphasic/physics/rigid_platen.hpp"
#include "biphasic/study/measures.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace biphasic {

/// The checkpoint's file name in the output folder.
inline constexpr const char* kCheckpointName = "checkpoint.bin";

/// Fingerprint of what a checkpoint's state depends on: the resolved configuration except
/// time.t_end (a restart may go further), the title and the case file's name, and the mesh's
/// nodes and elements (tetrahedra, or a section's triangles). The number of processes is not
/// part of it: the state is stored in the one-process layout.
template <class Elements>
std::uint64_t case_fingerprint(const Config& config, const auto& nodes, const Elements& elements) {
  nlohmann::json physical = config_to_json(config);
  physical.erase("case_file");
  physical.erase("title");
  if (physical.contains("time")) physical["time"].erase("t_end");
  std::uint64_t h = fnv1a64(physical.dump());
  auto bytes = [](const auto& v) {
    return std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v.front()));
  };
  h = fnv1a64(bytes(nodes), h);
  return fnv1a64(bytes(elements), h);
}

/// Checks that a checkpoint (read from `path`) belongs to this case and mesh (`case_hash`,
/// `unknowns` in the whole system) and lies before time.t_end; throws CheckpointError if not.
void accept_checkpoint(const Checkpoint& c, const std::string& path, std::uint64_t case_hash,
                       std::size_t unknowns, const TimeConfig& time);

/// The summary.json of the run being continued; throws CheckpointError if there is none or it
/// cannot be parsed.
nlohmann::json read_earlier_summary(const std::filesystem::path& path);

/// Appends this restart (checkpoint time, output step, the --set overrides) to the summary's
/// "restarts" list.
void record_restart(nlohmann::json& summary, const Checkpoint& c,
                    const std::vector<std::string>& overrides);

/// The log line of a restart: "restart from PATH: output step k at t = T s".
std::string restart_note(const Checkpoint& c, const std::string& path);

/// One step's entry of the summary's "steps" list (and of the checkpoint's record).
nlohmann::json step_record(const StepInfo& info);

/// The line measures of one output as the summary's "outputs" entries record them (overshoot,
/// undershoot and oscillation null where the measures are not defined).
nlohmann::json measures_json(const LineMeasures& m);

/// Writes one output's row of reactions.csv and returns the output's "reactions" entry,
/// {label: [Fx, Fy, Fz]} [N].
nlohmann::json write_reactions(ReactionCsv& csv, double t, const std::vector<std::string>& names,
                               const std::vector<std::array<double, 3>>& forces);

/// The summary's "platens" list: each platen's boundary, component, area [mm²] and the unknown
/// (one-process layout) that carries its displacement.
nlohmann::json platens_description(const RigidPlatens& platens);

/// Writes one output's rows of platens.csv, each platen's displacement y[master] [mm] (y in the
/// one-process layout) and prescribed force [N], and returns the output's "platens" entry.
nlohmann::json write_platens(PlatenCsv& csv, const RigidPlatens& platens, double t,
                             const double* y);

}  // namespace biphasic
