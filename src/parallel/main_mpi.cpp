// biphasic_mpi: `biphasic run` on several MPI processes (docs/parallel.md). Started by mpirun,
// directly or through `biphasic`, which hands over to it when mpirun started more than one
// process. Options: run CASE [-o DIR] [--set key=value ...] [--restart DIR] [--overwrite]
// [--quiet]; PETSc options (e.g. -biphasic_mat_mumps_icntl_14 40) may follow on the same
// command line.
#include <petscsys.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/app/run_arguments.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/output_folder.hpp"
#include "biphasic/parallel/distributed_run.hpp"
#include "biphasic/parallel/exit_guard.hpp"
#include "biphasic/time/progress_meter.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace {

int run(const std::vector<std::string>& args, int rank) {
  if (args.empty() || args[0] != "run")
    throw std::invalid_argument(
        "biphasic_mpi runs cases only: biphasic_mpi run CASE [-o DIR] [--set key=value ...] "
        "[--restart DIR] [--overwrite] [--quiet] (check, schema and help: biphasic)");
  biphasic::RunArguments parsed =
      biphasic::parse_run_arguments({args.begin() + 1, args.end()}, /*foreign_options=*/true);
  const std::string& case_path = parsed.case_path;
  const std::vector<std::string>& overrides = parsed.overrides;
  biphasic::RunOptions& options = parsed.options;
  biphasic::continue_in_restart_folder(parsed);
  const std::string& out_dir = parsed.output_dir;
  const biphasic::Config config = biphasic::read_case_file(case_path, overrides);
  options.output_dir =
      out_dir.empty() ? biphasic::default_output_folder(case_path, overrides) : out_dir;
  options.overrides = overrides;
  options.quiet = options.quiet || rank != 0;
  biphasic::run_distributed(config, options, PETSC_COMM_WORLD);
  return 0;
}

}  // namespace

// OpenBLAS's own thread control, if OpenBLAS is the BLAS loaded (weak: absent otherwise).
extern "C" void openblas_set_num_threads(int) __attribute__((weak));

int main(int argc, char** argv) {
  // One thread per process unless the user says otherwise (mpirun starts a process per core).
  setenv("OMP_NUM_THREADS", "1", 0);
  if (!std::getenv("OPENBLAS_NUM_THREADS") && openblas_set_num_threads) openblas_set_num_threads(1);
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) return 2;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  biphasic::arm_exit_guard(PETSC_COMM_WORLD);
  int status = 0;
  // Every process reads the case and meets the same errors; process 0 reports them.
  auto report = [&](const std::string& text, int code) {
    if (rank == 0) std::cerr << text;
    status = code;
  };
  try {
    status = run(std::vector<std::string>(argv + 1, argv + argc), rank);
  } catch (const biphasic::CaseError& e) {
    report("error: " + e.report() + "\n", 1);
  } catch (const std::invalid_argument& e) {
    report(std::string("error: ") + e.what() + "\n", 1);
  } catch (const biphasic::CheckpointError& e) {
    report(std::string("error: ") + e.what() + "\n", 1);
  } catch (const biphasic::OutputFolderError& e) {
    report(std::string("error: ") + e.what() + "\n", 1);
  } catch (const std::exception& e) {
    report(std::string("error: ") + e.what() + "\n", 2);
  }
  biphasic::disarm_exit_guard();
  PetscFinalize();
  return status;
}
