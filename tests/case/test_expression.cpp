// Case-file formulas: precedence, associativity, functions, simplification, symbolic
// derivatives against central differences, and error positions.
#include "biphasic/io/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace biphasic {
namespace {

using V = Expression::Variable;

double eval(const std::string& text, double x = 0.0, double y = 0.0, double z = 0.0,
            double t = 0.0) {
  return Expression::parse(text)(x, y, z, t);
}

TEST(Expression, NumbersAndPrecedence) {
  EXPECT_EQ(eval("42"), 42.0);
  EXPECT_EQ(eval(".5 + 1."), 1.5);
  EXPECT_EQ(eval("1e-3 * 2"), 0.002);
  EXPECT_EQ(eval("2.5E+2"), 250.0);
  EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(eval("2 - 3 - 4"), -5.0);  // left-associative
  EXPECT_EQ(eval("8 / 4 / 2"), 1.0);
  EXPECT_EQ(eval("1 + 6 / 2 * 3"), 10.0);
  EXPECT_EQ(eval("2 * -3"), -6.0);
  EXPECT_EQ(eval("--2"), 2.0);
  EXPECT_EQ(eval("+2 - -1"), 3.0);
  EXPECT_EQ(eval("  1\t+\n2 "), 3.0);
}

TEST(Expression, PowerIsRightAssociativeAndBindsTighterThanUnaryMinus) {
  EXPECT_EQ(eval("2^3^2"), 512.0);  // 2^(3^2)
  EXPECT_EQ(eval("(2^3)^2"), 64.0);
  EXPECT_EQ(eval("-2^2"), -4.0);  // -(2^2)
  EXPECT_EQ(eval("(-2)^2"), 4.0);
  EXPECT_EQ(eval("2^-1"), 0.5);
  EXPECT_EQ(eval("2 * 3^2"), 18.0);
  EXPECT_EQ(eval("-x^2", 3.0), -9.0);
  EXPECT_EQ(Expression::parse("-x^2").to_string(), "(-(x ^ 2))");
  EXPECT_EQ(Expression::parse("x^y^z").to_string(), "(x ^ (y ^ z))");
  EXPECT_EQ(Expression::parse("x - y - z").to_string(), "((x - y) - z)");
  EXPECT_EQ(Expression::parse("x / y * z").to_string(), "((x / y) * z)");
}

TEST(Expression, VariablesFunctionsAndPi) {
  EXPECT_EQ(eval("x + 2*y + 3*z + 4*t", 1.0, 2.0, 3.0, 4.0), 30.0);
  EXPECT_EQ(eval("pi"), std::numbers::pi);
  EXPECT_DOUBLE_EQ(eval("sin(pi / 2)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("cos(x)", 0.3), std::cos(0.3));
  EXPECT_DOUBLE_EQ(eval("tan(pi / 4)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("exp(1)"), std::numbers::e);
  EXPECT_DOUBLE_EQ(eval("log(exp(2))"), 2.0);
  EXPECT_EQ(eval("sqrt(16)"), 4.0);
  EXPECT_EQ(eval("abs(-3)"), 3.0);
  EXPECT_EQ(eval("sqrt(abs(y - 20))", 0.0, 4.0), 4.0);
  EXPECT_DOUBLE_EQ(eval("0.1 * sin(pi * x) * exp(-t / 2)", 0.25, 0.0, 0.0, 1.0),
                   0.1 * std::sin(std::numbers::pi * 0.25) * std::exp(-0.5));
  EXPECT_TRUE(std::isnan(eval("log(-1)")));
  EXPECT_TRUE(std::isinf(eval("1 / x")));
}

TEST(Expression, ConstantsFoldAndDependenciesAreKnown) {
  const Expression c = Expression::parse("2 * pi * 3");
  EXPECT_TRUE(c.is_constant());
  EXPECT_DOUBLE_EQ(c(0, 0, 0, 0), 6.0 * std::numbers::pi);
  EXPECT_TRUE(Expression::parse("0 * sin(x)").is_zero());
  EXPECT_TRUE(Expression::parse("x - x + 0").depends_on(V::X));  // no algebra beyond constants
  const Expression e = Expression::parse("x * t + 0 * y");
  EXPECT_TRUE(e.depends_on(V::X));
  EXPECT_TRUE(e.depends_on(V::T));
  EXPECT_FALSE(e.depends_on(V::Y));
  EXPECT_FALSE(e.depends_on(V::Z));
  EXPECT_TRUE(Expression().is_zero());
  EXPECT_EQ(Expression().text(), "0");
  EXPECT_EQ(Expression::constant(2.5)(1, 2, 3, 4), 2.5);
  EXPECT_EQ(Expression::parse("sin(x)").text(), "sin(x)");
}

TEST(Expression, DeepFormulasEvaluate) {
  // Right-nested sums need a deep evaluation stack.
  std::string text = "x";
  for (int i = 0; i < 40; ++i) text = "x + (" + text + ")";
  EXPECT_EQ(eval(text, 0.5), 20.5);
}

TEST(Expression, DerivativesMatchCentralDifferences) {
  const std::vector<std::string> formulas = {
      "x^3 * y - 2 * z / (1 + t^2)",
      "sin(2*x + y) * cos(z) * exp(-t)",
      "tan(0.3 * x) + log(2 + y) * sqrt(1 + z^2)",
      "x^y + (1 + t)^(z / 2)",
      "abs(x - 0.3) * t",
      "-(x * y)^2 / (3 + sin(t))",
      "exp(sqrt(x + y + z + t))",
  };
  const double X[4] = {0.7, 0.4, 0.9, 1.3};
  const double h = 1e-5;
  for (const auto& f : formulas) {
    const Expression e = Expression::parse(f);
    for (int v = 0; v < 4; ++v) {
      const Expression d = e.derivative(static_cast<V>(v));
      double xp[4] = {X[0], X[1], X[2], X[3]}, xm[4] = {X[0], X[1], X[2], X[3]};
      xp[v] += h;
      xm[v] -= h;
      const double fd = (e(xp[0], xp[1], xp[2], xp[3]) - e(xm[0], xm[1], xm[2], xm[3])) / (2 * h);
      EXPECT_NEAR(d(X[0], X[1], X[2], X[3]), fd, 1e-8 * std::max(1.0, std::abs(fd)))
          << d.text() << " = " << d.to_string();
    }
  }
}

TEST(Expression, DerivativesAreExactAndSimplified) {
  const Expression e = Expression::parse("t^3 + 5 * x");
  const Expression dt = e.derivative(V::T);
  EXPECT_EQ(dt(7.0, 0.0, 0.0, 2.0), 12.0);
  EXPECT_EQ(dt.text(), "d/dt(t^3 + 5 * x)");
  EXPECT_EQ(dt.to_string(), "(3 * (t ^ 2))");
  EXPECT_TRUE(e.derivative(V::Y).is_zero());
  EXPECT_TRUE(Expression::parse("sin(x) * y").derivative(V::T).is_zero());
  EXPECT_EQ(Expression::parse("3 * t").derivative(V::T).to_string(), "3");
  EXPECT_EQ(Expression::parse("abs(t)").derivative(V::T)(0, 0, 0, -2.0), -1.0);
}

struct BadFormula {
  std::string text;
  std::size_t position;  // 0-based
  std::string detail;
};

TEST(Expression, ErrorsNameThePositionAndTheProblem) {
  const std::vector<BadFormula> cases = {
      {"", 0, "the formula is empty"},
      {"   ", 3, "the formula is empty"},
      {"1 +", 3, "expected a number, a name or '(' but the formula ends"},
      {"sin(x", 5, "expected ')' to close the '(' at character 4"},
      {"(1 + 2", 6, "expected ')' to close the '(' at character 1"},
      {"(2x)", 2, "expected ')' to close the '(' at character 1, found 'x'"},
      {"2 * (3 + 4))", 11, "')' without a matching '('"},
      {"foo(x)", 0, "unknown name 'foo'"},
      {"2 * Sin(x)", 4, "unknown name 'Sin'"},
      {"sin x", 4, "function 'sin' needs its argument in parentheses"},
      {"x(2)", 1, "'x' is not a function"},
      {"2x", 1, "expected an operator (+ - * / ^) or the end of the formula, found 'x'"},
      {"3 # 4", 2, "found '#'"},
      {"* 3", 0, "expected a number, a name or '(', found '*'"},
      {"1 + 1e", 4, "malformed number '1e'"},
      {"1..2", 0, "malformed number '1..2'"},
      {"1e999", 0, "number '1e999' is out of range"},
      {"2 ^ ", 4, "but the formula ends"},
  };
  for (const auto& c : cases) {
    try {
      Expression::parse(c.text);
      ADD_FAILURE() << "accepted: '" << c.text << "'";
    } catch (const ExpressionError& e) {
      EXPECT_EQ(e.position(), c.position) << "'" << c.text << "': " << e.what();
      EXPECT_NE(e.detail().find(c.detail), std::string::npos) << "'" << c.text << "': " << e.what();
      EXPECT_EQ(
          std::string(e.what()).rfind("at character " + std::to_string(c.position + 1) + ": ", 0),
          0u)
          << e.what();
    }
  }
  const std::string deep = std::string(1000, '(') + "1" + std::string(1000, ')');
  EXPECT_THROW(
      {
        try {
          Expression::parse(deep);
        } catch (const ExpressionError& e) {
          EXPECT_NE(std::string(e.what()).find("nested too deeply"), std::string::npos);
          throw;
        }
      },
      ExpressionError);
}

// A long flat sum is a left-leaning tree as deep as it is long: compiling, differentiating,
// evaluating and printing it must not recurse (a 300 000-character "x+x+…" overflowed the
// stack in compilation, a 1.1 MB formula in its time derivative).
TEST(Expression, LongFlatFormulasAtTheLengthLimitWorkWithoutRecursion) {
  const std::size_t terms = (Expression::kMaxLength + 1) / 2;  // "x+x+…+x", at the limit
  std::string sum = "x";
  while (sum.size() + 2 <= Expression::kMaxLength) sum += "+x";
  ASSERT_EQ(sum.size(), 2 * terms - 1);
  const Expression e = Expression::parse(sum);
  EXPECT_EQ(e(0.5, 0, 0, 0), 0.5 * static_cast<double>(terms));
  EXPECT_EQ(e.derivative(Expression::Variable::X)(0, 0, 0, 0), static_cast<double>(terms));
  EXPECT_TRUE(e.derivative(Expression::Variable::T).is_zero());
  EXPECT_EQ(e.to_string().size(), sum.size() + 4 * (terms - 1) + 0);  // "(a + b)" per '+'

  // A product of n factors of t: d/dt t^n = n t^(n−1); the derivative must stay linear in
  // size (every shared subtree computed once), not quadratic.
  std::string product = "t";
  while (product.size() + 2 <= 20'001) product += "*t";
  const double n = static_cast<double>((product.size() + 1) / 2);
  const Expression p = Expression::parse(product);
  EXPECT_EQ(p.derivative(Expression::Variable::T)(0, 0, 0, 1.0), n);
  EXPECT_EQ(p.derivative(Expression::Variable::T).derivative(Expression::Variable::T)(0, 0, 0, 1.0),
            n * (n - 1));
}

TEST(Expression, FormulaLongerThanTheLimitIsAnErrorNamingTheLimit) {
  for (const std::size_t size :
       {Expression::kMaxLength + 1, std::size_t{300'000}, std::size_t{1'100'000}}) {
    std::string text = "x";
    while (text.size() + 2 <= size) text += "+x";
    if (text.size() < size) text += " ";
    try {
      Expression::parse(text);
      ADD_FAILURE() << "a formula of " << text.size() << " characters was accepted";
    } catch (const ExpressionError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::to_string(text.size()) + " characters"), std::string::npos) << what;
      EXPECT_NE(what.find("limit of " + std::to_string(Expression::kMaxLength)), std::string::npos)
          << what;
    }
  }
}

}  // namespace
}  // namespace biphasic
