// Formulas of the reference position and time written in case files, e.g. body forces:
//   "0.1 * sin(pi * x) * exp(-t / 2)"
// Grammar (usual precedence; ^ binds tighter than unary minus and groups to the right, so
// -x^2 = -(x^2) and 2^3^2 = 2^9):
//   expression := term (('+' | '-') term)*
//   term       := unary (('*' | '/') unary)*
//   unary      := ('-' | '+') unary | power
//   power      := primary ('^' unary)?
//   primary    := number | name | function '(' expression ')' | '(' expression ')'
// Names: the variables x, y, z (reference coordinates, mm) and t (time, s), the constant pi.
// Functions: sin cos tan exp log sqrt abs (log is the natural logarithm). Numbers: 2, 0.5, .5,
// 1e-3, 2.5E+2. A formula is parsed once into a tree, simplified (constants folded), and
// compiled to a program of register instructions (each node computed once); evaluation is a
// loop over that program with no allocation for ordinary formulas (up to 64 nodes). Outside a
// function's domain (log of a negative number, 0/0) the value is NaN or ±inf, as in C.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace biphasic {

/// A formula that could not be parsed: where (0-based offset into the text) and why.
/// what() is "at character <offset + 1>: <detail>".
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(std::size_t position, const std::string& detail);
  std::size_t position() const { return position_; }
  const std::string& detail() const { return detail_; }

 private:
  std::size_t position_;
  std::string detail_;
};

/// A parsed formula f(x, y, z, t). Copyable value type; evaluation is const and thread-safe.
class Expression {
 public:
  enum class Variable : std::uint8_t { X, Y, Z, T };

  /// The constant 0 (text "0").
  Expression();
  /// Longest formula accepted [characters]; parsing, differentiation, compilation and
  /// evaluation are iterative and linear in the length, this only bounds time and memory.
  static constexpr std::size_t kMaxLength = 100'000;

  /// Parses `text`; throws ExpressionError on a syntax error, an unknown name, nesting deeper
  /// than 200 levels of parentheses, unary signs or powers, or more than kMaxLength characters.
  static Expression parse(const std::string& text);
  /// The constant `value`.
  static Expression constant(double value);

  /// f at reference position (x, y, z) [mm] and time t [s].
  double operator()(double x, double y, double z, double t) const;
  double operator()(const std::array<double, 3>& X, double t) const {
    return (*this)(X[0], X[1], X[2], t);
  }

  /// The exact partial derivative ∂f/∂v, by symbolic differentiation (simplified; the
  /// derivative of abs(a) is sign(a) a′, with sign(0) = 0).
  Expression derivative(Variable v) const;

  /// True if the formula contains `v` after simplification.
  bool depends_on(Variable v) const;
  /// True if the formula is a number after simplification (no variable in it).
  bool is_constant() const;
  /// True if the formula simplifies to the number 0.
  bool is_zero() const;
  /// The text it was parsed from (for a derivative: "d/dv(text)").
  const std::string& text() const { return text_; }
  /// The simplified formula written back as text, fully parenthesised (for messages, tests).
  std::string to_string() const;

 private:
  enum class Op : std::uint8_t {
    Number,
    Var,
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Sin,
    Cos,
    Tan,
    Exp,
    Log,
    Sqrt,
    Abs,
    Sign,  ///< internal: derivative of abs
  };
  /// A tree node; children are indices into nodes_ (a < b < this node's own index).
  struct Node {
    Op op = Op::Number;
    double value = 0.0;  ///< Number
    Variable var = Variable::X;
    std::int32_t a = -1, b = -1;
  };
  /// One instruction: its result is register k (its index in program_), operands are the
  /// registers of earlier instructions (a, b; −1 when unused).
  struct Instruction {
    Op op;
    Variable var;
    double value;
    std::int32_t a, b;
  };
  friend class ExpressionBuilder;
  friend class ExpressionParser;

  void compile();

  std::vector<Node> nodes_;  ///< the tree; the root is the last node
  std::vector<Instruction> program_;
  std::string text_;
};

}  // namespace biphasic
