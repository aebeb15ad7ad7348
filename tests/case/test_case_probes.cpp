// [[probe]] tables and output.line_points: read into the Config, reported with file, key and
// value when wrong, overridable with --set probe[i].key, and in the JSON dump.
#include <gtest/gtest.h>

#include "case_test_support.hpp"

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::kMinimalCase;
using testing_support::problems_of;

const std::string kTwoProbes = kMinimalCase + R"(
[output]
line_points = 51

[[probe]]
name = "radial"
start = [0.0, 0.0, 4.0]
end = [17.0, 0.0, 4.0]
points = 35

[[probe]]
name = "off-axis_2"
start = [1.0, 1.0, 0.0]
end = [1.0, 1.0, 8.0]
)";

TEST(CaseProbes, ProbesAreRead) {
  const Config c = parse_case(kTwoProbes, "cases/x.toml");
  EXPECT_EQ(c.output.line_points, 51);
  ASSERT_EQ(c.output.probes.size(), 2u);
  EXPECT_EQ(c.output.probes[0].name, "radial");
  EXPECT_EQ(c.output.probes[0].start, (std::array<double, 3>{0.0, 0.0, 4.0}));
  EXPECT_EQ(c.output.probes[0].end, (std::array<double, 3>{17.0, 0.0, 4.0}));
  EXPECT_EQ(c.output.probes[0].points, 35);
  EXPECT_EQ(c.output.probes[1].name, "off-axis_2");
  EXPECT_EQ(c.output.probes[1].points, 0);  // default: mesh nodes, or 101 points
  const Config none = parse_case(kMinimalCase, "cases/x.toml");
  EXPECT_TRUE(none.output.probes.empty());
  EXPECT_EQ(none.output.line_points, 0);
}

TEST(CaseProbes, BadProbesNameTheKeyAndValue) {
  const auto problems = problems_of(kMinimalCase + R"(
[output]
line_points = 1

[[probe]]
name = "a b"
start = [0.0, 0.0, 0.0]
end = [1.0, 0.0, 0.0]

[[probe]]
name = "twice"
start = [0.0, 0.0, 0.0]
end = [0.0, 0.0, 0.0]
points = 1

[[probe]]
name = "twice"
start = [0.0, 0.0, 0.0]
end = [1.0, 0.0, 0.0]
pionts = 3

[[probe]]
start = [0.0, 0.0]
)");
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml", "output.line_points = 1", "at least 2"}));
  EXPECT_TRUE(has_problem(problems, {"probe[0].name = \"a b\"", "letters, digits"}));
  EXPECT_TRUE(has_problem(problems, {"probe[1].end = [0.0, 0.0, 0.0]", "must differ from start"}));
  EXPECT_TRUE(has_problem(problems, {"probe[1].points = 1", "at least 2"}));
  EXPECT_TRUE(has_problem(problems, {"probe[2].name = \"twice\"", "another [[probe]]"}));
  EXPECT_TRUE(has_problem(problems, {"probe[2].pionts", "probe[2].points"}));
  EXPECT_TRUE(has_problem(problems, {"probe[3].name", "required"}));
  EXPECT_TRUE(has_problem(problems, {"probe[3].start", "array of 3 numbers"}));
  EXPECT_TRUE(has_problem(problems, {"probe[3].end", "required"}));
  EXPECT_TRUE(has_problem(problems_of("probe = 3\n" + kMinimalCase),
                          {"probe = 3", "expected [[probe]] tables"}));
  EXPECT_TRUE(has_problem(problems_of(kTwoProbes, {"probe[0].points=100001"}),
                          {"--set", "probe[0].points = 100001", "in [0, 100000]"}));
}

TEST(CaseProbes, OverridesReachTheEntries) {
  const Config c = parse_case(kTwoProbes, "cases/x.toml",
                              {"probe[1].points=7", "probe[0].end=[10.0, 0.0, 4.0]"});
  EXPECT_EQ(c.output.probes[1].points, 7);
  EXPECT_EQ(c.output.probes[0].end, (std::array<double, 3>{10.0, 0.0, 4.0}));
  EXPECT_TRUE(has_problem(problems_of(kTwoProbes, {"probe[2].points=7"}),
                          {"--set probe[2].points=7", "out of range", "2 [[probe]] entries"}));
  EXPECT_TRUE(has_problem(problems_of(kTwoProbes, {"probe[0].point=7"}),
                          {"probe[0].point", "did you mean 'probe[0].points'"}));
}

TEST(CaseProbes, ProbesAreInTheJsonDump) {
  const nlohmann::json j = config_to_json(parse_case(kTwoProbes, "cases/x.toml"));
  ASSERT_EQ(j["probe"].size(), 2u);
  EXPECT_EQ(j["probe"][0]["name"], "radial");
  EXPECT_EQ(j["probe"][0]["points"], 35);
  EXPECT_EQ(j["probe"][1]["end"], nlohmann::json({1.0, 1.0, 8.0}));
  EXPECT_EQ(j["output"]["line_points"], 51);
}

}  // namespace
}  // namespace biphasic
