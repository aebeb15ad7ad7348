// The [material] keys are derived from the laws' own declarations (material_laws.hpp): these
// tests walk the registry, so that a newly registered law is checked without a test of its own.
// For every law and every parameter it declares: the key is read and stored under the law, its
// bounds are enforced, and it is refused under a law of its family that does not read it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "biphasic/material/material_laws.hpp"
#include "case_test_support.hpp"

namespace biphasic {
namespace {

using testing_support::has_problem;
using testing_support::kMinimalCase;
using testing_support::problems_of;

bool within(const ParameterBounds& b, double x) {
  return (!b.min || (b.min_open ? x > *b.min : x >= *b.min)) &&
         (!b.max || (b.max_open ? x < *b.max : x <= *b.max));
}

/// A valid value that differs from the parameter's default (near it, so that checks across
/// parameters keep holding).
double other_valid_value(const LawParameter& p) {
  const double x = 1.37 * p.default_value + 0.01;
  EXPECT_TRUE(within(p.bounds, x)) << p.name << " = " << x;
  return x;
}

std::string number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  std::string text = s.str();
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string material_case(const std::string& family, const std::string& law,
                          const std::string& extra) {
  return kMinimalCase + "[material]\n" + family + " = \"" + law + "\"\n" + extra;
}

TEST(CaseMaterialLaws, EveryDeclaredParameterIsReadUnderItsLaw) {
  int checked = 0;
  for (const LawFamily& family : material_law_families()) {
    for (const LawDescription& law : family.laws) {
      for (const LawParameter& p : law.parameters) {
        const double value = other_valid_value(p);
        const Config c =
            parse_case(material_case(family.key, law.name, p.name + " = " + number(value) + "\n"),
                       "cases/x.toml", {}, ".");
        EXPECT_EQ(c.material.*family.chosen, law.name);
        EXPECT_EQ(c.material.get(p.name), value) << law.name << "." << p.name;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 11);  // the laws registered when this test was written
}

TEST(CaseMaterialLaws, EveryBoundIsEnforcedNamingTheKey) {
  for (const LawFamily& family : material_law_families()) {
    for (const LawDescription& law : family.laws) {
      for (const LawParameter& p : law.parameters) {
        for (const auto& [edge, open] : {std::pair{p.bounds.min, p.bounds.min_open},
                                         std::pair{p.bounds.max, p.bounds.max_open}}) {
          if (!edge) continue;
          const double outside = edge == p.bounds.min ? *edge - 1.0 : *edge + 1.0;
          for (double bad :
               open ? std::vector<double>{*edge, outside} : std::vector<double>{outside}) {
            const auto problems = problems_of(
                material_case(family.key, law.name, p.name + " = " + number(bad) + "\n"));
            EXPECT_TRUE(has_problem(problems, {"material." + p.name + " = "}))
                << law.name << "." << p.name << " = " << bad;
          }
        }
      }
    }
  }
}

TEST(CaseMaterialLaws, AParameterIsRefusedUnderALawThatDoesNotReadIt) {
  int checked = 0;
  for (const LawFamily& family : material_law_families()) {
    for (const LawDescription& chosen : family.laws) {
      for (const LawDescription& other : family.laws) {
        for (const LawParameter& p : other.parameters) {
          if (chosen.reads(p.name)) continue;
          const auto problems = problems_of(material_case(
              family.key, chosen.name, p.name + " = " + number(other_valid_value(p)) + "\n"));
          EXPECT_TRUE(has_problem(
              problems, {"material." + p.name, "applies only to", "\"" + other.name + "\"",
                         "not to material." + family.key + " = \"" + chosen.name + "\""}))
              << chosen.name << " given " << p.name;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(CaseMaterialLaws, TheReferenceListsEveryLawAndParameter) {
  const std::string reference = case_schema_markdown();
  for (const LawFamily& family : material_law_families()) {
    EXPECT_NE(reference.find("`material." + family.key + "`"), std::string::npos);
    for (const LawDescription& law : family.laws) {
      EXPECT_NE(reference.find("`" + law.name + "`"), std::string::npos) << law.name;
      for (const LawParameter& p : law.parameters) {
        EXPECT_NE(reference.find("`material." + p.name + "`"), std::string::npos) << p.name;
        EXPECT_NE(reference.find("`region[i]." + p.name + "`"), std::string::npos) << p.name;
      }
    }
  }
}

TEST(CaseMaterialLaws, ALawsOwnCheckRunsOnMaterialAndRegions) {
  // The Neo-Hookean law declares lambda + 2/3 mu > 0.
  EXPECT_TRUE(has_problem(problems_of(kMinimalCase + "[material]\nlambda = -1.0\nmu = 0.6\n"),
                          {"material.lambda = -1.0", "material.lambda + 2/3 material.mu"}));
}

}  // namespace
}  // namespace biphasic
