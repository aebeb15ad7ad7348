// One simulation from a validated configuration: mesh → problem → integrator → outputs.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "biphasic/io/config.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/time/progress_meter.hpp"

namespace biphasic {

struct RunOptions {
  std::string output_dir = "results";
  bool quiet = false;  ///< no per-step lines, progress lines or notes on the terminal
  /// Wall time between BDF progress lines while IDA steps between outputs [s]; 0: after every
  /// internal step (main reads it from BIPHASIC_PROGRESS_INTERVAL).
  double progress_interval = kDefaultProgressInterval;
  bool overwrite = false;  ///< replace an earlier run in output_dir (--overwrite)
  bool restart = false;    ///< continue the run in output_dir from its checkpoint (--restart)
  std::vector<std::string> overrides;  ///< the --set key=value texts, recorded in summary.json
};

/// The mesh the configuration describes (generated or read); a relative mesh.write_msh is
/// written into `output_dir`. Generated quarter cylinders and sphere octants come from the mesh
/// cache (mesh_cache_directory()) when an earlier run made them and no .msh file is asked
/// for; `from_cache`, if given, tells whether this one did. Throws std::runtime_error on
/// failure.
Mesh build_mesh(const Config& config, const std::string& output_dir, bool* from_cache = nullptr);

/// Runs the case, writing into options.output_dir as the run goes:
///   line.csv      pressure and displacement on the probe line at each output time
///   fields.h5 / fields.xdmf   u on P2 nodes and p (ParaView, Tetrahedron_10)
///   reactions.csv t, boundary, Fx, Fy, Fz of each boundary in output.reactions [s, N]
///   platens.csv   t, platen, displacement, force of each rigid platen [s, mm, N]
///   summary.json  resolved configuration, mesh size, per-step records, outputs (line
///                 measures, reactions, platens), counters, timings
/// The folder is locked for the run and must not hold an earlier run unless options.overwrite
/// (see OutputFolder); its problems throw OutputFolderError before any work. Every write is
/// checked: a failed one stops the run with std::runtime_error naming file and cause, and the
/// files written before stay as they were. Returns the summary. summary.json always ends with
/// a final status: "completed"; "invalid" with the problems when input found faulty after the
/// folder was made (e.g. a boundary name the mesh lacks; the CaseError propagates); "failed"
/// with the error otherwise (the exception propagates).
///
/// A checkpoint.bin is written at every output time. With options.restart the run continues
/// from the checkpoint in output_dir up to the configuration's time.t_end, appending to the
/// earlier run's files; a missing, damaged or foreign checkpoint throws CheckpointError before
/// anything is written.
nlohmann::json run_case(const Config& config, const RunOptions& options);

/// Library versions linked into the build (SUNDIALS, SuiteSparse, gmsh, HDF5, Eigen, …).
std::string dependency_versions();

/// The summary's first entries: status "running", case file, overrides, version, dependency
/// versions and the configuration as read.
void start_summary(nlohmann::json& summary, const Config& config, const RunOptions& options);

}  // namespace biphasic
