// Case-file keys of the volume loads ([body_force], [fluid_source]).
#include <gtest/gtest.h>

#include "biphasic/io/case_file.hpp"
#include "case_test_support.hpp"

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::kMinimalCase;
using testing_support::problems_of;

TEST(CaseLoads, FormulasAreParsedOnceAndEvaluate) {
  const Config c = parse_case(kMinimalCase + R"toml(
[body_force]
x = "0.1 * sin(pi * x) * t"
z = -0.02
[fluid_source]
value = "1e-3 * (1 + y^2)"
)toml",
                              "cases/x.toml");
  EXPECT_DOUBLE_EQ(c.loads.body_force[0](0.5, 0.0, 0.0, 2.0), 0.2);
  EXPECT_TRUE(c.loads.body_force[1].is_zero());
  EXPECT_EQ(c.loads.body_force[2](1.0, 2.0, 3.0, 4.0), -0.02);
  EXPECT_EQ(c.loads.body_force[2].text(), "-0.02");
  EXPECT_DOUBLE_EQ(c.loads.fluid_source(0.0, 2.0, 0.0, 0.0), 5e-3);
  const nlohmann::json j = config_to_json(c);
  EXPECT_EQ(j["body_force"]["x"], "0.1 * sin(pi * x) * t");
  EXPECT_EQ(j["fluid_source"]["value"], "1e-3 * (1 + y^2)");
}

TEST(CaseLoads, DefaultsAreZero) {
  const Config c = parse_case(kMinimalCase, "cases/x.toml");
  for (const Expression& b : c.loads.body_force) EXPECT_TRUE(b.is_zero());
  EXPECT_TRUE(c.loads.fluid_source.is_zero());
}

TEST(CaseLoads, BadFormulasNameTheFileTheKeyAndThePosition) {
  const auto problems = problems_of(kMinimalCase + R"toml(
[body_force]
x = "sin(x"
y = "2 * q"
z = true
w = "1"
[fluid_source]
value = ""
)toml");
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: body_force.x = \"sin(x\": at character 6: "
                                     "expected ')' to close the '(' at character 4"}));
  EXPECT_TRUE(
      has_problem(problems, {"body_force.y = \"2 * q\": at character 5: unknown name 'q'"}));
  EXPECT_TRUE(has_problem(problems, {"body_force.z = true: expected a formula"}));
  EXPECT_TRUE(has_problem(problems, {"unknown key 'body_force.w'"}));
  EXPECT_TRUE(has_problem(problems, {"fluid_source.value = \"\": at character 1: the formula is "
                                     "empty"}));
}

TEST(CaseLoads, OverridesTakeFormulas) {
  const Config c = parse_case(kMinimalCase, "cases/x.toml",
                              {"body_force.z=-0.01*t", "fluid_source.value=\"2 * x\""});
  EXPECT_DOUBLE_EQ(c.loads.body_force[2](0, 0, 0, 3.0), -0.03);
  EXPECT_EQ(c.loads.fluid_source(1.5, 0, 0, 0), 3.0);
  const auto problems = problems_of(kMinimalCase, {"body_force.z=sin("});
  EXPECT_TRUE(has_problem(problems, {"--set: body_force.z = \"sin(\": at character 5"}));
}

}  // namespace
}  // namespace biphasic
