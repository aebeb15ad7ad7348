// Command-line front end: biphasic run|check CASE [-o DIR] [--set key=value ...].
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "biphasic/app/preflight.hpp"
#include "biphasic/app/probes.hpp"
#include "biphasic/app/run.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/output_folder.hpp"
#include "biphasic/io/size_guard.hpp"
#include "biphasic/time/progress_meter.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace {

constexpr const char* kUsage = R"(usage:
  biphasic run CASE.toml [-o DIR] [--overwrite] [--set KEY=VALUE ...] [--quiet]
  biphasic run CASE.toml --restart DIR [--set KEY=VALUE ...] [--quiet]
  biphasic check CASE.toml [--set KEY=VALUE ...]   validate the case (and overrides) on its mesh
  biphasic schema            print the case-file reference (Markdown)
  biphasic --help | --version

run: solves the finite-strain biphasic problem described by CASE.toml and writes, as the run
goes, into DIR (default: results/<case name>, or results/<case name>--<key=value,...> with
--set overrides, characters other than letters, digits and . _ , = + - replaced by _):
  line.csv       t, s, x, y, z, ux, uy, uz, p on the probe line at every output time
  probe_NAME.csv the same on each [[probe]] line
  fields.h5      displacement (P2 nodes) and pressure per output time; open fields.xdmf in ParaView
  reactions.csv  t, boundary, Fx, Fy, Fz of the boundaries in output.reactions
  summary.json   resolved configuration, overrides, mesh size, per-step records, counters,
                 timings, and the final status: completed, failed (with the error) or invalid
DIR is locked while the run writes (a second run into it stops with the first one's pid). A DIR
holding an earlier run (a summary.json) is refused unless --overwrite, which deletes that run's
files first.
--restart DIR continues the run in DIR from its last checkpoint (checkpoint.bin, written at
every output) up to the case's time.t_end, which may be later than the first run's; give the
same case file and overrides. Backward Euler continues as if never stopped; BDF restarts IDA
from the checkpoint's state (docs/output_and_restart.md).
--set overrides any case-file key, e.g. --set material.permeability=1e-2
  --set stabilisation.type=gls --set boundary[0].value=-0.16
Exit status: 0 success, 1 bad input (all problems listed) or unusable output folder,
2 failed solve or failed write.
)";

/// `run`, or `check` (validate == true): reads and validates the case, then runs it or stops.
int run_command(const std::vector<std::string>& args, bool validate_only) {
  std::string case_path, out_dir, restart_dir;
  std::vector<std::string> overrides;
  biphasic::RunOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* flag) {
      if (i + 1 >= args.size()) throw std::invalid_argument(std::string(flag) + " needs a value");
      return args[++i];
    };
    if (a == "-o" || a == "--output") {
      out_dir = value("-o");
    } else if (a == "--set") {
      overrides.push_back(value("--set"));
    } else if (a.rfind("--set=", 0) == 0) {
      overrides.push_back(a.substr(6));
    } else if (a == "--restart") {
      restart_dir = value("--restart");
    } else if (a == "--overwrite") {
      options.overwrite = true;
    } else if (a == "--quiet" || a == "-q") {
      options.quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("unknown option '" + a + "'");
    } else if (case_path.empty()) {
      case_path = a;
    } else {
      throw std::invalid_argument("more than one case file given ('" + case_path + "', '" + a +
                                  "')");
    }
  }
  if (case_path.empty()) throw std::invalid_argument("run needs a case file");
  const biphasic::Config config = biphasic::read_case_file(case_path, overrides);
  biphasic::check_size(config, case_path, biphasic::available_memory());
  if (validate_only) {
    // Builds the mesh: names, formulas, constraints and probe points are checked on it.
    const std::vector<std::string> notes = biphasic::check_case(config);
    std::cout << case_path << ": valid; mesh size estimate: "
              << biphasic::describe(biphasic::estimate_size(config)) << "\n";
    for (const std::string& note : notes) std::cout << note << "\n";
    return 0;
  }
  if (!restart_dir.empty()) {
    if (!out_dir.empty() && out_dir != restart_dir)
      throw std::invalid_argument("--restart " + restart_dir + " writes into " + restart_dir +
                                  "; -o " + out_dir + " contradicts it");
    if (options.overwrite)
      throw std::invalid_argument("--restart continues a run, --overwrite deletes it: give one");
    out_dir = restart_dir;
    options.restart = true;
  }
  options.output_dir =
      out_dir.empty() ? biphasic::default_output_folder(case_path, overrides) : out_dir;
  options.overrides = overrides;
  options.progress_interval = biphasic::progress_interval_from_environment();
  biphasic::run_case(config, options);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << kUsage;
    return args.empty() ? 1 : 0;
  }
  if (args[0] == "--version") {
    std::cout << "biphasic " << BIPHASIC_VERSION << "\n" << biphasic::dependency_versions() << "\n";
    return 0;
  }
  try {
    if (args[0] == "schema") {
      std::cout << biphasic::case_schema_markdown();
      return 0;
    }
    if (args[0] == "run") return run_command({args.begin() + 1, args.end()}, false);
    if (args[0] == "check") return run_command({args.begin() + 1, args.end()}, true);
    throw std::invalid_argument("unknown command '" + args[0] + "' (try --help)");
  } catch (const biphasic::CaseError& e) {
    std::cerr << "error: the case has " << e.problems().size() << " problem(s):\n";
    for (const auto& p : e.problems()) std::cerr << "  " << p << "\n";
    return 1;
  } catch (const biphasic::CheckpointError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const biphasic::OutputFolderError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n" << kUsage;
    return 1;
  } catch (const biphasic::StepFailure& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
