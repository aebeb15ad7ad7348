// The command line of `biphasic run` and `check`: CASE [-o DIR] [--set key=value ...]
// [--restart DIR] [--overwrite] [--quiet], shared by the one-process and the MPI programs.
#pragma once

#include <string>
#include <vector>

#include "biphasic/app/run.hpp"

namespace biphasic {

struct RunArguments {
  std::string case_path, output_dir, restart_dir;
  std::vector<std::string> overrides;
  RunOptions options;  ///< overwrite and quiet set; the rest by the caller
};

/// Parses the arguments after the command. Throws std::invalid_argument for a missing value, a
/// second case file, no case file, or an unknown option; with `foreign_options`, an unknown
/// option (and a value after it that does not start with '-') is skipped instead: the MPI
/// program's PETSc options, which PETSc reads itself.
RunArguments parse_run_arguments(const std::vector<std::string>& args,
                                 bool foreign_options = false);

/// With --restart DIR: the run continues in DIR (output_dir = DIR, options.restart set).
/// Throws std::invalid_argument if -o names another folder or --overwrite is given too.
void continue_in_restart_folder(RunArguments& arguments);

}  // namespace biphasic
