// Runs that fail, end to end: the binary exits 2 and names the step, the time, the step size
// and the cause in words (no raw SUNDIALS flag numbers); summary.json ends with status "failed"
// and the error; the outputs written before the failure stay. And a step count beyond the
// limit refused by `check` (exit 1) naming time.dt, time.t_end and the count.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

fs::path folder() { return scratch_dir("biphasic_failed"); }

fs::path write_case(const std::string& name, const std::string& text) {
  return write_text(folder() / name, text);
}

/// The times in line.csv's first column.
std::set<std::string> line_times(const fs::path& path) {
  std::set<std::string> times;
  std::ifstream in(path);
  std::string row;
  std::getline(in, row);  // header
  while (std::getline(in, row)) times.insert(row.substr(0, row.find(',')));
  return times;
}

/// A 1 mm column whose top is pushed down 1 % by t = 1 s and then through the bottom (120 %) by
/// t = 2 s: the second second must fail, whatever the integrator.
std::string crushing_case(const std::string& time_section) {
  return R"(format_version = 1
[mesh]
source = "column"
[mesh.column]
nz = 4
[material]
lambda = 0.2
mu = 0.5
permeability = 1e-2
[curves]
crush = [[0.0, 0.0], [1.0, 0.01], [2.0, 1.0]]
[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -1.2
curve = "crush"
[[boundary]]
name = "top"
type = "pressure"
value = 0.0
[[boundary]]
name = "bottom"
type = "displacement"
component = "z"
value = 0.0
[[boundary]]
name = "x0"
type = "symmetry"
[[boundary]]
name = "y0"
type = "symmetry"
[linear_solver]
type = "klu"
ordering = "amd"
[output]
fields = false
line_start = [0.0, 0.0, 0.0]
line_end = [0.0, 0.0, 1.0]
)" + time_section;
}

void expect_failed_run(const Result& r, const fs::path& out,
                       const std::vector<std::string>& parts) {
  EXPECT_EQ(r.status, 2) << r.output;
  for (const std::string& part : parts)
    EXPECT_NE(r.output.find(part), std::string::npos) << "lacks '" << part << "':\n" << r.output;
  for (const char* raw : {"KINSOL flag", "IDA flag"})
    EXPECT_EQ(r.output.find(raw), std::string::npos) << r.output;
  const nlohmann::json summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary.at("status"), "failed");
  const std::string error = summary.at("error");
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "summary error lacks '" << part << "'";
  // The rows of t = 0 and t = 1 s, written before the failure, are kept.
  EXPECT_EQ(line_times(out / "line.csv"), (std::set<std::string>{"0", "1"}));
}

TEST(FailedRun, BackwardEulerWithoutCutbacksNamesStepTimeDtAndCause) {
  const fs::path file = write_case("crush_be.toml", crushing_case(R"([time]
t_end = 3.0
dt = 1.0
[time.newton]
max_cutbacks = 0
)"));
  const fs::path out = folder() / "crush_be";
  const Result r = run("run " + file.string() + " -o " + out.string());
  expect_failed_run(r, out, {"backward Euler step 2", "t = 2 s", "dt = 1 s", "(element inverted)"});
}

TEST(FailedRun, BdfNamesStepTimeStepSizeAndCause) {
  const fs::path file = write_case("crush_bdf.toml", crushing_case(R"([time]
integrator = "bdf"
t_end = 3.0
dt = 1.0
)"));
  const fs::path out = folder() / "crush_bdf";
  const Result r = run("run " + file.string() + " -o " + out.string());
  expect_failed_run(r, out, {"BDF output step 2", "internal step", "from t = ", "h = ", "(IDA_"});
}

/// The crushing column with a Holmes–Mow permeability whose pores close at J = φ₀ = 0.6, long
/// before an element inverts: J ≤ φ₀ is a recoverable failure (steps are retried smaller), and
/// when no smaller step helps the run stops naming the element, the law, φ₀, the step and the
/// time, keeping what it wrote.
const std::string kClosingPores =
    " --set 'material.permeability_law=\"holmes_mow\"' --set material.solid_fraction=0.6"
    " --set material.permeability_kappa=1";

TEST(FailedRun, PoresClosingUnderBackwardEulerAreRetriedThenNamed) {
  const fs::path file = write_case("compact_be.toml", crushing_case(R"([time]
t_end = 3.0
dt = 1.0
[time.newton]
max_cutbacks = 3
)"));
  const fs::path out = folder() / "compact_be";
  const Result r = run("run " + file.string() + " -o " + out.string() + kClosingPores);
  expect_failed_run(r, out,
                    {"backward Euler step 2", "after 3 cut-backs", "element ",
                     "Holmes-Mow permeability", "phi0 = 0.6", "the pores have closed"});
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
}

TEST(FailedRun, PoresClosingUnderBdfAreRetriedThenNamed) {
  const fs::path file = write_case("compact_bdf.toml", crushing_case(R"([time]
integrator = "bdf"
t_end = 3.0
dt = 1.0
)"));
  const fs::path out = folder() / "compact_bdf";
  const Result r = run("run " + file.string() + " -o " + out.string() + kClosingPores);
  expect_failed_run(r, out,
                    {"BDF output step 2", "from t = ", "after step reductions", "element ",
                     "Holmes-Mow permeability", "phi0 = 0.6", "the pores have closed"});
}

TEST(StepLimit, CheckRefusesMoreStepsThanTheLimit) {
  const fs::path file = write_case("many_steps.toml", crushing_case(R"([time]
t_end = 32.0
dt = 1e-8
)"));
  const Result r = run("check " + file.string());
  EXPECT_EQ(r.status, 1) << r.output;
  for (const char* part : {"many_steps.toml", "time.dt", "time.t_end", "3200000000"})
    EXPECT_NE(r.output.find(part), std::string::npos) << "lacks '" << part << "':\n" << r.output;
  const Result huge = run("check " + file.string() + " --set time.t_end=1e308 --set time.dt=1.0");
  EXPECT_EQ(huge.status, 1) << huge.output;
  EXPECT_NE(huge.output.find("time.t_end"), std::string::npos) << huge.output;
}

}  // namespace
