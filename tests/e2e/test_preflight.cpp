// The checks before the first step, through the command line: rigid-body modes left free,
// coincident nodes, conflicting conditions, names, formulas and mesh files, each refused with
// exit status 1 by both `check` and `run` before any work, naming the key and the value; and a
// full cylinder held by a named point and curve instead of symmetry planes, solved alike by
// the three direct solvers.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../common/mixed_order_msh.hpp"
#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

fs::path scratch() { return scratch_dir("biphasic_preflight"); }

fs::path write_file(const std::string& name, const std::string& text) {
  return write_text(scratch() / name, text);
}

std::string data(const std::string& name) {
  return std::string(BIPHASIC_SOURCE_DIR) + "/tests/mesh/data/" + name;
}

/// A full cylinder (radius 2 mm, height 1.5 mm; physical curve "axis" on the z axis, point
/// "rim" at (2, 0, 0)) compressed by 0.1 mm between frictionless platens: u_z on top and
/// bottom only, drained on the side. `extra` is appended.
std::string cylinder_case(const std::string& extra = "") {
  return R"(format_version = 1
[mesh]
source = "file"
file = ")" +
         data("full_cylinder_tet10_v41.msh") +
         R"("
[curves]
ramp = [[0.0, 0.0], [1.0, 1.0]]
[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -0.1
curve = "ramp"
[[boundary]]
name = "bottom"
type = "displacement"
component = "z"
value = 0.0
[[boundary]]
name = "lateral"
type = "pressure"
value = 0.0
[time]
t_end = 1.0
dt = 0.5
[time.newton]
rtol_displacement = 1e-13
rtol_pressure = 1e-13
atol_displacement = 1e-15
atol_pressure = 1e-18
[output]
line_start = [0, 0, 0]
line_end = [0, 0, 1.5]
fields = false
reactions = ["top"]
)" + extra;
}

/// The axis held in x and y, the rim point in y: the axisymmetric solution satisfies both, so
/// they remove the rigid modes without changing the answer.
const char* kHeldByPointAndCurve = R"([[boundary]]
name = "axis"
type = "displacement"
component = "x"
value = 0.0
[[boundary]]
name = "axis"
type = "displacement"
component = "y"
value = 0.0
[[boundary]]
name = "rim"
type = "displacement"
component = "y"
value = 0.0
)";

void expect_in(const std::string& text, const std::vector<std::string>& parts) {
  for (const std::string& p : parts)
    EXPECT_NE(text.find(p), std::string::npos) << "lacks '" << p << "':\n" << text;
}

/// `check` and `run` both exit 1 naming `parts`, and the run starts no work.
void expect_refused(const std::string& name, const std::string& text,
                    const std::vector<std::string>& parts) {
  const fs::path file = write_file(name, text);
  const Result checked = run("check " + file.string());
  EXPECT_EQ(checked.status, 1) << name << ":\n" << checked.output;
  expect_in(checked.output, parts);
  const Result ran = run("run " + file.string() + " -o " + (scratch() / "out").string());
  EXPECT_EQ(ran.status, 1) << name << ":\n" << ran.output;
  expect_in(ran.output, parts);
  EXPECT_EQ(ran.output.find("step "), std::string::npos) << "work started for " << name;
}

TEST(Preflight, UnderConstrainedCylinderIsRefusedNamingItsFreeModes) {
  expect_refused("free.toml", cylinder_case(),
                 {"free.toml", "translation x", "translation y", "rotation about z",
                  "constraints.allow_free_rigid_modes"});
  // Opted in, the case passes with a note.
  const fs::path file =
      write_file("allowed.toml", cylinder_case("[constraints]\nallow_free_rigid_modes = true\n"));
  const Result r = run("check " + file.string());
  EXPECT_EQ(r.status, 0) << r.output;
  expect_in(r.output, {"rotation about z", "accepted"});
}

TEST(Preflight, CylinderHeldByAPointAndACurveGivesOnePlatenForceWithEverySolver) {
  std::vector<double> forces;
  for (const char* solver : {"klu", "umfpack", "mumps"}) {
    const fs::path file =
        write_file(std::string("held_") + solver + ".toml",
                   cylinder_case(std::string(kHeldByPointAndCurve) + "[linear_solver]\ntype = \"" +
                                 solver + "\"\nprecision = \"double\"\n"));
    const fs::path out = scratch() / (std::string("held_") + solver);
    const Result r = run("run " + file.string() + " --quiet -o " + out.string());
    ASSERT_EQ(r.status, 0) << solver << ":\n" << r.output;
    std::ifstream in(out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in);
    const auto& top = summary["outputs"].back()["reactions"]["top"];
    forces.push_back(top[2].get<double>());
    // No drift: the platen pushes straight down.
    EXPECT_LT(std::abs(top[0].get<double>()), 1e-9 * std::abs(forces.back())) << solver;
    EXPECT_LT(std::abs(top[1].get<double>()), 1e-9 * std::abs(forces.back())) << solver;
  }
  EXPECT_LT(forces[0], 0.0);  // the top platen pushes down on the compressed body
  for (std::size_t k = 1; k < forces.size(); ++k)
    EXPECT_NEAR(forces[k], forces[0], 1e-8 * std::abs(forces[0])) << "solver " << k;
}

TEST(Preflight, CoincidentNodesAreRefusedNamingTheirTagsAndPlace) {
  const std::string text = R"(format_version = 1
[mesh]
source = "file"
file = ")" + data("crack_tet4_v22.msh") +
                           R"("
[[boundary]]
name = "base"
type = "displacement"
component = "z"
value = 0.0
[constraints]
allow_free_rigid_modes = true
)";
  expect_refused("crack.toml", text,
                 {"crack_tet4_v22.msh", "file tag 2", "file tag 6", "(1, 0, 0)",
                  "constraints.allow_coincident_nodes"});
  const fs::path file = write_file("crack_allowed.toml", text + "allow_coincident_nodes = true\n");
  // The default probe line (the axis) does not lie in this two-tetrahedron mesh.
  const Result r = run("check " + file.string() + " --set output.line=false");
  EXPECT_EQ(r.status, 0) << r.output;
}

TEST(Preflight, ConflictingConditionsNameBoth) {
  const std::string held = kHeldByPointAndCurve;
  expect_refused("flux.toml",
                 cylinder_case(held + "[[boundary]]\nname = \"lateral\"\ntype = \"flux\"\n"
                                      "value = 1e-3\n"),
                 {"boundary[6] (flux on 'lateral')", "boundary[2] (pressure on 'lateral')"});
  expect_refused(
      "two_values.toml",
      cylinder_case(held + "[[boundary]]\nname = \"top\"\ntype = \"displacement\"\n"
                           "component = \"z\"\nvalue = -0.2\n"),
      {"boundary[0] (displacement z on 'top')", "boundary[6] (displacement z on 'top')", "u_z"});
  // Conditions on faces that share an edge: held apart only where they agree.
  expect_refused(
      "edge.toml",
      cylinder_case(held + "[[boundary]]\nname = \"lateral\"\ntype = \"displacement\"\n"
                           "component = \"z\"\nvalue = 0.0\n"),
      {"boundary[0] (displacement z on 'top')", "boundary[6] (displacement z on 'lateral')"});
  // Symmetry on the curved side, flux on a curve.
  expect_refused("curved.toml",
                 cylinder_case(held + "[[boundary]]\nname = \"lateral\"\ntype = \"symmetry\"\n"),
                 {"boundary[6] (symmetry on 'lateral')", "normal to x, y or z"});
  expect_refused("curve_flux.toml",
                 cylinder_case(held + "[[boundary]]\nname = \"axis\"\ntype = \"flux\"\n"
                                      "value = 1e-3\n"),
                 {"boundary[6].name = \"axis\"", "physical curve", "\"flux\""});
}

TEST(Preflight, CheckValidatesNamesFormulasAndMeshFiles) {
  const std::string held = kHeldByPointAndCurve;
  expect_refused("name.toml",
                 cylinder_case(held + "[[boundary]]\nname = \"lid\"\ntype = \"pressure\"\n"
                                      "value = 0.0\n"),
                 {"boundary[6].name = \"lid\"", "no such boundary", "lateral", "axis", "rim"});
  expect_refused("formula.toml", cylinder_case(held + "[body_force]\nz = \"1/0\"\n"),
                 {"body_force.z = \"1/0\"", "+inf"});
  expect_refused("late.toml", cylinder_case(held + "[body_force]\nz = \"1 / (t - 0.75)\"\n"),
                 {"body_force.z", "t = 0.75"});
  const fs::path garbage = write_file("garbage.msh", "this is not a mesh\n");
  std::string text = cylinder_case(held);
  text.replace(text.find(data("full_cylinder_tet10_v41.msh")),
               data("full_cylinder_tet10_v41.msh").size(), garbage.string());
  expect_refused("garbage.toml", text, {"mesh.file = \"" + garbage.string() + "\""});
}

// A [[region]] entry naming no region of the mesh: `check` and `run` refuse it before any work,
// naming the case file, the key and the mesh's regions (its physical volumes).
TEST(Preflight, UnknownRegionIsRefusedNamingTheMeshRegions) {
  const std::string text = cylinder_case(std::string(kHeldByPointAndCurve) +
                                         "[[region]]\nname = \"cartilage\"\npermeability = 2e-3\n");
  expect_refused("region.toml", text,
                 {"region.toml: region[0].name = \"cartilage\"", "no such region",
                  "mesh regions: \"domain\""});
}

// A binary .msh file whose one volume holds both 4-node and 10-node tetrahedra (gmsh corrupted
// its heap reading one) is bad input: `check` and `run` exit 1 before any work, naming the file
// and the mixed orders.
TEST(Preflight, BinaryMeshMixingElementOrdersIsRefusedNamingTheFile) {
  for (const char* version : {"v41", "v22"}) {
    const fs::path msh = scratch() / (std::string("mixed_") + version + "_binary.msh");
    if (version == std::string("v41"))
      biphasic::mixed_order_msh::write_mixed_binary_v41(msh.string());
    else
      biphasic::mixed_order_msh::write_mixed_binary_v22(msh.string());
    std::string text = cylinder_case(kHeldByPointAndCurve);
    text.replace(text.find(data("full_cylinder_tet10_v41.msh")),
                 data("full_cylinder_tet10_v41.msh").size(), msh.string());
    expect_refused(std::string("mixed_") + version + ".toml", text,
                   {"mesh.file = \"" + msh.string() + "\"",
                    "mixed element orders: both 4-node and 10-node tetrahedra"});
  }
}

TEST(Preflight, HeldCylinderPassesCheck) {
  const fs::path file = write_file("held.toml", cylinder_case(kHeldByPointAndCurve));
  const Result r = run("check " + file.string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("valid"), std::string::npos) << r.output;
}

}  // namespace
