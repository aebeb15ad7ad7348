// A case run on several MPI processes (docs/parallel.md): the same case file and output folder
// as a one-process run, with what runs distributed so far.
#pragma once

#include <mpi.h>

#include <nlohmann/json.hpp>

#include "biphasic/app/run.hpp"
#include "biphasic/io/config.hpp"

namespace biphasic {

/// Runs `config` on the processes of `comm` (collective). Process 0 builds the mesh (mesh
/// cache included) and sends it to the others, holds the output folder, writes line.csv (and
/// the [[probe]] files), reactions.csv, fields.h5 (displacement and pressure) and
/// summary.json, and prints the progress; every process assembles its part and takes part in
/// the solves. Supported so far: three-dimensional models, backward Euler, linear_solver.type
/// = "mumps" (the parallel MUMPS through PETSc). Anything else is refused before any work with
/// std::invalid_argument naming the key. Failures are thrown on every process; process 0
/// records them in summary.json first. Returns the summary (complete on process 0).
///
/// Process 0 writes checkpoint.bin at every output exactly as a one-process run of the case
/// would (state, rate and integrator state gathered into the one-process layout), and with
/// options.restart every process continues from its part of such a checkpoint, written on any
/// number of processes; a missing, damaged or foreign checkpoint throws CheckpointError on
/// every process before anything is written (run_case in app/run.hpp).
nlohmann::json run_distributed(const Config& config, const RunOptions& options, MPI_Comm comm);

}  // namespace biphasic
