// Command-line front end: biphasic run|check CASE [-o DIR] [--set key=value ...], biphasic
// schema, biphasic help [COMMAND], and COMMAND --help (command_help.hpp).
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "biphasic/app/command_help.hpp"
#include "biphasic/app/preflight.hpp"
#include "biphasic/app/probes.hpp"
#include "biphasic/app/run.hpp"
#include "biphasic/app/run_arguments.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/output_folder.hpp"
#include "biphasic/io/size_guard.hpp"
#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/time/progress_meter.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace {

/// Whether the arguments after the command ask for its help.
bool asks_for_help(const std::vector<std::string>& args) {
  for (std::size_t i = 1; i < args.size(); ++i)
    if (args[i] == "--help" || args[i] == "-h") return true;
  return false;
}

/// `run`, or `check` (validate == true): reads and validates the case, then runs it or stops.
int run_command(const std::vector<std::string>& args, bool validate_only) {
  biphasic::RunArguments parsed = biphasic::parse_run_arguments(args);
  const std::string& case_path = parsed.case_path;
  const std::string& out_dir = parsed.output_dir;
  const std::vector<std::string>& overrides = parsed.overrides;
  biphasic::RunOptions& options = parsed.options;
  const biphasic::Config config = biphasic::read_case_file(case_path, overrides);
  biphasic::check_size(config, case_path, biphasic::available_memory());
  if (config.linear_solver.type == biphasic::LinearSolverType::SuperluDist && !validate_only)
    throw std::invalid_argument(case_path + ": " + biphasic::kSuperluDistNeedsProcesses);
  if (validate_only) {
    // Builds the mesh: names, formulas, constraints and probe points are checked on it.
    const std::vector<std::string> notes = biphasic::check_case(config);
    std::cout << case_path << ": valid; mesh size estimate: "
              << biphasic::describe(biphasic::estimate_size(config)) << "\n";
    for (const std::string& note : notes) std::cout << note << "\n";
    return 0;
  }
  biphasic::continue_in_restart_folder(parsed);
  options.output_dir =
      out_dir.empty() ? biphasic::default_output_folder(case_path, overrides) : out_dir;
  options.overrides = overrides;
  options.progress_interval = biphasic::progress_interval_from_environment();
  biphasic::run_case(config, options);
  return 0;
}

}  // namespace

/// Processes mpirun started: Open MPI sets OMPI_COMM_WORLD_SIZE, MPICH and Intel MPI PMI_SIZE.
int mpi_world_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::atoi(v);
  return 1;
}

/// `run` under mpirun with more than one process: the MPI program takes over this process
/// (docs/parallel.md); it lies next to this one, else where the build put it. Returns only if
/// it could not be started.
void hand_over_to_mpi_program(char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  std::string program = ec ? std::string() : (self.parent_path() / "biphasic_mpi").string();
  if (program.empty() || !std::filesystem::exists(program)) program = BIPHASIC_MPI_PROGRAM;
  // One thread per process unless the user says otherwise: mpirun starts a process per core,
  // and OpenMP or OpenBLAS threads on top of them would oversubscribe the cores. (Set before
  // the exec: OpenBLAS reads its variable when it is loaded.)
  setenv("OMP_NUM_THREADS", "1", 0);
  setenv("OPENBLAS_NUM_THREADS", "1", 0);
  argv[0] = program.data();
  execv(program.c_str(), argv);
  std::cerr << "error: biphasic was started by mpirun with " << mpi_world_size()
            << " processes, but the MPI program " << program << " could not be started ("
            << std::strerror(errno) << ")\n";
}

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0] == "run" && mpi_world_size() > 1) {
    hand_over_to_mpi_program(argv);
    return 2;
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::cout << biphasic::program_usage();
    return args.empty() ? 1 : 0;
  }
  if (args[0] == "help") {
    if (args.size() < 2 || args[1] == "--help" || args[1] == "-h") {
      std::cout << (args.size() < 2 ? biphasic::program_usage() : *biphasic::command_help("help"));
      return 0;
    }
    if (const auto help = biphasic::command_help(args[1])) {
      std::cout << *help;
      return 0;
    }
    std::cerr << "error: unknown command '" << args[1] << "' (try --help)\n";
    return 1;
  }
  // COMMAND --help anywhere among the command's arguments: that command's help, nothing run.
  if (const auto help = biphasic::command_help(args[0]); help && asks_for_help(args)) {
    std::cout << *help;
    return 0;
  }
  if (args[0] == "--version") {
    std::cout << "biphasic " << BIPHASIC_VERSION << "\n" << biphasic::dependency_versions() << "\n";
    return 0;
  }
  try {
    if (args[0] == "schema") {
      const bool as_json = args.size() == 2 && args[1] == "--json";
      if (args.size() > 1 && !as_json)
        throw std::invalid_argument("schema takes no arguments but --json ('" + args[1] +
                                    "' given)");
      if (as_json)
        std::cout << biphasic::case_json_schema().dump(2) << '\n';
      else
        std::cout << biphasic::case_schema_markdown();
      return 0;
    }
    if (args[0] == "run") return run_command({args.begin() + 1, args.end()}, false);
    if (args[0] == "check") return run_command({args.begin() + 1, args.end()}, true);
    throw std::invalid_argument("unknown command '" + args[0] + "' (try --help)");
  } catch (const biphasic::CaseError& e) {
    std::cerr << "error: " << e.report() << "\n";
    return 1;
  } catch (const biphasic::CheckpointError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const biphasic::OutputFolderError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n" << biphasic::program_usage();
    return 1;
  } catch (const biphasic::StepFailure& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
