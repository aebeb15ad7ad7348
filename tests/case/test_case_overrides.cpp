// --set key=value overrides applied before validation.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "case_test_support.hpp"

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::kMinimalCase;
using testing_support::problems_of;

const std::string kTwoBoundaries = kMinimalCase + R"(
[curves]
ramp = [[0.0, 0.0], [32.0, 1.0]]
half = [[0.0, 0.0], [16.0, 0.5]]
)" + "[[boundary]]\nname = \"lateral\"\ntype = \"pressure\"\nvalue = 0.0\n";

TEST(CaseOverrides, NumberArrayAndStrings) {
  const Config c = parse_case(
      kTwoBoundaries, "x.toml",
      {"time.dt=3.2", "output.line_end=[0,0,4]", "stabilisation.type=\"gls\"",
       "stabilisation.length=shortest_edge", "title = a title with spaces", "time.t_end=40"});
  EXPECT_DOUBLE_EQ(c.time.dt, 3.2);
  EXPECT_DOUBLE_EQ(c.time.t_end, 40.0);
  EXPECT_EQ(c.output.line_end, (std::array<double, 3>{0.0, 0.0, 4.0}));
  EXPECT_EQ(c.stabilisation.type, "gls");
  EXPECT_EQ(c.stabilisation.length, ElementLength::ShortestEdge);
  EXPECT_EQ(c.title, "a title with spaces");
}

TEST(CaseOverrides, ReplaceValuesGivenInTheFile) {
  const Config c =
      parse_case(kMinimalCase + "[time]\ndt = 1.0\n", "x.toml", {"time.dt=2.0", "time.dt=4.0"});
  EXPECT_DOUBLE_EQ(c.time.dt, 4.0);  // the last one wins
}

TEST(CaseOverrides, AddKeysAbsentFromTheFile) {
  const Config c = parse_case(kMinimalCase, "x.toml",
                              {"time.newton.max_iterations=7", "mesh.grading_faces=[\"top\"]",
                               "curves.ramp=[[0, 0], [10, 1]]", "boundary[0].curve=ramp"});
  EXPECT_EQ(c.time.newton.max_iterations, 7);
  EXPECT_EQ(c.mesh.cylinder.grading_faces, std::vector<std::string>{"top"});
  ASSERT_EQ(c.curves.count("ramp"), 1u);
  EXPECT_DOUBLE_EQ(c.curves.at("ramp").value(5.0), 0.5);
  EXPECT_EQ(c.bcs[0].curve, "ramp");
}

TEST(CaseOverrides, BoundaryEntries) {
  const Config c = parse_case(
      kTwoBoundaries, "x.toml",
      {"boundary[0].value=-0.1", "boundary[1].curve=half", "boundary[0].component=\"x\""});
  EXPECT_DOUBLE_EQ(c.bcs[0].value, -0.1);
  EXPECT_EQ(c.bcs[0].component, 0);
  EXPECT_EQ(c.bcs[1].curve, "half");
  EXPECT_DOUBLE_EQ(c.bcs[1].value, 0.0);
}

TEST(CaseOverrides, BadOverridesNameTheArgument) {
  const auto problems =
      problems_of(kTwoBoundaries, {"time.dtt=3", "time.dt", "boundary[2].value=1",
                                   "boundary[0].valeu=1", "boundary[x].value=1", "=3"});
  EXPECT_TRUE(has_problem(problems,
                          {"--set time.dtt=3: unknown key 'time.dtt' (did you mean 'time.dt'?)"}));
  EXPECT_TRUE(has_problem(problems, {"--set time.dt: expected key=value"}));
  EXPECT_TRUE(has_problem(
      problems, {"--set boundary[2].value=1: index 2 is out of range", "2 [[boundary]] entries"}));
  EXPECT_TRUE(has_problem(problems, {"--set boundary[0].valeu=1: unknown key 'boundary[0].valeu'",
                                     "did you mean 'boundary[0].value'?"}));
  EXPECT_TRUE(has_problem(problems, {"--set boundary[x].value=1:"}));
  EXPECT_TRUE(has_problem(problems, {"--set =3: expected key=value"}));
  EXPECT_EQ(problems.size(), 6u);
}

TEST(CaseOverrides, InvalidValuesAreAttributedToSet) {
  const auto problems =
      problems_of(kTwoBoundaries, {"time.dt=-1", "stabilisation.type=glss",
                                   "boundary[1].curve=rampp", "quadrature.points=4.5"});
  EXPECT_TRUE(has_problem(problems, {"--set: time.dt = -1: must be > 0 (s)"}));
  EXPECT_TRUE(
      has_problem(problems, {"--set: stabilisation.type = \"glss\": must be one of none, gls"}));
  EXPECT_TRUE(has_problem(
      problems, {"--set: boundary[1].curve = \"rampp\": no such curve (defined: half, ramp)"}));
  EXPECT_TRUE(has_problem(problems, {"--set: quadrature.points = 4.5: expected an integer"}));
  EXPECT_EQ(problems.size(), 4u);
}

TEST(CaseOverrides, TablesCannotBeSetWhole) {
  const auto problems = problems_of(kMinimalCase, {"time.newton={max_iterations=3}", "curves=3"});
  EXPECT_TRUE(has_problem(problems, {"--set time.newton={max_iterations=3}:",
                                     "'time.newton' is a table", "time.newton.atol_displacement"}));
  EXPECT_TRUE(has_problem(problems, {"--set curves=3:", "'curves' is a table"}));
  EXPECT_EQ(problems.size(), 2u);
}

TEST(CaseOverrides, SettingBelowAValueThatIsNotATable) {
  const auto problems = problems_of("time = 3\n" + kMinimalCase, {"time.dt=1.0"});
  EXPECT_TRUE(has_problem(problems, {"--set time.dt=1.0:", "'time'", "not a table"}));
}

}  // namespace
}  // namespace biphasic
