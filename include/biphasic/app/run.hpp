// One simulation from a validated configuration: mesh → problem → integrator → outputs.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "biphasic/io/config.hpp"

namespace biphasic {

struct RunOptions {
  std::string output_dir = "results";
  bool quiet = false;  ///< no per-step lines on the terminal
};

/// Runs the case, writing into options.output_dir as the run goes:
///   line.csv      pressure and displacement on the probe line at each output time
///   fields.h5 / fields.xdmf   u on P2 nodes and p (ParaView, Tetrahedron_10)
///   summary.json  resolved configuration, mesh size, per-step records, counters, timings
/// Returns the summary. On a failed step the summary records the failure (status "failed")
/// and the StepFailure propagates.
nlohmann::json run_case(const Config& config, const RunOptions& options);

/// Library versions linked into the build (SUNDIALS, SuiteSparse, gmsh, HDF5, Eigen, …).
std::string dependency_versions();

}  // namespace biphasic
