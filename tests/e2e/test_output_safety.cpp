// The output folder end to end: a full disk stops the run with the cause and a final status,
// a locked or used folder is refused before any work, write_msh stays inside the folder, and
// the default folder tells overrides apart.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

nlohmann::json read_summary(const fs::path& dir) {
  return nlohmann::json::parse(read_text(dir / "summary.json"));
}

/// A column under a ramped compression: no gmsh, two output times, reactions of the bottom.
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
t_end = 2.0
dt = 1.0
[output]
line_start = [0, 0, 0]
line_end = [0, 0, 1]
reactions = ["bottom"]
)";

/// A fresh folder for one test, holding column.toml.
struct Work : FreshDir {
  explicit Work(const std::string& name) : FreshDir("biphasic_out_" + name) {
    write_text(dir / "column.toml", kColumn);
  }
  std::string run_args(const fs::path& out, const std::string& extra = "") const {
    return "run " + (dir / "column.toml").string() + " -o " + out.string() + " --quiet " + extra;
  }
};

TEST(OutputSafety, TheColumnRunCompletes) {
  const Work w("plain");
  const Result r = run(w.run_args(w.dir / "out"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_summary(w.dir / "out")["status"], "completed");
}

// Each output file in turn on a full device: exit 2 naming the file and the cause, and a
// summary.json that is whole and says "failed".
TEST(OutputSafety, AFullDiskStopsTheRunWithTheCause) {
  for (const char* file : {"line.csv", "reactions.csv", "fields.h5"}) {
    const Work w(std::string("full_") + file);
    const fs::path out = w.dir / "out";
    fs::create_directories(out);
    fs::create_symlink("/dev/full", out / file);
    const Result r = run(w.run_args(out));
    EXPECT_EQ(r.status, 2) << file << ": " << r.output;
    EXPECT_NE(r.output.find(file), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << file << r.output;
    const nlohmann::json s = read_summary(out);
    EXPECT_EQ(s["status"], "failed") << file;
    EXPECT_NE(s.value("error", std::string()).find(file), std::string::npos) << s.dump();
  }
}

// The summary itself cannot be written: the run stops (exit 2) instead of replacing it by an
// empty file and reporting success.
TEST(OutputSafety, AnUnwritableSummaryStopsTheRun) {
  const Work w("summary_full");
  const fs::path out = w.dir / "out";
  fs::create_directories(out);
  fs::create_symlink("/dev/full", out / "summary.json.tmp");
  const Result r = run(w.run_args(out));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("summary.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::is_symlink(out / "summary.json"));
}

TEST(OutputSafety, ALockedFolderIsRefusedWithTheHoldersPid) {
  const Work w("locked");
  const fs::path out = w.dir / "out";
  fs::create_directories(out);
  // Hold the lock as a running run would, under a made-up pid.
  const int fd = ::open((out / ".biphasic.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  ASSERT_EQ(::write(fd, "424242\n", 7), 7);
  const Result r = run(w.run_args(out));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pid 424242"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  ::close(fd);
  EXPECT_EQ(run(w.run_args(out)).status, 0);
}

// A second run into a used folder is refused; with --overwrite it replaces the first run as a
// whole (no reactions.csv of the first run beside the second's summary).
TEST(OutputSafety, AnEarlierRunIsRefusedOrReplacedAsAWhole) {
  const Work w("rerun");
  const fs::path out = w.dir / "out";
  ASSERT_EQ(run(w.run_args(out)).status, 0);
  ASSERT_TRUE(fs::exists(out / "reactions.csv"));
  const std::string first_line = read_text(out / "line.csv");

  const Result again = run(w.run_args(out, "--set output.reactions=[] --set output.line=false"));
  EXPECT_EQ(again.status, 1) << again.output;
  EXPECT_NE(again.output.find(out.string()), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("--overwrite"), std::string::npos) << again.output;
  EXPECT_EQ(read_text(out / "line.csv"), first_line);

  const Result over =
      run(w.run_args(out, "--overwrite --set output.reactions=[] --set output.line=false"));
  ASSERT_EQ(over.status, 0) << over.output;
  EXPECT_FALSE(fs::exists(out / "reactions.csv"));
  EXPECT_FALSE(fs::exists(out / "line.csv"));
  EXPECT_EQ(read_summary(out)["overrides"].size(), 2u);
}

TEST(OutputSafety, TheDefaultFolderNamesTheOverrides) {
  const Work w("default");
  ASSERT_EQ(run("run column.toml --quiet", "", w.dir).status, 0);
  const Result r = run("run column.toml --quiet --set time.dt=2.0", "", w.dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path with = w.dir / "results" / "column--time.dt=2.0";
  ASSERT_TRUE(fs::exists(with / "summary.json"));
  EXPECT_EQ(read_summary(with)["overrides"], nlohmann::json::array({"time.dt=2.0"}));
  EXPECT_EQ(read_summary(w.dir / "results" / "column")["configuration"]["time"]["dt"], 1.0);
}

TEST(OutputSafety, WriteMshStaysInsideTheOutputFolder) {
  const Work w("msh");
  for (const char* bad :
       {"../escape.msh", "/tmp/biphasic_escape.msh", "sub/../../x.msh", "mesh.dat", "line.csv"}) {
    const Result r =
        run("check " + (w.dir / "column.toml").string() +
            " --set mesh.source=\\\"quarter_cylinder\\\" --set mesh.write_msh=\\\"" + bad + "\\\"");
    EXPECT_EQ(r.status, 1) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("mesh.write_msh"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(bad), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("column.toml"), std::string::npos) << r.output;
  }
}

// Input found faulty after the folder was made (a boundary the mesh lacks) ends the summary
// with "invalid" and the problem, and exit 1.
TEST(OutputSafety, LateInputErrorsEndTheSummaryAsInvalid) {
  const Work w("invalid");
  const fs::path out = w.dir / "out";
  const Result r = run(w.run_args(out, "--set boundary[0].name=\\\"lid\\\""));
  EXPECT_EQ(r.status, 1) << r.output;
  const nlohmann::json s = read_summary(out);
  EXPECT_EQ(s["status"], "invalid");
  EXPECT_NE(s.value("error", nlohmann::json()).dump().find("lid"), std::string::npos) << s.dump();
}

TEST(OutputSafety, AnUnusableOutputPathIsBadInput) {
  const Work w("badpath");
  const fs::path file = w.dir / "a_file";
  std::ofstream(file) << "x\n";
  for (const fs::path& out : {file, file / "sub", fs::path("/proc/1")}) {
    const Result r = run(w.run_args(out));
    EXPECT_EQ(r.status, 1) << out << ": " << r.output;
    EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
  }
  EXPECT_EQ(read_text(file), "x\n");
}

}  // namespace
