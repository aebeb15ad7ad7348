// Case-file parsing: valid files, defaults, every kind of bad input, JSON dump and boundary
// checks against a mesh.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "case_test_support.hpp"

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::kMinimalCase;
using testing_support::problems_of;
using testing_support::TempDir;

/// Every key set, mostly to non-default values; the mesh file is "meshes/disc.msh".
const std::string kFullCase = R"(
format_version = 1
title = "reference loading"

[mesh]
source = "file"
file = "meshes/disc.msh"
radius = 17.5
height = 7
lc = 1.1
grading_faces = ["top", "lateral"]
grading_ratio = 2.5
grading_distance = 3.0
write_msh = "out/mesh.msh"

[material]
lambda = -0.1
mu = 0.6
permeability = 2e-3

[curves]
ramp = [[0.0, 0.0], [32.0, 1.0]]
step = [[0, 1]]

[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -0.08
curve = "ramp"

[[boundary]]
name = "symmetry_x"
type = "symmetry"

[[boundary]]
name = "lateral"
type = "pressure"
value = 0.0

[[boundary]]
name = "bottom"
type = "flux"
value = 1e-4
curve = "step"

[[boundary]]
name = "top"
type = "traction"
vector = [0.0, 0.5, -0.1]

[[boundary]]
name = "lateral"
type = "normal_traction"
value = 0.02

[stabilisation]
type = "gls"
length = "longest_edge"
scale = 0.5

[quadrature]
points = 27

[time]
integrator = "backward_euler"
t_end = 40.0
dt = 2.5

[time.newton]
max_iterations = 12
rtol_displacement = 1e-6
rtol_pressure = 1e-7
atol_displacement = 1e-10
atol_pressure = 1e-14
max_setup_calls = 1
reuse_across_steps = false

[linear_solver]
type = "klu"
ordering = "metis"

[output]
line_start = [1.0, 2.0, 0.0]
line_end = [1.0, 2.0, 7]
every = 3
fields = false
line = false
)";

TEST(CaseFile, FullCaseParsesToExpectedValues) {
  TempDir dir;
  dir.write("cases/meshes/disc.msh", "not read here\n");
  const auto case_path = dir.write("cases/full.toml", kFullCase);

  const Config c = read_case_file(case_path.string());
  EXPECT_EQ(c.case_file, case_path.string());
  EXPECT_EQ(c.title, "reference loading");

  EXPECT_EQ(c.mesh.source, MeshSource::File);
  EXPECT_EQ(c.mesh.file, (dir.path() / "cases/meshes/disc.msh").string());
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.radius, 17.5);
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.height, 7.0);
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.lc, 1.1);
  EXPECT_EQ(c.mesh.cylinder.grading_faces, (std::vector<std::string>{"top", "lateral"}));
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.grading_ratio, 2.5);
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.grading_distance, 3.0);
  EXPECT_EQ(c.mesh.cylinder.write_msh, "out/mesh.msh");  // kept as given

  EXPECT_DOUBLE_EQ(c.material.get("lambda"), -0.1);
  EXPECT_DOUBLE_EQ(c.material.get("mu"), 0.6);
  EXPECT_DOUBLE_EQ(c.material.get("permeability"), 2e-3);

  ASSERT_EQ(c.curves.size(), 2u);
  const auto& ramp = c.curves.at("ramp").points;
  ASSERT_EQ(ramp.size(), 2u);
  EXPECT_EQ(ramp[1], (std::pair<double, double>{32.0, 1.0}));
  EXPECT_EQ(c.curves.at("step").points, (std::vector<std::pair<double, double>>{{0.0, 1.0}}));

  ASSERT_EQ(c.bcs.size(), 6u);
  EXPECT_EQ(c.bcs[0].type, BcType::Displacement);
  EXPECT_EQ(c.bcs[0].boundary, "top");
  EXPECT_EQ(c.bcs[0].component, 2);
  EXPECT_DOUBLE_EQ(c.bcs[0].value, -0.08);
  EXPECT_EQ(c.bcs[0].curve, "ramp");
  EXPECT_EQ(c.bcs[1].type, BcType::Symmetry);
  EXPECT_EQ(c.bcs[1].boundary, "symmetry_x");
  EXPECT_EQ(c.bcs[1].curve, "");
  EXPECT_EQ(c.bcs[2].type, BcType::Pressure);
  EXPECT_DOUBLE_EQ(c.bcs[2].value, 0.0);
  EXPECT_EQ(c.bcs[3].type, BcType::Flux);
  EXPECT_DOUBLE_EQ(c.bcs[3].value, 1e-4);
  EXPECT_EQ(c.bcs[3].curve, "step");
  EXPECT_EQ(c.bcs[4].type, BcType::Traction);
  EXPECT_EQ(c.bcs[4].vector, (std::array<double, 3>{0.0, 0.5, -0.1}));
  EXPECT_EQ(c.bcs[5].type, BcType::NormalTraction);
  EXPECT_DOUBLE_EQ(c.bcs[5].value, 0.02);

  EXPECT_EQ(c.stabilisation.type, "gls");
  EXPECT_EQ(c.stabilisation.length, ElementLength::LongestEdge);
  EXPECT_DOUBLE_EQ(c.stabilisation.scale, 0.5);
  EXPECT_EQ(c.quadrature_points, 27);

  EXPECT_EQ(c.time.integrator, Integrator::BackwardEuler);
  EXPECT_DOUBLE_EQ(c.time.t_end, 40.0);
  EXPECT_DOUBLE_EQ(c.time.dt, 2.5);
  EXPECT_EQ(c.time.newton.max_iterations, 12);
  EXPECT_DOUBLE_EQ(c.time.newton.rtol_displacement, 1e-6);
  EXPECT_DOUBLE_EQ(c.time.newton.rtol_pressure, 1e-7);
  EXPECT_DOUBLE_EQ(c.time.newton.atol_displacement, 1e-10);
  EXPECT_DOUBLE_EQ(c.time.newton.atol_pressure, 1e-14);
  EXPECT_EQ(c.time.newton.max_setup_calls, 1);
  EXPECT_FALSE(c.time.newton.reuse_across_steps);

  EXPECT_EQ(c.linear_solver.type, LinearSolverType::Klu);
  EXPECT_EQ(c.linear_solver.ordering, Ordering::Metis);

  EXPECT_EQ(c.output.line_start, (std::array<double, 3>{1.0, 2.0, 0.0}));
  EXPECT_EQ(c.output.line_end, (std::array<double, 3>{1.0, 2.0, 7.0}));
  EXPECT_EQ(c.output.every, 3);
  EXPECT_TRUE(c.output.fields.empty());
  EXPECT_FALSE(c.output.line);
}

TEST(CaseFile, DefaultsAppliedWhenKeysAbsent) {
  const Config c = parse_case(kMinimalCase, "minimal.toml");
  const Config d;
  EXPECT_EQ(c.case_file, "minimal.toml");
  EXPECT_EQ(c.title, "");
  EXPECT_EQ(c.mesh.source, MeshSource::QuarterCylinder);
  EXPECT_EQ(c.mesh.file, "");
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.radius, 18.0);
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.height, 8.0);
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.lc, 1.3);
  EXPECT_TRUE(c.mesh.cylinder.grading_faces.empty());
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.grading_ratio, 1.0);
  EXPECT_DOUBLE_EQ(c.mesh.cylinder.grading_distance, 2.0);
  EXPECT_DOUBLE_EQ(c.material.get("lambda"), 0.2);
  EXPECT_DOUBLE_EQ(c.material.get("mu"), 0.5);
  EXPECT_DOUBLE_EQ(c.material.get("permeability"), 1e-3);
  EXPECT_TRUE(c.curves.empty());
  EXPECT_EQ(c.stabilisation.type, "none");
  EXPECT_EQ(c.stabilisation.length, ElementLength::Circumradius);
  EXPECT_EQ(c.quadrature_points, 4);
  EXPECT_DOUBLE_EQ(c.time.t_end, 32.0);
  EXPECT_DOUBLE_EQ(c.time.dt, 6.4);
  EXPECT_EQ(c.time.volume_rate, VolumeRate::Incremental);
  EXPECT_EQ(c.time.newton.max_iterations, 25);
  EXPECT_DOUBLE_EQ(c.time.newton.atol_pressure, 1e-15);
  EXPECT_EQ(c.time.newton.max_setup_calls, 10);
  EXPECT_TRUE(c.time.newton.reuse_across_steps);
  EXPECT_EQ(c.linear_solver.type, LinearSolverType::Mumps);
  EXPECT_EQ(c.linear_solver.ordering, Ordering::Metis);
  EXPECT_EQ(c.output.line_end, d.output.line_end);
  EXPECT_EQ(c.output.every, 1);
  EXPECT_EQ(c.output.fields, default_field_quantities());
  ASSERT_EQ(c.bcs.size(), 1u);
  EXPECT_EQ(c.bcs[0].curve, "");
}

TEST(CaseFile, FieldOutputIsAFlagOrAListOfQuantities) {
  using Q = FieldQuantity;
  const auto fields = [](const std::string& value) {
    return parse_case(kMinimalCase + "[output]\nfields = " + value + "\n", "x.toml").output.fields;
  };
  EXPECT_EQ(fields("true"), (std::vector<Q>{Q::Displacement, Q::Pressure}));
  EXPECT_TRUE(fields("false").empty());
  EXPECT_TRUE(fields("[]").empty());
  // Any order given; kept in the order of the reference (docs/case_file.md).
  EXPECT_EQ(fields(R"(["permeability", "J", "stress", "displacement"])"),
            (std::vector<Q>{Q::Displacement, Q::Stress, Q::J, Q::Permeability}));
  EXPECT_EQ(fields(R"(["effective_stress", "flux", "pressure"])"),
            (std::vector<Q>{Q::Pressure, Q::EffectiveStress, Q::Flux}));
  // --set takes the list as TOML.
  EXPECT_EQ(parse_case(kMinimalCase, "x.toml", {R"(output.fields=["flux"])"}).output.fields,
            std::vector<Q>{Q::Flux});

  // Reported as given: true for the default set, false for none, else the names.
  const auto reported = [](const std::string& value) {
    const Config c = parse_case(kMinimalCase + "[output]\nfields = " + value + "\n", "x.toml");
    return config_to_json(c)["output"]["fields"];
  };
  EXPECT_EQ(reported("true"), nlohmann::json(true));
  EXPECT_EQ(reported(R"(["pressure", "displacement"])"), nlohmann::json(true));
  EXPECT_EQ(reported("[]"), nlohmann::json(false));
  EXPECT_EQ(reported(R"(["J", "stress"])"), nlohmann::json({"stress", "J"}));

  const auto problems = problems_of(kMinimalCase + "[output]\nfields = [\"stress\", \"strain\"]\n");
  EXPECT_TRUE(has_problem(problems, {"output.fields = [\"stress\", \"strain\"]",
                                     "\"strain\" is not one of displacement, pressure, stress, "
                                     "effective_stress, J, flux, permeability"}));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + "[output]\nfields = [\"J\", \"J\"]\n"),
                          {"output.fields", "\"J\" is listed twice"}));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + "[output]\nfields = \"stress\"\n"),
                          {"output.fields = \"stress\"", "expected true or false, or an array"}));
}

TEST(CaseFile, IntegersAcceptedForNumbersButNotTheReverse) {
  const Config c = parse_case(kMinimalCase + "[time]\nt_end = 40\ndt = 4\n", "x.toml");
  EXPECT_DOUBLE_EQ(c.time.t_end, 40.0);
  EXPECT_DOUBLE_EQ(c.time.dt, 4.0);

  const auto problems = problems_of(kMinimalCase + "[time.newton]\nmax_iterations = 2.0\n");
  EXPECT_TRUE(has_problem(problems, {"time.newton.max_iterations = 2.0", "expected an integer"}));
}

TEST(CaseFile, SyntaxErrorGivesFileLineAndColumn) {
  const auto problems = problems_of("format_version = 1\ntitle = \"x\"\ndt = = 3\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].rfind("cases/x.toml:3:", 0), 0u) << problems[0];
  EXPECT_NE(problems[0].find("syntax error"), std::string::npos) << problems[0];
}

TEST(CaseFile, MissingCaseFileIsReported) {
  try {
    read_case_file("/no/such/folder/case.toml");
    FAIL() << "a missing file was accepted";
  } catch (const CaseError& error) {
    ASSERT_EQ(error.problems().size(), 1u);
    EXPECT_TRUE(has_problem(error.problems(), {"/no/such/folder/case.toml", "not found"}));
  }
}

TEST(CaseFile, UnknownKeysAtEveryLevel) {
  const auto problems = problems_of("titel = \"x\"\nunrelated = 3\n" + kMinimalCase + R"(
[time]
dtt = 1.0
[time.newton]
max_iteration = 3
[timee]
dt = 1.0
[mesh]
dt = 2.0
)" + "[[boundary]]\nname = \"lateral\"\ntype = \"pressure\"\nvalu = 1.0\nvalue = 0.0\n");
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: unknown key 'titel' (did you mean 'title'?)"}));
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: unknown key 'unrelated'"}));
  EXPECT_TRUE(
      has_problem(problems, {"cases/x.toml: unknown key 'time.dtt' (did you mean 'time.dt'?)"}));
  EXPECT_TRUE(has_problem(problems, {"unknown key 'time.newton.max_iteration'",
                                     "did you mean 'time.newton.max_iterations'?"}));
  EXPECT_TRUE(has_problem(problems, {"unknown key 'timee' (did you mean 'time'?)"}));
  EXPECT_TRUE(has_problem(problems, {"unknown key 'mesh.dt' (did you mean 'time.dt'?)"}));
  EXPECT_TRUE(has_problem(problems,
                          {"unknown key 'boundary[1].valu'", "did you mean 'boundary[1].value'?"}));
  EXPECT_EQ(problems.size(), 7u);
}

TEST(CaseFile, WrongTypes) {
  const auto problems = problems_of("title = 3\n" + kMinimalCase + R"(
[mesh]
grading_faces = "top"
[time]
dt = "fast"
[quadrature]
points = 4.0
[output]
line_end = [0, 0]
fields = 1
)");
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: time.dt = \"fast\": expected a number"}));
  EXPECT_TRUE(has_problem(problems, {"title = 3", "expected a string"}));
  EXPECT_TRUE(
      has_problem(problems, {"mesh.grading_faces = \"top\"", "expected an array of strings"}));
  EXPECT_TRUE(has_problem(problems, {"quadrature.points = 4.0", "expected an integer"}));
  EXPECT_TRUE(
      has_problem(problems, {"output.line_end = [0, 0]", "expected an array of 3 numbers"}));
  EXPECT_TRUE(has_problem(problems, {"output.fields = 1", "expected true or false"}));
  EXPECT_EQ(problems.size(), 6u);
}

TEST(CaseFile, SectionThatIsNotATable) {
  const auto problems = problems_of("time = 3\n" + kMinimalCase);
  EXPECT_TRUE(has_problem(problems, {"time = 3", "expected a table"}));
}

TEST(CaseFile, OutOfRangeValues) {
  const auto problems = problems_of(R"(
format_version = 2
[mesh]
radius = 0
grading_ratio = 0.5
[material]
permeability = -1e-3
[time]
dt = -6.4
[time.newton]
max_iterations = 0
rtol_pressure = 1.0
atol_pressure = -1e-15
[quadrature]
points = 3
[output]
every = 0
line_start = [0, 0, inf]
)" + kMinimalCase.substr(kMinimalCase.find("[[boundary]]")));
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: time.dt = -6.4: must be > 0 (s)"}));
  EXPECT_TRUE(has_problem(problems, {"format_version = 2: must be 1"}));
  EXPECT_TRUE(has_problem(problems, {"mesh.radius = 0: must be > 0 (mm)"}));
  EXPECT_TRUE(has_problem(problems, {"mesh.grading_ratio = 0.5: must be >= 1"}));
  EXPECT_TRUE(has_problem(problems, {"material.permeability = -0.001", "> 0"}));
  EXPECT_TRUE(has_problem(problems, {"time.newton.max_iterations = 0: must be in [1, 1000]"}));
  EXPECT_TRUE(has_problem(problems, {"time.newton.rtol_pressure = 1.0: must be in (0, 1)"}));
  EXPECT_TRUE(has_problem(problems, {"time.newton.atol_pressure = -1e-15: must be >= 0 (mm^3/s)"}));
  EXPECT_TRUE(
      has_problem(problems, {"quadrature.points = 3: must be one of 1, 4, 5, 8, 27, 64, 125"}));
  EXPECT_TRUE(has_problem(problems, {"output.every = 0: must be >= 1"}));
  EXPECT_TRUE(has_problem(problems, {"output.line_start = [0, 0, inf]", "finite"}));
  EXPECT_EQ(problems.size(), 11u);
}

// linear_solver.out_of_core: MUMPS only, into an existing writable folder (relative to the
// case file's folder, by default $TMPDIR, else /tmp), made absolute when the case is read.
TEST(CaseFile, OutOfCoreFactorsNeedMumpsAndAFolder) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "scratch");
  const std::string base = dir.path().string();
  auto parse = [&](const std::string& extra) {
    return parse_case(kMinimalCase + "[linear_solver]\n" + extra, "cases/x.toml", {}, base);
  };
  Config c = parse("out_of_core = true\nout_of_core_directory = \"scratch\"\n");
  EXPECT_TRUE(c.linear_solver.out_of_core);
  EXPECT_EQ(c.linear_solver.out_of_core_directory, (dir.path() / "scratch").string());

  const char* saved = std::getenv("TMPDIR");
  const std::string saved_value = saved ? saved : "";
  setenv("TMPDIR", base.c_str(), 1);
  EXPECT_EQ(parse("out_of_core = true\n").linear_solver.out_of_core_directory, base);
  setenv("TMPDIR", (base + "/absent").c_str(), 1);
  const auto from_env = problems_of(kMinimalCase + "[linear_solver]\nout_of_core = true\n");
  if (saved)
    setenv("TMPDIR", saved_value.c_str(), 1);
  else
    unsetenv("TMPDIR");
  EXPECT_TRUE(has_problem(from_env, {"linear_solver.out_of_core_directory", "from $TMPDIR",
                                     "folder not found", "absent"}));
  EXPECT_FALSE(parse("").linear_solver.out_of_core);

  EXPECT_TRUE(has_problem(
      problems_of(kMinimalCase + "[linear_solver]\ntype = \"klu\"\nout_of_core = true\n"),
      {"linear_solver.out_of_core = true", "\"mumps\" only", "\"klu\""}));
  EXPECT_TRUE(has_problem(
      problems_of(kMinimalCase + "[linear_solver]\nout_of_core_directory = \"/tmp\"\n"),
      {"linear_solver.out_of_core_directory = \"/tmp\"", "only with linear_solver.out_of_core"}));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + "[linear_solver]\nout_of_core = true\n"
                                                     "out_of_core_directory = \"/no/such\"\n"),
                          {"out_of_core_directory = \"/no/such\"", "folder not found"}));
  const auto file = dir.write("plain.txt", "x");
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase +
                                      "[linear_solver]\nout_of_core = true\n"
                                      "out_of_core_directory = \"" +
                                      file.string() + "\"\n"),
                          {"out_of_core_directory", "is not a folder"}));
  const auto deep = dir.path() / std::string(100, 'a') / std::string(100, 'b') /
                    std::string(100, 'c');  // MUMPS keeps 255 characters of the name
  std::filesystem::create_directories(deep);
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase +
                                      "[linear_solver]\nout_of_core = true\n"
                                      "out_of_core_directory = \"" +
                                      deep.string() + "\"\n"),
                          {"out_of_core_directory", "characters long; MUMPS takes at most 255"}));
}

TEST(CaseFile, BadChoices) {
  const auto problems = problems_of(kMinimalCase + R"(
[stabilisation]
type = "glss"
length = "diameter"
[mesh]
source = "generated"
grading_faces = ["top", "topp"]
[linear_solver]
ordering = "nd"
)" + "[[boundary]]\nname = \"top\"\ntype = \"displacment\"\n" +
                                    "[[boundary]]\nname = \"top\"\ntype = \"displacement\"\n"
                                    "component = \"w\"\nvalue = 1.0\n");
  EXPECT_TRUE(has_problem(
      problems, {"cases/x.toml: stabilisation.type = \"glss\": must be one of none, gls"}));
  EXPECT_TRUE(has_problem(problems, {"stabilisation.length = \"diameter\"", "circumradius"}));
  EXPECT_TRUE(has_problem(problems, {"mesh.source = \"generated\"",
                                     "quarter_cylinder, column, sphere_octant, section, file"}));
  EXPECT_TRUE(has_problem(problems, {"mesh.grading_faces = [\"top\", \"topp\"]", "\"topp\"",
                                     "bottom, top, lateral, symmetry_x, symmetry_y"}));
  EXPECT_TRUE(has_problem(problems, {"linear_solver.ordering = \"nd\"", "amd, colamd, metis"}));
  EXPECT_TRUE(has_problem(problems, {"boundary[1].type = \"displacment\"", "displacement"}));
  EXPECT_TRUE(has_problem(problems, {"boundary[2].component = \"w\"", "must be one of x, y, z"}));
  EXPECT_EQ(problems.size(), 7u);
}

TEST(CaseFile, MissingRequiredKeys) {
  const auto no_version = problems_of("[[boundary]]\nname = \"top\"\ntype = \"symmetry\"\n");
  EXPECT_TRUE(has_problem(no_version, {"cases/x.toml: format_version: required key is missing"}));

  const auto no_boundary = problems_of("format_version = 1\n");
  EXPECT_TRUE(has_problem(no_boundary, {"boundary", "at least one [[boundary]]"}));
  const auto empty_boundary = problems_of("format_version = 1\nboundary = []\n");
  EXPECT_TRUE(has_problem(empty_boundary, {"boundary", "at least one [[boundary]]"}));

  const auto problems = problems_of(R"(
format_version = 1
[[boundary]]
type = "symmetry"
[[boundary]]
name = "top"
[[boundary]]
name = "top"
type = "displacement"
[[boundary]]
name = "top"
type = "traction"
[[boundary]]
name = ""
type = "flux"
value = 1.0
)");
  EXPECT_TRUE(has_problem(problems, {"boundary[0].name: required key is missing"}));
  EXPECT_TRUE(has_problem(problems, {"boundary[1].type: required key is missing"}));
  EXPECT_TRUE(has_problem(problems, {"boundary[2].component: required for type \"displacement\""}));
  EXPECT_TRUE(has_problem(problems, {"boundary[2].value: required for type \"displacement\""}));
  EXPECT_TRUE(has_problem(problems, {"boundary[3].vector: required for type \"traction\""}));
  EXPECT_TRUE(has_problem(problems, {"boundary[4].name = \"\": must not be empty"}));
  EXPECT_EQ(problems.size(), 6u);
}

TEST(CaseFile, KeysNotAllowedForTheBoundaryType) {
  const auto problems = problems_of(R"(
format_version = 1
[curves]
ramp = [[0, 0], [1, 1]]
[[boundary]]
name = "lateral"
type = "pressure"
component = "x"
value = 0.0
[[boundary]]
name = "symmetry_x"
type = "symmetry"
value = 0.0
curve = "ramp"
[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -0.1
vector = [0, 0, 1]
[[boundary]]
name = "top"
type = "traction"
value = 1.0
vector = [0, 0, 1]
)");
  EXPECT_TRUE(
      has_problem(problems, {"boundary[0].component = \"x\": not allowed for type \"pressure\""}));
  EXPECT_TRUE(
      has_problem(problems, {"boundary[1].value = 0.0: not allowed for type \"symmetry\""}));
  EXPECT_TRUE(
      has_problem(problems, {"boundary[1].curve = \"ramp\": not allowed for type \"symmetry\""}));
  EXPECT_TRUE(
      has_problem(problems, {"boundary[2].vector = [0, 0, 1]", "not allowed", "displacement"}));
  EXPECT_TRUE(
      has_problem(problems, {"boundary[3].value = 1.0: not allowed for type \"traction\""}));
  EXPECT_EQ(problems.size(), 5u);
}

TEST(CaseFile, UndefinedCurve) {
  const auto problems = problems_of(kMinimalCase + R"(
curve = "ramp"
[curves]
ramp = [[0.0, 0.0], [32.0, 1.0]]
)" + "[[boundary]]\nname = \"lateral\"\ntype = \"pressure\"\nvalue = 0.0\ncurve = \"rampp\"\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0],
            "cases/x.toml: boundary[1].curve = \"rampp\": no such curve (defined: ramp)");

  const auto none_defined = problems_of(kMinimalCase + "curve = \"ramp\"\n");
  EXPECT_TRUE(has_problem(none_defined, {"boundary[0].curve = \"ramp\"", "no curves are defined"}));
}

TEST(CaseFile, BadCurves) {
  const auto problems = problems_of(kMinimalCase + R"(
[curves]
flat = [[0.0, 1.0], [10.0, 1.0], [10.0, 2.0]]
back = [[5, 0], [1, 1]]
empty = []
odd = [[0.0, 1.0, 2.0]]
words = [["a", 1]]
scalar = 3.0
)");
  EXPECT_TRUE(
      has_problem(problems, {"cases/x.toml: curves.flat = [[0.0, 1.0], [10.0, 1.0], [10.0, 2.0]]",
                             "strictly increasing", "t = 10.0 follows t = 10.0"}));
  EXPECT_TRUE(has_problem(problems, {"curves.back = [[5, 0], [1, 1]]", "strictly increasing"}));
  EXPECT_TRUE(has_problem(problems, {"curves.empty = []", "at least one"}));
  EXPECT_TRUE(has_problem(problems, {"curves.odd", "[t, value]"}));
  EXPECT_TRUE(has_problem(problems, {"curves.words", "[t, value]"}));
  EXPECT_TRUE(has_problem(problems, {"curves.scalar = 3.0", "expected an array"}));
  EXPECT_EQ(problems.size(), 6u);
}

TEST(CaseFile, CrossFieldRules) {
  const auto problems = problems_of(kMinimalCase + R"(
[time]
t_end = 10.0
dt = 12.5
[material]
lambda = -1
mu = 0.6
[output]
line_start = [0, 0, 1]
line_end = [0.0, 0.0, 1.0]
[mesh]
source = "file"
)");
  EXPECT_TRUE(has_problem(problems, {"time.dt = 12.5: must be <= time.t_end = 10.0 (s)"}));
  EXPECT_TRUE(has_problem(
      problems,
      {"material.lambda = -1: material.lambda + 2/3 material.mu must be > 0 (here -0.6 MPa)"}));
  EXPECT_TRUE(has_problem(
      problems, {"output.line_end = [0.0, 0.0, 1.0]", "must differ from output.line_start"}));
  EXPECT_TRUE(
      has_problem(problems, {"cases/x.toml: mesh.file: required when mesh.source = \"file\""}));
  EXPECT_EQ(problems.size(), 4u);

  // lambda + 2/3 mu = 0 exactly is rejected too; dt == t_end is fine.
  const auto boundary_case = problems_of(
      kMinimalCase + "[material]\nlambda = -0.4\nmu = 0.6\n[time]\nt_end = 5\ndt = 5\n");
  ASSERT_EQ(boundary_case.size(), 1u);
  EXPECT_TRUE(has_problem(boundary_case, {"material.lambda = -0.4"}));
}

TEST(CaseFile, ConservativeVolumeRateIsForBackwardEulerOnly) {
  const Config c = parse_case(kMinimalCase + "[time]\nvolume_rate = \"conservative\"\n", "x.toml");
  EXPECT_EQ(c.time.volume_rate, VolumeRate::Conservative);
  EXPECT_EQ(c.time.integrator, Integrator::BackwardEuler);

  const auto problems =
      problems_of(kMinimalCase + "[time]\nintegrator = \"bdf\"\nvolume_rate = \"conservative\"\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(
      has_problem(problems, {"cases/x.toml: time.volume_rate = \"conservative\": applies "
                             "only to time.integrator = \"backward_euler\", not to \"bdf\""}));
  // The same from the command line names --set as the source.
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + "[time]\nintegrator = \"bdf\"\n",
                                      {"time.volume_rate=conservative"}),
                          {"--set: time.volume_rate = \"conservative\"", "backward_euler"}));
  // The default with bdf, the incremental form named explicitly, and unknown names.
  EXPECT_NO_THROW(parse_case(kMinimalCase + "[time]\nintegrator = \"bdf\"\n", "x.toml"));
  EXPECT_NO_THROW(parse_case(
      kMinimalCase + "[time]\nintegrator = \"bdf\"\nvolume_rate = \"incremental\"\n", "x.toml"));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + "[time]\nvolume_rate = \"exact\"\n"),
                          {"time.volume_rate = \"exact\"", "incremental", "conservative"}));
}

TEST(CaseFile, MeshFileMustExistAndIsResolvedAgainstTheCaseFolder) {
  TempDir dir;
  const std::string text = kMinimalCase + "[mesh]\nsource = \"file\"\nfile = \"meshes/disc.msh\"\n";
  try {
    parse_case(text, "cases/x.toml", {}, dir.path().string());
    FAIL() << "a missing mesh file was accepted";
  } catch (const CaseError& error) {
    EXPECT_TRUE(has_problem(error.problems(), {"mesh.file = \"meshes/disc.msh\": file not found",
                                               (dir.path() / "meshes/disc.msh").string()}));
  }

  dir.write("meshes/disc.msh", "$MeshFormat\n");
  const Config c = parse_case(text, "cases/x.toml", {}, dir.path().string());
  EXPECT_EQ(c.mesh.file, (dir.path() / "meshes/disc.msh").string());

  // An absolute path is kept; with the quarter cylinder the file is not required to exist.
  const Config absolute = parse_case(kMinimalCase + "[mesh]\nfile = \"/abs/m.msh\"\n", "x.toml");
  EXPECT_EQ(absolute.mesh.file, "/abs/m.msh");
}

TEST(CaseFile, SeveralProblemsReportedTogether) {
  const std::string text = R"(
format_version = 1
[time]
dt = -1.0
dtt = 3
[stabilisation]
type = "glss"
[[boundary]]
name = "top"
type = "displacement"
component = "z"
)";
  try {
    parse_case(text, "cases/x.toml");
    FAIL() << "accepted";
  } catch (const CaseError& error) {
    const auto& problems = error.problems();
    ASSERT_EQ(problems.size(), 4u) << error.what();
    EXPECT_TRUE(has_problem(problems, {"time.dt = -1.0"}));
    EXPECT_TRUE(has_problem(problems, {"'time.dtt'"}));
    EXPECT_TRUE(has_problem(problems, {"stabilisation.type = \"glss\""}));
    EXPECT_TRUE(has_problem(problems, {"boundary[0].value"}));
    std::string joined;
    for (const auto& p : problems) joined += (joined.empty() ? "" : "\n") + p;
    EXPECT_EQ(std::string(error.what()), joined);
  }
}

TEST(CaseFile, ConfigToJsonHoldsEveryKey) {
  const Config c = parse_case("title = \"json\"\n" + kMinimalCase + R"(
curve = "ramp"
[curves]
ramp = [[0.0, 0.0], [32.0, 1.0]]
[time]
dt = 3.2
[stabilisation]
type = "gls"
[output]
line_end = [0, 0, 4]
)" + "[[boundary]]\nname = \"bottom\"\ntype = \"traction\"\nvector = [1, 2, 3]\n",
                              "cases/j.toml");
  const nlohmann::json j = config_to_json(c);
  EXPECT_EQ(j["case_file"], "cases/j.toml");
  EXPECT_EQ(j["format_version"], 1);
  EXPECT_EQ(j["title"], "json");
  EXPECT_DOUBLE_EQ(j["time"]["dt"].get<double>(), 3.2);
  EXPECT_DOUBLE_EQ(j["time"]["t_end"].get<double>(), 32.0);
  EXPECT_EQ(j["time"]["newton"]["max_iterations"], 25);
  EXPECT_EQ(j["stabilisation"]["type"], "gls");
  EXPECT_EQ(j["mesh"]["source"], "quarter_cylinder");
  EXPECT_EQ(j["quadrature"]["points"], 4);
  EXPECT_EQ(j["output"]["line_end"], nlohmann::json::parse("[0.0, 0.0, 4.0]"));
  EXPECT_EQ(j["curves"]["ramp"], nlohmann::json::parse("[[0.0, 0.0], [32.0, 1.0]]"));
  ASSERT_EQ(j["boundary"].size(), 2u);
  EXPECT_EQ(j["boundary"][0]["name"], "top");
  EXPECT_EQ(j["boundary"][0]["type"], "displacement");
  EXPECT_EQ(j["boundary"][0]["component"], "z");
  EXPECT_DOUBLE_EQ(j["boundary"][0]["value"].get<double>(), -0.08);
  EXPECT_EQ(j["boundary"][0]["curve"], "ramp");
  EXPECT_FALSE(j["boundary"][0].contains("vector"));
  EXPECT_EQ(j["boundary"][1]["vector"], nlohmann::json::parse("[1.0, 2.0, 3.0]"));
  EXPECT_FALSE(j["boundary"][1].contains("component"));

  // Every section of the case file appears.
  for (const char* section :
       {"mesh", "material", "curves", "boundary", "body_force", "fluid_source", "stabilisation",
        "quadrature", "time", "linear_solver", "output"}) {
    EXPECT_TRUE(j.contains(section)) << section;
  }
  EXPECT_EQ(j["time"]["newton"].size(), 8u);
  EXPECT_EQ(j["time"]["newton"]["max_cutbacks"], 4);
  // Thirteen keys, [mesh.column], [mesh.sphere_octant], [mesh.section].
  EXPECT_EQ(j["mesh"].size(), 16u);
  EXPECT_EQ(j["mesh"]["section"].size(), 6u);
  EXPECT_EQ(j["mesh"]["column"].size(), 10u);
  EXPECT_EQ(j["mesh"]["sphere_octant"].size(), 4u);
  EXPECT_EQ(j["output"]["reactions"], nlohmann::json::array());
  EXPECT_EQ(j["body_force"]["y"], "0");
  EXPECT_EQ(j["fluid_source"]["value"], "0");
}

TEST(CaseFile, GeneratedColumnAndSphereOctant) {
  const Config column = parse_case(kMinimalCase + R"(
[mesh]
source = "column"
[mesh.column]
width = 0.5
depth = 0.25
height = 2
nx = 2
ny = 3
nz = 12
grading_faces = ["top"]
grading_ratio = 4
)",
                                   "cases/x.toml");
  EXPECT_EQ(column.mesh.source, MeshSource::Column);
  EXPECT_DOUBLE_EQ(column.mesh.column.width, 0.5);
  EXPECT_DOUBLE_EQ(column.mesh.column.depth, 0.25);
  EXPECT_DOUBLE_EQ(column.mesh.column.height, 2.0);
  EXPECT_EQ(column.mesh.column.nx, 2);
  EXPECT_EQ(column.mesh.column.ny, 3);
  EXPECT_EQ(column.mesh.column.nz, 12);
  EXPECT_EQ(column.mesh.column.grading_faces, std::vector<std::string>{"top"});
  EXPECT_DOUBLE_EQ(column.mesh.column.grading_ratio, 4.0);

  const Config sphere = parse_case(kMinimalCase + R"(
[mesh]
source = "sphere_octant"
write_msh = "octant.msh"
[mesh.sphere_octant]
radius = 3
lc = 0.4
grading_ratio = 2
grading_distance = 0.5
)",
                                   "cases/x.toml");
  EXPECT_EQ(sphere.mesh.source, MeshSource::SphereOctant);
  EXPECT_DOUBLE_EQ(sphere.mesh.sphere_octant.radius, 3.0);
  EXPECT_DOUBLE_EQ(sphere.mesh.sphere_octant.lc, 0.4);
  EXPECT_DOUBLE_EQ(sphere.mesh.sphere_octant.grading_ratio, 2.0);
  EXPECT_DOUBLE_EQ(sphere.mesh.sphere_octant.grading_distance, 0.5);
  EXPECT_EQ(sphere.mesh.cylinder.write_msh, "octant.msh");
}

TEST(CaseFile, KeysOfAnotherMeshSourceAreErrors) {
  const auto problems = problems_of(kMinimalCase + R"(
[mesh]
source = "column"
height = 2.0
write_msh = "column.msh"
[mesh.sphere_octant]
radius = 1
[mesh.column]
nz = 0
)");
  EXPECT_TRUE(has_problem(problems, {"mesh.height = 2.0: applies only to mesh.source = "
                                     "\"quarter_cylinder\", not to mesh.source = \"column\""}));
  EXPECT_TRUE(has_problem(problems, {"mesh.write_msh", "gmsh"}));
  EXPECT_TRUE(has_problem(problems, {"mesh.sphere_octant = { radius = 1 }",
                                     "applies only to mesh.source = \"sphere_octant\""}));
  EXPECT_TRUE(has_problem(problems, {"mesh.column.nz = 0: must be >= 1"}));
  EXPECT_EQ(problems.size(), 4u);

  // Column keys with the quarter cylinder, and too few layers for a grading.
  const auto cylinder = problems_of(kMinimalCase + "[mesh.column]\nwidth = 2.0\n");
  ASSERT_EQ(cylinder.size(), 1u);
  EXPECT_TRUE(has_problem(
      cylinder, {"mesh.column = { width = 2.0 }", "not to mesh.source = \"quarter_cylinder\""}));
  const auto layers = problems_of(kMinimalCase + R"(
[mesh]
source = "column"
[mesh.column]
nz = 2
grading_faces = ["top", "bottom"]
grading_ratio = 3
)");
  ASSERT_EQ(layers.size(), 1u);
  EXPECT_TRUE(has_problem(layers, {"mesh.column.nz = 2: must be >= 3 to grade the layers toward "
                                   "[\"top\", \"bottom\"]"}));

  // A swept quarter cylinder: graded by its layers only, with enough of them; layer keys
  // belong to the quarter cylinder.
  const auto swept = problems_of(kMinimalCase + R"(
[mesh]
layers = 2
layer_grading_faces = ["top", "bottom"]
layer_grading_ratio = 4
grading_faces = ["top"]
)");
  ASSERT_EQ(swept.size(), 2u);
  EXPECT_TRUE(has_problem(swept, {"mesh.grading_faces = [\"top\"]", "mesh.layer_grading_faces"}));
  EXPECT_TRUE(has_problem(swept, {"mesh.layers = 2: must be >= 3"}));
  const auto unswept = problems_of(kMinimalCase + "[mesh]\nlayer_grading_faces = [\"top\"]\n");
  ASSERT_EQ(unswept.size(), 1u);
  EXPECT_TRUE(has_problem(unswept, {"mesh.layer_grading_faces", "mesh.layers > 0"}));
  const auto column = problems_of(kMinimalCase + "[mesh]\nsource = \"column\"\nlayers = 4\n");
  ASSERT_EQ(column.size(), 1u);
  EXPECT_TRUE(has_problem(column, {"mesh.layers = 4: applies only to mesh.source = "
                                   "\"quarter_cylinder\""}));
}

TEST(CaseFile, ReactionBoundariesNeedADisplacementOrSymmetryCondition) {
  const std::string side = "[[boundary]]\nname = \"side\"\ntype = \"pressure\"\nvalue = 0.0\n";
  const Config ok = parse_case(kMinimalCase + side + "[output]\nreactions = [\"top\"]\n", "x");
  EXPECT_EQ(ok.output.reactions, std::vector<std::string>{"top"});
  const auto problems =
      problems_of(kMinimalCase + side + "[output]\nreactions = [\"top\", \"side\"]\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(
      has_problem(problems, {"output.reactions = [\"top\", \"side\"]",
                             "\"side\" has no displacement, symmetry or rigid_platen condition"}));
}

TEST(CaseFile, CheckBoundariesAgainstTheMesh) {
  const std::string text = kMinimalCase + R"(
[mesh]
grading_faces = ["top", "lateral"]
)" + "[[boundary]]\nname = \"side\"\ntype = \"pressure\"\nvalue = 0.0\n";
  const Config c = parse_case(text, "cases/x.toml");
  EXPECT_NO_THROW(check_boundaries(c, {"bottom", "top", "side", "lateral"}));
  try {
    check_boundaries(c, {"bottom", "top", "symmetry_x"});
    FAIL() << "unknown boundaries accepted";
  } catch (const CaseError& error) {
    const auto& problems = error.problems();
    ASSERT_EQ(problems.size(), 2u) << error.what();
    EXPECT_TRUE(has_problem(problems, {"cases/x.toml: boundary[1].name = \"side\"",
                                       "mesh boundaries: bottom, top, symmetry_x"}));
    EXPECT_TRUE(has_problem(problems, {"mesh.grading_faces", "\"lateral\"",
                                       "mesh boundaries: bottom, top, symmetry_x"}));
  }
}

}  // namespace
}  // namespace biphasic

namespace biphasic {
namespace {

// A 300 000-character formula crashed `check` (stack overflow) and 1e308 as the layer grading
// ratio aborted inside gmsh: both are now input errors naming the key, before any work.
TEST(CaseFile, OverlongFormulaAndExtremeLayerGradingAreRefusedNamingTheKey) {
  std::string sum = "x";
  while (sum.size() < 300'000) sum += "+x";
  const auto problems = problems_of(kMinimalCase + "[body_force]\nx = \"" + sum +
                                    "\"\n[mesh]\nlayers = 4\nlayer_grading_ratio = 1e308\n");
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: body_force.x", "300001 characters",
                                     "more than the limit of 100000"}));
  EXPECT_TRUE(has_problem(problems, {"mesh.layer_grading_ratio = 1e308", "[1, 1000000]"}));
  for (const std::string& p : problems) EXPECT_LT(p.size(), 1000u) << p.substr(0, 200);
}

}  // namespace
}  // namespace biphasic

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::kMinimalCase;
using testing_support::problems_of;

// The strain-dependent permeability laws: chosen by name with their parameters; parameters of
// a law that is not chosen, and phi0 outside (0, 1), are errors naming the key.
TEST(CaseFile, PermeabilityLawAndItsParameters) {
  const Config c = parse_case(kMinimalCase + R"(
[material]
permeability = 2e-3
permeability_law = "holmes_mow"
solid_fraction = 0.15
permeability_kappa = 2.0
permeability_M = 4.5
)",
                              "cases/x.toml", {}, ".");
  EXPECT_EQ(c.material.permeability_law, "holmes_mow");
  EXPECT_EQ(c.material.get("solid_fraction"), 0.15);
  EXPECT_EQ(c.material.get("permeability_kappa"), 2.0);
  EXPECT_EQ(c.material.get("permeability_M"), 4.5);
  EXPECT_EQ(parse_case(kMinimalCase, "cases/x.toml", {}, ".").material.permeability_law,
            "constant");

  const auto wrong_law = problems_of(kMinimalCase + R"(
[material]
permeability_law = "exponential"
permeability_kappa = 2.0
)");
  ASSERT_EQ(wrong_law.size(), 1u);
  EXPECT_TRUE(has_problem(wrong_law, {"material.permeability_kappa = 2.0",
                                      "applies only to material.permeability_law = "
                                      "\"holmes_mow\"",
                                      "not to material.permeability_law = \"exponential\""}));
  const auto constant = problems_of(kMinimalCase + "[material]\nsolid_fraction = 0.2\n");
  EXPECT_TRUE(has_problem(constant, {"material.solid_fraction = 0.2",
                                     "not to material.permeability_law = \"constant\""}));
  const auto bad = problems_of(kMinimalCase + R"(
[material]
permeability_law = "darcy"
)");
  EXPECT_TRUE(has_problem(bad, {"material.permeability_law", "darcy", "holmes_mow"}));
  const auto phi = problems_of(kMinimalCase + R"(
[material]
permeability_law = "holmes_mow"
solid_fraction = 1.0
)");
  EXPECT_TRUE(has_problem(phi, {"material.solid_fraction = 1.0"}));
}

// The solid law: neo_hookean by default; holmes_mow with E, nu, beta and their defaults.
TEST(CaseFile, SolidLawAndItsParameters) {
  const Config neo = parse_case(kMinimalCase, "cases/x.toml", {}, ".");
  EXPECT_EQ(neo.material.solid_law, "neo_hookean");
  const Config c = parse_case(kMinimalCase + R"(
[material]
solid_law = "holmes_mow"
youngs_modulus = 0.7
poissons_ratio = -0.2
beta = 0.35
)",
                              "cases/x.toml", {}, ".");
  EXPECT_EQ(c.material.solid_law, "holmes_mow");
  EXPECT_EQ(c.material.get("youngs_modulus"), 0.7);
  EXPECT_EQ(c.material.get("poissons_ratio"), -0.2);
  EXPECT_EQ(c.material.get("beta"), 0.35);
  const Config d = parse_case(kMinimalCase + "[material]\nsolid_law = \"holmes_mow\"\n",
                              "cases/x.toml", {}, ".");
  EXPECT_EQ(d.material.get("youngs_modulus"), 1.0);
  EXPECT_EQ(d.material.get("poissons_ratio"), 0.2);
  EXPECT_EQ(d.material.get("beta"), 0.0);
  const Config set = parse_case(kMinimalCase, "cases/x.toml",
                                {"material.solid_law=holmes_mow", "material.beta=2"}, ".");
  EXPECT_EQ(set.material.solid_law, "holmes_mow");
  EXPECT_EQ(set.material.get("beta"), 2.0);
}

// Keys of the law not chosen are errors naming the key and both laws.
TEST(CaseFile, KeysOfTheOtherSolidLawAreRefused) {
  const auto lame = problems_of(kMinimalCase + R"(
[material]
solid_law = "holmes_mow"
lambda = 0.2
mu = 0.5
youngs_modulus = 1.0
)");
  ASSERT_EQ(lame.size(), 2u);
  EXPECT_TRUE(has_problem(
      lame, {"material.lambda = 0.2", "applies only to material.solid_law = \"neo_hookean\"",
             "not to material.solid_law = \"holmes_mow\""}));
  EXPECT_TRUE(has_problem(lame, {"material.mu = 0.5", "not to material.solid_law"}));
  const auto hm = problems_of(kMinimalCase + "[material]\nyoungs_modulus = 1.0\nbeta = 0.1\n");
  ASSERT_EQ(hm.size(), 2u);
  EXPECT_TRUE(has_problem(
      hm, {"material.youngs_modulus = 1.0", "applies only to material.solid_law = \"holmes_mow\"",
           "not to material.solid_law = \"neo_hookean\""}));
  EXPECT_TRUE(has_problem(hm, {"material.beta = 0.1"}));
  const auto nu = problems_of(kMinimalCase + R"(
[material]
solid_law = "neo_hookean"
poissons_ratio = 0.3
)");
  EXPECT_TRUE(has_problem(nu, {"material.poissons_ratio = 0.3", "\"neo_hookean\""}));
  const auto bad = problems_of(kMinimalCase + "[material]\nsolid_law = \"mooney\"\n");
  EXPECT_TRUE(has_problem(bad, {"material.solid_law", "mooney", "holmes_mow"}));
}

// Ranges: E > 0, nu in (-1, 0.5), beta >= 0.
TEST(CaseFile, HolmesMowParameterRanges) {
  auto problems = [](const std::string& key_value) {
    return problems_of(kMinimalCase + "[material]\nsolid_law = \"holmes_mow\"\n" + key_value +
                       "\n");
  };
  EXPECT_TRUE(has_problem(problems("poissons_ratio = 0.5"),
                          {"material.poissons_ratio", "0.5", "in (-1, 0.5)"}));
  EXPECT_TRUE(has_problem(problems("poissons_ratio = -1.0"), {"material.poissons_ratio"}));
  EXPECT_TRUE(has_problem(problems("youngs_modulus = 0.0"), {"material.youngs_modulus", "> 0"}));
  EXPECT_TRUE(has_problem(problems("beta = -0.1"), {"material.beta", ">= 0"}));
  const std::string valid =
      kMinimalCase + "[material]\nsolid_law = \"holmes_mow\"\npoissons_ratio = 0.49\nbeta = 0.0\n";
  EXPECT_EQ(parse_case(valid, "cases/x.toml", {}, ".").material.get("poissons_ratio"), 0.49);
}

}  // namespace
// [[region]]: each omitted key inherited from [material]; the [material] checks on each entry,
// named region[i].key.
TEST(CaseFile, RegionsInheritFromMaterial) {
  const Config c = parse_case(kMinimalCase + R"(
[material]
lambda = 0.3
mu = 0.6
permeability = 2e-3

[[region]]
name = "bone"
mu = 5.0

[[region]]
name = "cartilage"
solid_law = "holmes_mow"
youngs_modulus = 0.7
permeability_law = "exponential"
permeability_M = 3.0
)",
                              "cases/x.toml", {}, ".");
  ASSERT_EQ(c.regions.size(), 2u);
  EXPECT_EQ(c.regions[0].name, "bone");
  EXPECT_EQ(c.regions[0].material.get("mu"), 5.0);
  EXPECT_EQ(c.regions[0].material.get("lambda"), 0.3);
  EXPECT_EQ(c.regions[0].material.get("permeability"), 2e-3);
  EXPECT_EQ(c.regions[1].material.solid_law, "holmes_mow");
  EXPECT_EQ(c.regions[1].material.get("youngs_modulus"), 0.7);
  EXPECT_EQ(c.regions[1].material.permeability_law, "exponential");
  EXPECT_EQ(c.regions[1].material.get("permeability_M"), 3.0);
  EXPECT_EQ(c.regions[1].material.get("permeability"), 2e-3);
  EXPECT_EQ(c.material.get("mu"), 0.6);  // [material] itself unchanged
  EXPECT_EQ(c.material.solid_law, "neo_hookean");
  // --set reaches an entry's keys.
  const Config set = parse_case(kMinimalCase + "[[region]]\nname = \"bone\"\n", "cases/x.toml",
                                {"region[0].permeability=5e-4"}, ".");
  EXPECT_EQ(set.regions.at(0).material.get("permeability"), 5e-4);
  // The choice of [material] is inherited: a region under a Holmes-Mow [material] may give E.
  const Config hm = parse_case(kMinimalCase + R"(
[material]
solid_law = "holmes_mow"

[[region]]
name = "a"
youngs_modulus = 2.0
)",
                               "cases/x.toml", {}, ".");
  EXPECT_EQ(hm.regions.at(0).material.solid_law, "holmes_mow");
  EXPECT_EQ(hm.regions.at(0).material.get("youngs_modulus"), 2.0);
}

TEST(CaseFile, RegionKeysAreCheckedLikeMaterial) {
  const auto p = problems_of(kMinimalCase + R"(
[[region]]
name = "a"
lambda = 0.2
solid_law = "holmes_mow"
permeability = -1

[[region]]
mu = 0.5

[[region]]
name = "a"
permeability_kappa = 2.0
viscosity = 1.0

[[region]]
name = "c"
lambda = -1.0
)");
  EXPECT_TRUE(has_problem(p, {"cases/x.toml: region[0].lambda = 0.2",
                              "applies only to region[0].solid_law = \"neo_hookean\"",
                              "not to region[0].solid_law = \"holmes_mow\""}));
  EXPECT_TRUE(has_problem(p, {"region[0].permeability = -1", "must be > 0"}));
  EXPECT_TRUE(has_problem(p, {"region[1].name", "required key is missing"}));
  EXPECT_TRUE(has_problem(p, {"region[2].name = \"a\"", "another [[region]] has this name"}));
  EXPECT_TRUE(has_problem(p, {"region[2].permeability_kappa = 2.0", "holmes_mow"}));
  EXPECT_TRUE(has_problem(p, {"region[2].viscosity"}));
  EXPECT_TRUE(has_problem(p, {"region[3].lambda = -1.0", "region[3].lambda + 2/3 region[3].mu"}));
  for (const auto& problem : p) EXPECT_EQ(problem.find("material."), std::string::npos) << problem;
}

TEST(CaseFile, ColumnRegionKeys) {
  const std::string column = R"(
[mesh]
source = "column"
[mesh.column]
nz = 4
region_names = ["lower", "upper"]
)";
  const Config c =
      parse_case(kMinimalCase + column + "region_tops = [0.5, 1.0]\n", "cases/x.toml", {}, ".");
  EXPECT_EQ(c.mesh.column.region_names, (std::vector<std::string>{"lower", "upper"}));
  EXPECT_EQ(c.mesh.column.region_tops, (std::vector<double>{0.5, 1.0}));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + column + "region_tops = [0.4, 1.0]\n"),
                          {"mesh.column.region_tops = [0.4, 1.0]", "not a layer interface"}));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + column + "region_tops = [0.5, 0.75]\n"),
                          {"mesh.column.region_tops", "mesh.column.height"}));
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + column + "region_tops = [1.0]\n"),
                          {"mesh.column.region_tops", "2 names, 1 tops"}));
}

}  // namespace biphasic
