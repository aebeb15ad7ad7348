// The command line: help, version, and bad case files rejected with their messages and a
// non-zero exit before any work starts.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

fs::path write_case(const std::string& name, const std::string& text) {
  return write_text(scratch_dir("biphasic_cli") / name, text);
}

const char* kValid = R"(format_version = 1
[mesh]
lc = 4.0
[[boundary]]
name = "bottom"
type = "displacement"
component = "z"
value = 0.0
[[boundary]]
name = "symmetry_x"
type = "symmetry"
[[boundary]]
name = "symmetry_y"
type = "symmetry"
)";

TEST(Cli, HelpAndVersion) {
  const Result help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("biphasic run CASE.toml"), std::string::npos);
  const Result version = run("--version");
  EXPECT_EQ(version.status, 0);
  for (const char* lib : {"SUNDIALS 6.4", "SuiteSparse", "gmsh", "HDF5", "Eigen 3.4"})
    EXPECT_NE(version.output.find(lib), std::string::npos) << lib;
}

TEST(Cli, BadInputIsReportedWithFileKeyAndValue) {
  struct Case {
    const char* name;
    std::string text;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {"syntax.toml", "format_version = 1\n[mesh\n", {"syntax.toml", "TOML"}},
      {"unknown.toml", std::string(kValid) + "[time]\ndtt = 1.0\n", {"time.dtt", "time.dt"}},
      {"type.toml", std::string(kValid) + "[time]\ndt = \"fast\"\n", {"time.dt", "fast"}},
      {"range.toml", std::string(kValid) + "[material]\nmu = -0.5\n", {"material.mu", "-0.5"}},
      {"choice.toml",
       std::string(kValid) + "[stabilisation]\ntype = \"glss\"\n",
       {"stabilisation.type", "glss"}},
      {"curve.toml",
       std::string(kValid) +
           "[[boundary]]\nname = \"top\"\ntype = \"pressure\"\nvalue = 0.0\ncurve = \"rampp\"\n",
       {"boundary[3].curve", "rampp"}},
  };
  for (const Case& c : cases) {
    const fs::path file = write_case(c.name, c.text);
    const Result r = run("run " + file.string() + " -o " + (file.parent_path() / "out").string());
    EXPECT_EQ(r.status, 1) << c.name << ":\n" << r.output;
    for (const std::string& e : c.expected)
      EXPECT_NE(r.output.find(e), std::string::npos) << c.name << " lacks '" << e << "':\n"
                                                     << r.output;
    EXPECT_EQ(r.output.find("mesh:"), std::string::npos) << "work started for " << c.name;
  }
}

TEST(Cli, UnknownBoundaryNameListsTheMeshBoundaries) {
  const fs::path file = write_case("boundary.toml", std::string(kValid) + R"([[boundary]]
name = "lid"
type = "pressure"
value = 0.0
)");
  const Result r = run("run " + file.string() + " -o " + (file.parent_path() / "out").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("lid"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("symmetry_x"), std::string::npos) << r.output;
}

TEST(Cli, BadOverrideIsReported) {
  const fs::path file = write_case("valid.toml", kValid);
  const Result r = run("run " + file.string() + " --set time.dt=-1");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("--set"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("time.dt"), std::string::npos) << r.output;
}

// SuperLU_DIST exists in the MPI program only: one process refuses it before any work, naming
// the file and the key, and writes nothing.
TEST(Cli, SuperluDistInOneProcessIsRefusedNamingTheKey) {
  const fs::path file = write_case("superlu.toml", kValid);
  const fs::path out = scratch_dir("biphasic_cli") / "superlu_out";
  fs::remove_all(out);
  const Result r = run("run " + file.string() + " -o " + out.string() +
                       " --set linear_solver.type=\"superlu_dist\"");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("linear_solver.type"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("mpirun"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// A generated mesh is cached by the first run and read back by the second (without gmsh), with
// the same results to the last digit.
TEST(Cli, SecondRunTakesTheMeshFromTheCache) {
  const fs::path file = write_case("cached.toml", std::string(kValid) + R"([time]
dt = 6.4
t_end = 6.4
[output]
fields = false
)");
  const fs::path cache = file.parent_path() / "mesh_cache";
  fs::remove_all(cache);
  const std::string env = "BIPHASIC_MESH_CACHE=" + cache.string();
  const Result first =
      run("run " + file.string() + " -o " + (file.parent_path() / "first").string(), env);
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_EQ(first.output.find("from the mesh cache"), std::string::npos) << first.output;
  // The second run must not load gmsh at all (the dynamic loader's log names every library
  // it opens).
  const Result second =
      run("run " + file.string() + " -o " + (file.parent_path() / "second").string(),
          env + " LD_DEBUG=files");
  ASSERT_EQ(second.status, 0) << second.output;
  EXPECT_NE(second.output.find("from the mesh cache"), std::string::npos) << second.output;
  EXPECT_EQ(second.output.find("libgmsh"), std::string::npos) << "gmsh was loaded";
  EXPECT_NE(second.output.find("libsundials"), std::string::npos) << "no loader log";
  EXPECT_EQ(read_text(file.parent_path() / "first" / "line.csv"),
            read_text(file.parent_path() / "second" / "line.csv"));
  fs::remove_all(cache);
}

TEST(Cli, MissingGmshModuleIsNamed) {
  const fs::path file = write_case("nomodule.toml", kValid);
  const Result r =
      run("run " + file.string() + " -o " + (file.parent_path() / "nomodule").string(),
          "BIPHASIC_MESH_CACHE=off BIPHASIC_GMSH_MODULE=/nonexistent/libbiphasic_gmsh.so");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("/nonexistent/libbiphasic_gmsh.so"), std::string::npos) << r.output;
}

TEST(Cli, UnknownOptionAndMissingCase) {
  EXPECT_EQ(run("run --frobnicate x.toml").status, 1);
  const Result missing = run("run /nonexistent/case.toml");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("/nonexistent/case.toml"), std::string::npos) << missing.output;
}

}  // namespace
