// Formula parser: any text either parses (then evaluates, differentiates and prints) or is an
// ExpressionError; nothing else (no crash, stack overflow, hang or unbounded growth).
#include <cstddef>
#include <cstdint>
#include <string>

#include "biphasic/io/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using biphasic::Expression;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Expression e = Expression::parse(text);
    volatile double sink = e(0.5, -1.0, 2.0, 0.25);
    for (auto v : {Expression::Variable::X, Expression::Variable::Y, Expression::Variable::Z,
                   Expression::Variable::T}) {
      const Expression d = e.derivative(v);
      sink = d(0.5, -1.0, 2.0, 0.25);
      sink = d.derivative(Expression::Variable::T)(0.5, -1.0, 2.0, 0.25);
    }
    if (text.size() < 2000) sink = static_cast<double>(e.to_string().size());
    (void)sink;
  } catch (const biphasic::ExpressionError&) {
  }
  return 0;
}
