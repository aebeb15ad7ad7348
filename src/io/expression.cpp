// Parsing (recursive descent), simplification, symbolic differentiation and register
// evaluation of case-file formulas.
#include "biphasic/io/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <system_error>
#include <utility>

namespace biphasic {

namespace {

constexpr std::array<const char*, 4> kVariableNames{"x", "y", "z", "t"};

std::string number_text(double v) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace

ExpressionError::ExpressionError(std::size_t position, const std::string& detail)
    : std::runtime_error("at character " + std::to_string(position + 1) + ": " + detail),
      position_(position),
      detail_(detail) {}

// ---- building simplified trees -------------------------------------------------------------

/// Appends nodes to a tree, folding constants and dropping neutral operands as it goes.
class ExpressionBuilder {
 public:
  using Op = Expression::Op;
  using Node = Expression::Node;
  using Variable = Expression::Variable;

  explicit ExpressionBuilder(std::vector<Node>& nodes) : nodes_(nodes) {}

  static double apply(Op op, double a, double b) {
    switch (op) {
      case Op::Neg:
        return -a;
      case Op::Add:
        return a + b;
      case Op::Sub:
        return a - b;
      case Op::Mul:
        return a * b;
      case Op::Div:
        return a / b;
      case Op::Pow:
        return std::pow(a, b);
      case Op::Sin:
        return std::sin(a);
      case Op::Cos:
        return std::cos(a);
      case Op::Tan:
        return std::tan(a);
      case Op::Exp:
        return std::exp(a);
      case Op::Log:
        return std::log(a);
      case Op::Sqrt:
        return std::sqrt(a);
      case Op::Abs:
        return std::abs(a);
      case Op::Sign:
        return static_cast<double>((a > 0.0) - (a < 0.0));
      case Op::Number:
      case Op::Var:
        break;
    }
    return 0.0;
  }

  int number(double v) {
    Node n;
    n.op = Op::Number;
    n.value = v;
    return push(n);
  }
  int variable(Variable v) {
    Node n;
    n.op = Op::Var;
    n.var = v;
    return push(n);
  }
  int unary(Op op, int a) {
    if (is_number(a)) return number(apply(op, value(a), 0.0));
    if (op == Op::Neg && nodes_[a].op == Op::Neg) return nodes_[a].a;
    Node n;
    n.op = op;
    n.a = a;
    return push(n);
  }
  int binary(Op op, int a, int b) {
    if (is_number(a) && is_number(b)) return number(apply(op, value(a), value(b)));
    switch (op) {
      case Op::Add:
        if (is(a, 0.0)) return b;
        if (is(b, 0.0)) return a;
        break;
      case Op::Sub:
        if (is(b, 0.0)) return a;
        if (is(a, 0.0)) return unary(Op::Neg, b);
        break;
      case Op::Mul:
        if (is(a, 0.0) || is(b, 0.0)) return number(0.0);
        if (is(a, 1.0)) return b;
        if (is(b, 1.0)) return a;
        if (is(a, -1.0)) return unary(Op::Neg, b);
        if (is(b, -1.0)) return unary(Op::Neg, a);
        break;
      case Op::Div:
        if (is(a, 0.0)) return number(0.0);
        if (is(b, 1.0)) return a;
        break;
      case Op::Pow:
        if (is(b, 0.0)) return number(1.0);
        if (is(b, 1.0)) return a;
        break;
      default:
        break;
    }
    Node n;
    n.op = op;
    n.a = a;
    n.b = b;
    return push(n);
  }

  /// Appends ∂(subtree at root)/∂v and returns its node. Iterative: children have smaller
  /// indices than their parents, so one pass in index order over the nodes reachable from
  /// the root finds every child's derivative done (no recursion, linear in the tree size).
  int derivative(int root, Variable v) {
    const std::vector<char> used = reachable(nodes_, root);
    std::vector<int> done(static_cast<std::size_t>(root) + 1, -1);
    for (int i = 0; i <= root; ++i)
      if (used[static_cast<std::size_t>(i)]) done[static_cast<std::size_t>(i)] = step(i, v, done);
    return done[static_cast<std::size_t>(root)];
  }

  /// The nodes reachable from `root` (a mask over nodes[0..root]).
  static std::vector<char> reachable(const std::vector<Node>& nodes, int root) {
    std::vector<char> used(static_cast<std::size_t>(root) + 1, 0);
    used[static_cast<std::size_t>(root)] = 1;
    for (int i = root; i >= 0; --i) {
      if (!used[static_cast<std::size_t>(i)]) continue;
      const Node& n = nodes[static_cast<std::size_t>(i)];
      if (n.a >= 0) used[static_cast<std::size_t>(n.a)] = 1;
      if (n.b >= 0) used[static_cast<std::size_t>(n.b)] = 1;
    }
    return used;
  }

  bool is_number(int i) const { return nodes_[i].op == Op::Number; }

 private:
  /// ∂(node i)/∂v from the derivatives of its children, already in `done`.
  int step(int i, Variable v, const std::vector<int>& done) {
    const Node n = nodes_[i];  // copy: push() may reallocate
    int d = 0;
    auto da = [&] { return done[static_cast<std::size_t>(n.a)]; };
    auto db = [&] { return done[static_cast<std::size_t>(n.b)]; };
    switch (n.op) {
      case Op::Number:
        d = number(0.0);
        break;
      case Op::Var:
        d = number(n.var == v ? 1.0 : 0.0);
        break;
      case Op::Neg:
        d = unary(Op::Neg, da());
        break;
      case Op::Add:
      case Op::Sub:
        d = binary(n.op, da(), db());
        break;
      case Op::Mul:  // a′b + ab′
        d = binary(Op::Add, binary(Op::Mul, da(), n.b), binary(Op::Mul, n.a, db()));
        break;
      case Op::Div:  // a′/b − a b′/b²
        d = binary(Op::Sub, binary(Op::Div, da(), n.b),
                   binary(Op::Div, binary(Op::Mul, n.a, db()), binary(Op::Mul, n.b, n.b)));
        break;
      case Op::Pow: {
        const int dexp = db();
        if (is(dexp, 0.0)) {  // b a^(b−1) a′
          d = binary(Op::Mul,
                     binary(Op::Mul, n.b, binary(Op::Pow, n.a, binary(Op::Sub, n.b, number(1.0)))),
                     da());
        } else {  // a^b (b′ ln a + b a′/a)
          d = binary(Op::Mul, i,
                     binary(Op::Add, binary(Op::Mul, dexp, unary(Op::Log, n.a)),
                            binary(Op::Div, binary(Op::Mul, n.b, da()), n.a)));
        }
        break;
      }
      case Op::Sin:
        d = binary(Op::Mul, unary(Op::Cos, n.a), da());
        break;
      case Op::Cos:
        d = unary(Op::Neg, binary(Op::Mul, unary(Op::Sin, n.a), da()));
        break;
      case Op::Tan: {  // a′ / cos²a
        const int c = unary(Op::Cos, n.a);
        d = binary(Op::Div, da(), binary(Op::Mul, c, c));
        break;
      }
      case Op::Exp:
        d = binary(Op::Mul, i, da());
        break;
      case Op::Log:
        d = binary(Op::Div, da(), n.a);
        break;
      case Op::Sqrt:
        d = binary(Op::Div, da(), binary(Op::Mul, number(2.0), i));
        break;
      case Op::Abs:
        d = binary(Op::Mul, unary(Op::Sign, n.a), da());
        break;
      case Op::Sign:
        d = number(0.0);
        break;
    }
    return d;
  }

  int push(const Node& n) {
    nodes_.push_back(n);
    return static_cast<int>(nodes_.size()) - 1;
  }
  double value(int i) const { return nodes_[i].value; }
  bool is(int i, double v) const { return is_number(i) && nodes_[i].value == v; }

  std::vector<Node>& nodes_;
};

// ---- parsing --------------------------------------------------------------------------------

class ExpressionParser {
 public:
  using Op = Expression::Op;

  ExpressionParser(const std::string& text, std::vector<Expression::Node>& nodes)
      : text_(text), build_(nodes) {}

  /// Parses the whole text; the returned node is the root.
  int parse() {
    skip_space();
    if (pos_ == text_.size()) throw ExpressionError(pos_, "the formula is empty");
    const int root = expression();
    skip_space();
    if (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ')') throw ExpressionError(pos_, "')' without a matching '('");
      throw ExpressionError(pos_,
                            "expected an operator (+ - * / ^) or the end of the formula, "
                            "found " +
                                found());
    }
    return root;
  }

 private:
  static constexpr int kMaxDepth = 200;

  /// Guards the recursion depth (a formula like "((((…" must not overflow the stack).
  struct Nesting {
    explicit Nesting(ExpressionParser& p) : parser(p) {
      if (++parser.depth_ > kMaxDepth)
        throw ExpressionError(parser.pos_, "the formula is nested too deeply");
    }
    ~Nesting() { --parser.depth_; }
    ExpressionParser& parser;
  };

  int expression() {
    Nesting guard(*this);
    int left = term();
    while (true) {
      skip_space();
      if (accept('+'))
        left = build_.binary(Op::Add, left, term());
      else if (accept('-'))
        left = build_.binary(Op::Sub, left, term());
      else
        return left;
    }
  }

  int term() {
    int left = unary();
    while (true) {
      skip_space();
      if (accept('*'))
        left = build_.binary(Op::Mul, left, unary());
      else if (accept('/'))
        left = build_.binary(Op::Div, left, unary());
      else
        return left;
    }
  }

  int unary() {
    Nesting guard(*this);
    skip_space();
    if (accept('-')) return build_.unary(Op::Neg, unary());
    if (accept('+')) return unary();
    return power();
  }

  int power() {
    const int base = primary();
    skip_space();
    if (accept('^')) return build_.binary(Op::Pow, base, unary());  // right-associative
    return base;
  }

  int primary() {
    skip_space();
    if (pos_ == text_.size())
      throw ExpressionError(pos_, "expected a number, a name or '(' but the formula ends");
    const char c = text_[pos_];
    if (c == '(') {
      const std::size_t open = pos_++;
      const int inner = expression();
      close(open);
      return inner;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    throw ExpressionError(pos_, "expected a number, a name or '(', found " + found());
  }

  int number() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
      ++pos_;
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    const std::string token = text_.substr(start, pos_ - start);
    double v = 0.0;
    const auto result = std::from_chars(token.data(), token.data() + token.size(), v);
    if (result.ptr != token.data() + token.size() || result.ec == std::errc::invalid_argument)
      throw ExpressionError(start, "malformed number '" + token + "'");
    if (result.ec != std::errc{} || !std::isfinite(v))
      throw ExpressionError(start, "number '" + token + "' is out of range");
    return build_.number(v);
  }

  int name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string word = text_.substr(start, pos_ - start);
    static const std::array<std::pair<const char*, Op>, 7> functions{{{"sin", Op::Sin},
                                                                      {"cos", Op::Cos},
                                                                      {"tan", Op::Tan},
                                                                      {"exp", Op::Exp},
                                                                      {"log", Op::Log},
                                                                      {"sqrt", Op::Sqrt},
                                                                      {"abs", Op::Abs}}};
    for (const auto& [fname, op] : functions) {
      if (word != fname) continue;
      skip_space();
      if (!accept('('))
        throw ExpressionError(pos_, "function '" + word + "' needs its argument in parentheses");
      const std::size_t open = pos_ - 1;
      const int argument = expression();
      close(open);
      return build_.unary(op, argument);
    }
    int node = -1;
    for (std::size_t v = 0; v < kVariableNames.size(); ++v)
      if (word == kVariableNames[v]) node = build_.variable(static_cast<Expression::Variable>(v));
    if (word == "pi") node = build_.number(std::numbers::pi);
    if (node < 0)
      throw ExpressionError(start, "unknown name '" + word +
                                       "' (variables: x, y, z, t; constant: pi; functions: sin, "
                                       "cos, tan, exp, log, sqrt, abs)");
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == '(')
      throw ExpressionError(pos_, "'" + word + "' is not a function");
    return node;
  }

  void close(std::size_t open) {
    skip_space();
    if (!accept(')'))
      throw ExpressionError(pos_, "expected ')' to close the '(' at character " +
                                      std::to_string(open + 1) +
                                      (pos_ < text_.size() ? ", found " + found() : ""));
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  std::string found() const { return "'" + std::string(1, text_[pos_]) + "'"; }

  const std::string& text_;
  ExpressionBuilder build_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

// ---- Expression ---------------------------------------------------------------------------

Expression::Expression() : text_("0") {
  ExpressionBuilder(nodes_).number(0.0);
  compile();
}

Expression Expression::constant(double value) {
  Expression e;
  e.nodes_.clear();
  ExpressionBuilder(e.nodes_).number(value);
  e.text_ = number_text(value);
  e.compile();
  return e;
}

Expression Expression::parse(const std::string& text) {
  if (text.size() > kMaxLength)
    throw ExpressionError(kMaxLength, "the formula has " + std::to_string(text.size()) +
                                          " characters, more than the limit of " +
                                          std::to_string(kMaxLength));
  Expression e;
  e.nodes_.clear();
  const int root = ExpressionParser(text, e.nodes_).parse();
  // The root must be the last node (simplification may return an earlier one).
  if (root != static_cast<int>(e.nodes_.size()) - 1) e.nodes_.push_back(e.nodes_[root]);
  e.text_ = text;
  e.compile();
  return e;
}

Expression Expression::derivative(Variable v) const {
  Expression d;
  d.nodes_ = nodes_;
  const int root = ExpressionBuilder(d.nodes_).derivative(static_cast<int>(nodes_.size()) - 1, v);
  if (root != static_cast<int>(d.nodes_.size()) - 1) d.nodes_.push_back(d.nodes_[root]);
  d.text_ = std::string("d/d") + kVariableNames[static_cast<std::size_t>(v)] + "(" + text_ + ")";
  d.compile();
  return d;
}

void Expression::compile() {
  // One instruction per node reachable from the root, in index order (children before
  // parents); operands are earlier instructions. A node shared by several parents (as after
  // differentiation) is computed once. No recursion: any depth compiles.
  const int root = static_cast<int>(nodes_.size()) - 1;
  const std::vector<char> used = ExpressionBuilder::reachable(nodes_, root);
  std::vector<std::int32_t> slot(nodes_.size(), -1);
  program_.clear();
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    const Node& n = nodes_[i];
    slot[i] = static_cast<std::int32_t>(program_.size());
    program_.push_back({n.op, n.var, n.value, n.a >= 0 ? slot[static_cast<std::size_t>(n.a)] : -1,
                        n.b >= 0 ? slot[static_cast<std::size_t>(n.b)] : -1});
  }
}

double Expression::operator()(double x, double y, double z, double t) const {
  if (program_.size() == 1 && program_[0].op == Op::Number) return program_[0].value;
  constexpr std::size_t kLocal = 64;
  std::array<double, kLocal> local{};
  std::vector<double> heap;
  double* r = local.data();
  if (program_.size() > kLocal) {
    heap.resize(program_.size());
    r = heap.data();
  }
  const double vars[4] = {x, y, z, t};
  for (std::size_t k = 0; k < program_.size(); ++k) {
    const Instruction& in = program_[k];
    switch (in.op) {
      case Op::Number:
        r[k] = in.value;
        break;
      case Op::Var:
        r[k] = vars[static_cast<std::size_t>(in.var)];
        break;
      default:
        r[k] = ExpressionBuilder::apply(in.op, r[in.a], in.b >= 0 ? r[in.b] : 0.0);
        break;
    }
  }
  return r[program_.size() - 1];
}

bool Expression::depends_on(Variable v) const {
  for (const Instruction& in : program_)
    if (in.op == Op::Var && in.var == v) return true;
  return false;
}

bool Expression::is_constant() const { return nodes_.back().op == Op::Number; }

bool Expression::is_zero() const { return is_constant() && nodes_.back().value == 0.0; }

std::string Expression::to_string() const {
  // Post-order with an explicit stack (no recursion, any depth): a node's text is built once
  // both children's texts are on the `done` stack.
  std::vector<std::string> done;
  std::vector<std::pair<int, bool>> todo{{static_cast<int>(nodes_.size()) - 1, false}};
  while (!todo.empty()) {
    const auto [i, children_done] = todo.back();
    todo.pop_back();
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    if (!children_done && n.a >= 0) {
      todo.push_back({i, true});
      if (n.b >= 0) todo.push_back({n.b, false});
      todo.push_back({n.a, false});
      continue;
    }
    switch (n.op) {
      case Op::Number:
        done.push_back(number_text(n.value));
        break;
      case Op::Var:
        done.push_back(kVariableNames[static_cast<std::size_t>(n.var)]);
        break;
      case Op::Neg:
        done.back() = "(-" + done.back() + ")";
        break;
      case Op::Add:
      case Op::Sub:
      case Op::Mul:
      case Op::Div:
      case Op::Pow: {
        static const char symbols[] = {'+', '-', '*', '/', '^'};
        const char symbol = symbols[static_cast<int>(n.op) - static_cast<int>(Op::Add)];
        std::string right = std::move(done.back());
        done.pop_back();
        done.back() = "(" + done.back() + " " + symbol + " " + right + ")";
        break;
      }
      default: {
        static const char* const names[] = {"sin", "cos",  "tan", "exp",
                                            "log", "sqrt", "abs", "sign"};
        done.back() = std::string(names[static_cast<int>(n.op) - static_cast<int>(Op::Sin)]) + "(" +
                      done.back() + ")";
      }
    }
  }
  return done.back();
}

}  // namespace biphasic
