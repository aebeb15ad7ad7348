// Case-file keys of the volume loads ([body_force], [fluid_source]).
#include <gtest/gtest.h>
#include <pthread.h>

#include <functional>
#include <string>

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

/// Runs `work` on a thread with a stack of `bytes` and waits for it: recursion as deep as a
/// long formula overflows such a stack (and crashes the test), a loop does not.
void run_on_small_stack(std::size_t bytes, const std::function<void()>& work) {
  pthread_attr_t attr;
  ASSERT_EQ(pthread_attr_init(&attr), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, bytes), 0);
  pthread_t thread;
  auto call = [](void* w) -> void* {
    (*static_cast<const std::function<void()>*>(w))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attr, call, const_cast<std::function<void()>*>(&work)), 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
}

/// "v+v+…+v" of `length` characters (odd), or of `length` − 1 and a trailing space (even).
std::string flat_sum(char v, std::size_t length) {
  std::string sum(1, v);
  while (sum.size() + 2 <= length) sum += std::string("+") + v;
  if (sum.size() < length) sum += " ";
  return sum;
}

// Formulas up to the length limit (100 000 characters) are taken from a case file and work
// without recursion: a 50 000-character "t+t+…" (a tree 25 000 levels deep) is read, evaluated
// and differentiated in time (∂b/∂t, which the integrators use) exactly, on a 512 KiB stack. One
// character more than the limit is refused naming the file, the key and the limit.
TEST(CaseLoads, FormulasUpToTheLengthLimitWorkWithoutRecursionLongerOnesNameTheKey) {
  run_on_small_stack(512 * 1024, [] {
    const std::string sum = flat_sum('t', 50'000);
    const Config c =
        parse_case(kMinimalCase + "[body_force]\nz = \"" + sum + "\"\n", "cases/x.toml");
    const Expression& b = c.loads.body_force[2];
    EXPECT_EQ(b(0.0, 0.0, 0.0, 0.5), 12'500.0);
    const Expression rate = b.derivative(Expression::Variable::T);
    EXPECT_EQ(rate(0.0, 0.0, 0.0, 0.5), 25'000.0);
    EXPECT_TRUE(rate.is_constant());
    EXPECT_TRUE(b.derivative(Expression::Variable::X).is_zero());
  });

  const std::string at_limit = flat_sum('x', 100'000);
  const Config c =
      parse_case(kMinimalCase + "[body_force]\nx = \"" + at_limit + "\"\n", "cases/x.toml");
  EXPECT_EQ(c.loads.body_force[0](2.0, 0.0, 0.0, 0.0), 100'000.0);  // 50 000 terms
  const auto problems =
      problems_of(kMinimalCase + "[body_force]\nx = \"" + flat_sum('x', 100'001) + "\"\n");
  EXPECT_TRUE(has_problem(problems, {"cases/x.toml: body_force.x", "100001 characters",
                                     "more than the limit of 100000"}));
}

}  // namespace
}  // namespace biphasic
