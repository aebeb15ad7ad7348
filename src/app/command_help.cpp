#include "biphasic/app/command_help.hpp"

namespace biphasic {

namespace {

/// What `run` writes into its output folder; in the program's and in run's help.
constexpr const char* kRunFiles =
    R"(  line.csv       t, s, x, y, z, ux, uy, uz, p on the probe line at every output time
  probe_NAME.csv the same on each [[probe]] line
  fields.h5      displacement (P2 nodes) and pressure per output time; open fields.xdmf in ParaView
  reactions.csv  t, boundary, Fx, Fy, Fz of the boundaries in output.reactions
  platens.csv    t, platen, displacement, force of each rigid_platen condition
  summary.json   resolved configuration, overrides, mesh size, per-step records, counters,
                 timings, and the final status: completed, failed (with the error) or invalid
)";

constexpr const char* kProgramHead = R"(usage:
  biphasic run CASE.toml [-o DIR] [--overwrite] [--set KEY=VALUE ...] [--quiet]
  biphasic run CASE.toml --restart DIR [--set KEY=VALUE ...] [--quiet]
  biphasic check CASE.toml [--set KEY=VALUE ...]   validate the case (and overrides) on its mesh
  biphasic schema [--json]   print the case-file reference (Markdown, or JSON Schema)
  biphasic --help | --version
  biphasic COMMAND --help    the options of one command (run, check, schema)

run: solves the finite-strain biphasic problem described by CASE.toml and writes, as the run
goes, into DIR (default: results/<case name>, or results/<case name>--<key=value,...> with
--set overrides, characters other than letters, digits and . _ , = + - replaced by _):
)";

constexpr const char* kProgramTail =
    R"(DIR is locked while the run writes (a second run into it stops with the first one's pid). A DIR
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

constexpr const char* kRunHead = R"(usage:
  biphasic run CASE.toml [-o DIR] [--overwrite] [--set KEY=VALUE ...] [--quiet]
  biphasic run CASE.toml --restart DIR [--set KEY=VALUE ...] [--quiet]

Solves the finite-strain biphasic problem described by CASE.toml (validated first, as check
does) and writes the results into DIR as the run goes. Prints a line per output time, notes
such as the oscillation advisor's and backward Euler's cut-backs, and under BDF (and adaptive
backward Euler) a progress line every 2 s of wall time between outputs: t, h, order, internal
steps, factorisations, error-test failures and the estimated wall time left.

arguments:
  CASE.toml              the case file (its keys: biphasic schema, docs/case_file.md)

options:
  -o, --output DIR       output folder; default results/<case name>, or with --set overrides
                         results/<case name>--<key=value,...> (characters other than letters,
                         digits and . _ , = + - replaced by _)
  --overwrite            replace an earlier run in DIR (its files are deleted first); without
                         it a DIR holding a summary.json is refused
  --restart DIR          continue the run in DIR from its last checkpoint (checkpoint.bin) up to
                         the case's time.t_end; give the same case file and overrides
  --set KEY=VALUE        override a case-file key (repeatable; also --set=KEY=VALUE), e.g.
                         --set material.permeability=1e-2 --set boundary[0].value=-0.16
  -q, --quiet            print nothing but errors: no step, progress or note lines
  -h, --help             this help

files written into DIR:
)";

constexpr const char* kRunTail = R"(  checkpoint.bin the state at the last output, for --restart
  steps.csv      BDF with time.bdf.step_log = true: t, h, order of every internal step

environment:
  BIPHASIC_PROGRESS_INTERVAL  wall time between BDF progress lines [s] (default 2; 0: after
                              every internal step)
  BIPHASIC_MESH_CACHE         folder of the mesh cache, or "off" (default
                              ~/.cache/biphasic/meshes)
  OMP_NUM_THREADS             threads of the assembly

exit status: 0 success, 1 bad input (all problems listed) or unusable output folder (locked by
another run, or holding an earlier run without --overwrite), 2 failed solve or failed write.
)";

constexpr const char* kCheckHelp = R"(usage:
  biphasic check CASE.toml [--set KEY=VALUE ...]

Validates the case file and the overrides as run does, without running: every key, type,
range and name is checked, then the mesh is built (or taken from the mesh cache) and the
boundary names, formulas, constraints (no free rigid-body mode, no conflicting conditions) and
probe points are checked on it (docs/constraints.md). Prints "valid", the mesh size estimate
and notes; writes no results.

arguments:
  CASE.toml              the case file (its keys: biphasic schema, docs/case_file.md)

options:
  --set KEY=VALUE        override a case-file key (repeatable; also --set=KEY=VALUE), e.g.
                         --set mesh.layers=24
  -h, --help             this help

exit status: 0 valid, 1 bad input (all problems listed, each naming the file, the key and the
value).
)";

constexpr const char* kSchemaHelp = R"(usage:
  biphasic schema [--json]

Prints the case-file reference in Markdown: every key with its type, default, allowed values
or range, unit and meaning (the same text as docs/case_file.md).

options:
  --json                 the same schema as JSON Schema (draft-07), for editors and validators:
                         biphasic schema --json > biphasic-case.schema.json (docs/case_file.md,
                         *Editor support*)
  -h, --help             this help

exit status: 0.
)";

constexpr const char* kHelpHelp = R"(usage:
  biphasic help [COMMAND]

Prints the whole program's help, or with COMMAND (run, check, schema, help) that command's help,
the same as biphasic COMMAND --help.

arguments:
  COMMAND                run, check, schema or help

options:
  -h, --help             this help

exit status: 0, or 1 for an unknown COMMAND.
)";

}  // namespace

std::string program_usage() { return std::string(kProgramHead) + kRunFiles + kProgramTail; }

std::vector<std::string> command_names() { return {"run", "check", "schema", "help"}; }

std::optional<std::string> command_help(std::string_view command) {
  if (command == "run") return std::string(kRunHead) + kRunFiles + kRunTail;
  if (command == "check") return std::string(kCheckHelp);
  if (command == "schema") return std::string(kSchemaHelp);
  if (command == "help") return std::string(kHelpHelp);
  return std::nullopt;
}

}  // namespace biphasic
