// The size guard and input bounds through the command line: cases whose mesh cannot fit in
// memory (lc = 1e-4 meshed for minutes and grew without bound; a 200³ column and 10⁵ layers
// ran into std::bad_alloc) are refused with exit 1 before any meshing, naming the keys and
// the estimate; `check` reports the estimate of a valid case; a huge OMP_NUM_THREADS is
// clamped instead of crashing the OpenMP runtime.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

class SizeGuard : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir("biphasic_size_guard");
    case_ = (dir_ / "case.toml").string();
    // Held in z only (free rigid modes allowed) and without a probe line: the size guard is
    // what these tests are about, not the constraints or the probes.
    std::ofstream(case_) << "format_version = 1\n[output]\nline = false\n[constraints]\n"
                            "allow_free_rigid_modes = true\n[[boundary]]\nname = "
                            "\"bottom\"\ntype = \"displacement\"\ncomponent = \"z\"\nvalue = 0.0\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// `command` on the case with --set `overrides`, timed.
  Result timed(const std::string& command, const std::string& overrides, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    Result r =
        run(command + " " + case_ + " -o " + (dir_ / "out").string() + " --quiet " + overrides);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

  fs::path dir_;
  std::string case_;
};

TEST_F(SizeGuard, MeshesTooLargeForTheMachineAreRefusedBeforeMeshing) {
  struct Case {
    std::string overrides, keys;
  };
  const Case cases[] = {
      {"--set mesh.lc=1e-4", "mesh.radius, mesh.height, mesh.lc"},
      {"--set mesh.source=column --set mesh.column.nx=200 --set mesh.column.ny=200 "
       "--set mesh.column.nz=200",
       "mesh.column.nx, mesh.column.ny, mesh.column.nz"},
      {"--set mesh.layers=100000 --set mesh.lc=0.5", "mesh.radius, mesh.lc, mesh.layers"},
  };
  for (const Case& c : cases) {
    for (const char* command : {"run", "check"}) {
      double seconds = 0.0;
      const Result r = timed(command, c.overrides, seconds);
      EXPECT_EQ(r.status, 1) << command << " " << c.overrides << "\n" << r.output;
      EXPECT_NE(r.output.find(case_ + ": " + c.keys + ": the mesh would have about"),
                std::string::npos)
          << r.output;
      EXPECT_NE(r.output.find("GB available"), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("mesh.ignore_memory_estimate"), std::string::npos) << r.output;
      EXPECT_LT(seconds, 10.0) << command << " " << c.overrides;  // refused, not meshed
      EXPECT_FALSE(fs::exists(dir_ / "out" / "summary.json"));
    }
  }
}

// A column beyond the generator's limit of 10^8 cells is bad input even with the memory
// estimate overridden: exit 1 before any work (no allocation, no output folder), naming the
// case, the keys, the counts and the limit.
TEST_F(SizeGuard, ColumnsBeyondTheCellLimitAreRefusedEvenWithTheEstimateIgnored) {
  for (const char* command : {"run", "check"}) {
    double seconds = 0.0;
    const Result r = timed(command,
                           "--set mesh.source=column --set mesh.column.nx=1000 "
                           "--set mesh.column.ny=1000 --set mesh.column.nz=101 "
                           "--set mesh.ignore_memory_estimate=true",
                           seconds);
    EXPECT_EQ(r.status, 1) << command << "\n" << r.output;
    EXPECT_NE(r.output.find(case_ + ": mesh.column.nx, mesh.column.ny, mesh.column.nz: 1000 * "
                                    "1000 * 101 = 101000000 cells is more than the limit of "
                                    "100000000"),
              std::string::npos)
        << r.output;
    EXPECT_LT(seconds, 10.0) << command;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
}

TEST_F(SizeGuard, CheckReportsTheEstimateOfAValidCase) {
  const Result r = run("check " + case_ + " --set mesh.source=column");
  EXPECT_EQ(r.status, 0) << r.output;
  // The default column (1 x 1 x 10 cells, 60 tets) is counted exactly.
  EXPECT_NE(r.output.find("valid; mesh size estimate: about"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(60 tetrahedra)"), std::string::npos) << r.output;
}

TEST_F(SizeGuard, HugeThreadCountsAreClampedNotACrash) {
  const Result r = run("run " + case_ + " -o " + (dir_ / "threads").string() +
                           " --quiet --set mesh.source=column --set time.t_end=0.1 "
                           "--set time.dt=0.1",
                       "OMP_NUM_THREADS=1000000");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("OMP_NUM_THREADS=1000000 is more than"), std::string::npos) << r.output;
}

}  // namespace
