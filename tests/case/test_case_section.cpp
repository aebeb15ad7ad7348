// Case files of two-dimensional models: the model and section keys are read, and what a
// two-dimensional model cannot mean (a z component, a point off z = 0, a tetrahedral mesh
// source, a section without a two-dimensional model) is refused naming the key.
#include <gtest/gtest.h>

#include <string>

#include "case_test_support.hpp"

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::problems_of;

const std::string kSectionCase = R"(
format_version = 1
model = "axisymmetric"

[mesh]
source = "section"

[mesh.section]
width = 2.0
height = 1.0
nr = 8
nz = 6
grading_curves = ["top", "bottom"]
grading_ratio = 4.0

[[boundary]]
name = "top"
type = "displacement"
component = "y"
value = -0.01

[output]
line_start = [0.0, 0.0, 0.0]
line_end = [0.0, 1.0, 0.0]
)";

TEST(CaseSection, ModelAndSectionKeysAreRead) {
  const Config c = parse_case(kSectionCase, "section.toml");
  EXPECT_EQ(c.model, ModelKind::Axisymmetric);
  EXPECT_EQ(c.mesh.source, MeshSource::Section);
  EXPECT_EQ(c.mesh.section.width, 2.0);
  EXPECT_EQ(c.mesh.section.height, 1.0);
  EXPECT_EQ(c.mesh.section.nr, 8);
  EXPECT_EQ(c.mesh.section.nz, 6);
  EXPECT_EQ(c.mesh.section.grading_ratio, 4.0);
  EXPECT_EQ(c.mesh.section.grading_curves.size(), 2u);
  EXPECT_EQ(to_string(c.model), "axisymmetric");
  EXPECT_EQ(config_to_json(c).at("model"), "axisymmetric");
  const Config plane = parse_case(kSectionCase, "section.toml", {"model=\"plane_strain\""});
  EXPECT_EQ(plane.model, ModelKind::PlaneStrain);
  // The default is the three-dimensional model.
  EXPECT_EQ(parse_case(testing_support::kMinimalCase, "m.toml").model, ModelKind::ThreeDimensional);
}

TEST(CaseSection, ZComponentsAndPointsOffThePlaneAreRefused) {
  std::string text = kSectionCase;
  text.replace(text.find("component = \"y\""), 15, "component = \"z\"");
  EXPECT_TRUE(has_problem(problems_of(text), {"boundary[0].component", "\"z\"", "axisymmetric"}));
  EXPECT_TRUE(has_problem(problems_of(kSectionCase, {"output.line_end=[0.0, 1.0, 0.5]"}),
                          {"output.line_end", "z = 0"}));
  EXPECT_TRUE(has_problem(problems_of(kSectionCase, {"body_force.z=\"0.1\""}),
                          {"body_force.z", "no z component"}));
}

TEST(CaseSection, SourceAndModelMustAgree) {
  // A section mesh without a two-dimensional model.
  EXPECT_TRUE(has_problem(problems_of(kSectionCase, {"model=\"three_dimensional\""}),
                          {"mesh.source", "\"section\"", "two-dimensional model"}));
  // A two-dimensional model on a generated tetrahedral mesh.
  std::string text = testing_support::kMinimalCase;
  text.replace(text.find("component = \"z\""), 15, "component = \"y\"");
  EXPECT_TRUE(has_problem(problems_of("model = \"plane_strain\"\n" + text),
                          {"mesh.source", "section mesh"}));
  // Section keys with another source.
  EXPECT_TRUE(has_problem(
      problems_of(kSectionCase, {"mesh.source=\"column\"", "model=\"three_dimensional\""}),
      {"mesh.section"}));
}

TEST(CaseSection, SectionSpecIsChecked) {
  EXPECT_TRUE(has_problem(problems_of(kSectionCase, {"mesh.section.nz=2"}),
                          {"mesh.section.nz", "must be >= 3"}));
  EXPECT_TRUE(
      has_problem(problems_of(kSectionCase, {"mesh.section.width=0"}), {"mesh.section.width"}));
  EXPECT_TRUE(has_problem(problems_of(kSectionCase, {"mesh.section.grading_curves=[\"side\"]"}),
                          {"mesh.section.grading_curves", "side"}));
  EXPECT_TRUE(
      has_problem(problems_of(kSectionCase, {"model=\"spherical\""}), {"model", "spherical"}));
}

}  // namespace
}  // namespace biphasic
