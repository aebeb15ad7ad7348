// Progress lines under BDF end to end: BIPHASIC_PROGRESS_INTERVAL = 0 prints one after every
// internal step between outputs, with t, h, order, steps, factorisations, error-test failures
// and the wall time left; --quiet removes them; they leave the results bit for bit unchanged;
// a bad interval is refused before any work.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

/// A column under a ramped compression integrated by BDF: no gmsh, two output times, many
/// internal steps between them.
constexpr const char* kColumn = R"(format_version = 1
[mesh]
source = "column"
[mesh.column]
nz = 4
[curves]
ramp = [[0.0, 0.0], [1.0, 1.0]]
[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -0.1
curve = "ramp"
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
[time]
integrator = "bdf"
t_end = 2.0
dt = 1.0
[output]
line_start = [0, 0, 0]
line_end = [0, 0, 1]
)";

/// The lines of `text` that start with "progress".
std::vector<std::string> progress_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("progress", 0) == 0) lines.push_back(line);
  return lines;
}

struct Work : FreshDir {
  explicit Work(const std::string& name) : FreshDir("biphasic_progress_" + name) {
    write_text(dir / "column.toml", kColumn);
  }
  Result run_into(const std::string& out, const std::string& env,
                  const std::string& extra = "") const {
    return run(
        "run " + (dir / "column.toml").string() + " -o " + (dir / out).string() + " " + extra, env);
  }
};

TEST(Progress, ALineAfterEveryInternalStepWithItsFields) {
  const Work w("fields");
  const Result r = w.run_into("out", "BIPHASIC_PROGRESS_INTERVAL=0");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> lines = progress_lines(r.output);
  ASSERT_GE(lines.size(), 3u) << r.output;
  const std::regex format(
      R"(progress  t +(\S+) s \( *(\S+) %\)  h +(\S+) s  order ([1-5])  steps (\d+)  )"
      R"(factorisations (\d+)  error-test failures (\d+)  wall left (~.+|< 1 s|unknown))");
  double t_before = 0.0;
  long steps_before = 0;
  for (const std::string& line : lines) {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(line, m, format)) << line;
    const double t = std::stod(m[1]);
    const double percent = std::stod(m[2]);
    const double h = std::stod(m[3]);
    const long steps = std::stol(m[5]);
    EXPECT_GT(t, t_before) << line;
    EXPECT_LT(t, 2.0) << line;  // between outputs: none after the last one
    EXPECT_NEAR(percent, 100.0 * t / 2.0, 0.1) << line;
    EXPECT_GT(h, 0.0) << line;
    EXPECT_GT(steps, steps_before) << line;
    EXPECT_GE(std::stol(m[6]), 1) << line;
    t_before = t;
    steps_before = steps;
  }
  // The output lines are still there, each after the progress lines of its interval.
  EXPECT_NE(r.output.find("output    2/2"), std::string::npos) << r.output;
}

TEST(Progress, QuietRemovesThem) {
  const Work w("quiet");
  const Result r = w.run_into("out", "BIPHASIC_PROGRESS_INTERVAL=0", "--quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(progress_lines(r.output).empty()) << r.output;
  EXPECT_EQ(r.output, "");
}

TEST(Progress, TheResultsAreBitIdenticalWithAndWithoutThem) {
  const Work w("identical");
  ASSERT_EQ(w.run_into("every_step", "BIPHASIC_PROGRESS_INTERVAL=0", "--quiet").status, 0);
  ASSERT_EQ(w.run_into("never", "BIPHASIC_PROGRESS_INTERVAL=1e9", "--quiet").status, 0);
  const std::string a = read_text(w.dir / "every_step" / "line.csv");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, read_text(w.dir / "never" / "line.csv"));
}

TEST(Progress, ABadIntervalIsRefusedBeforeAnyWork) {
  const Work w("bad");
  for (const char* value : {"two", "-1", "2s", "inf"}) {
    const Result r =
        w.run_into("out", std::string("BIPHASIC_PROGRESS_INTERVAL=") + value, "--quiet");
    EXPECT_EQ(r.status, 1) << value << ":\n" << r.output;
    EXPECT_NE(r.output.find("BIPHASIC_PROGRESS_INTERVAL"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(w.dir / "out" / "summary.json")) << value;
  }
}

}  // namespace
