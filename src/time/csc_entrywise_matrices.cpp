// The consistent start's matrices in one process: value arrays of the system's CSC pattern,
// factorised by the configured sparse direct solver.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "biphasic/time/semidiscrete_system.hpp"
#include "biphasic/time/solver_messages.hpp"

namespace biphasic {

namespace {

class CscEntrywiseMatrices final : public EntrywiseMatrices {
 public:
  explicit CscEntrywiseMatrices(SemidiscreteSystem& problem)
      : problem_(problem),
        pattern_(problem.pattern()),
        a0_(static_cast<std::size_t>(pattern_.nnz())),
        r_(a0_.size()) {
    if (SUNContext_Create(nullptr, &ctx_) != 0)
      throw std::runtime_error("SUNContext_Create failed");
  }
  ~CscEntrywiseMatrices() override {
    if (x_) N_VDestroy(x_);
    if (b_) N_VDestroy(b_);
    ls_.reset();
    if (M_) SUNMatDestroy(M_);
    SUNContext_Free(&ctx_);
  }

  void evaluate(double t, const double* y, const double* ydot) override {
    problem_.jacobian(t, y, ydot, 0.0, a0_.data(), r_.data());
  }
  double a0_diagonal(Index i) const override {
    return a0_[static_cast<std::size_t>(pattern_.find(i, i))];
  }
  void build(int slot, const Rule& rule) override {
    std::vector<double>& m = slots_.at(static_cast<std::size_t>(slot));
    m.resize(a0_.size());
    const auto& cp = pattern_.colptr();
    const auto& ri = pattern_.rowind();
    const std::vector<char>& fixed = problem_.constrained();
    const Index n = pattern_.size(), nu = problem_.num_u();
    for (Index j = 0; j < n; ++j)
      for (Index q = cp[j]; q < cp[j + 1]; ++q) {
        const Index i = ri[q];
        m[q] = rule(i < nu, j < nu, fixed[i] != 0, a0_[q], r_[q]);
      }
  }
  void residual(int slot, const double* b, const double* x, double* r) const override {
    const std::vector<double>& m = slots_.at(static_cast<std::size_t>(slot));
    const auto& cp = pattern_.colptr();
    const auto& ri = pattern_.rowind();
    const Index n = pattern_.size();
    std::copy(b, b + n, r);
    for (Index j = 0; j < n; ++j)
      for (Index q = cp[j]; q < cp[j + 1]; ++q) r[ri[q]] -= m[q] * x[j];
  }
  void factorise(int slot, const LinearSolverConfig& config, LinearSolverStats* stats) override {
    const std::vector<double>& m = slots_.at(static_cast<std::size_t>(slot));
    M_ = pattern_.new_matrix(ctx_);
    std::copy(m.begin(), m.end(), SUNSparseMatrix_Data(M_));
    // A few solves with no Newton iteration after them: double-precision factors. The
    // regularised matrix is GLS-dominated (a step of ε ≪ the GLS time), where the iterative
    // solver's multigrid fails: a direct factorisation then, once per start.
    LinearSolverConfig exact = config;
    exact.precision = FactorPrecision::Double;
    if (exact.type == LinearSolverType::Iterative) {
      exact.type = LinearSolverType::Mumps;
      exact.ordering = Ordering::Metis;
    }
    LinearSolverStats* counted = stats ? stats : &own_stats_;
    ls_ = make_linear_solver(exact, ctx_, counted, fill_order(exact, pattern_));
    x_ = N_VNew_Serial(pattern_.size(), ctx_);
    b_ = N_VNew_Serial(pattern_.size(), ctx_);
    const int flag = SUNLinSolSetup(ls_.get(), M_);
    if (flag != 0)
      throw std::runtime_error("the consistent start's regularised system could not be " +
                               std::string("factorised: ") + linear_solver_flag_message(flag) +
                               (counted->last_error.empty() ? "" : ": " + counted->last_error));
  }
  void solve(const double* b, double* x) override {
    std::copy(b, b + pattern_.size(), N_VGetArrayPointer(b_));
    const int flag = SUNLinSolSolve(ls_.get(), M_, x_, b_, 0.0);
    if (flag != 0)
      throw std::runtime_error("the consistent start's regularised system could not be solved: " +
                               linear_solver_flag_message(flag));
    std::copy_n(N_VGetArrayPointer(x_), pattern_.size(), x);
  }

 private:
  SemidiscreteSystem& problem_;
  const SparsityPattern& pattern_;
  std::vector<double> a0_, r_;
  std::array<std::vector<double>, 3> slots_;
  SUNContext ctx_ = nullptr;
  SUNMatrix M_ = nullptr;
  LinearSolverStats own_stats_;
  LinearSolverPtr ls_;
  N_Vector x_ = nullptr, b_ = nullptr;
};

}  // namespace

std::unique_ptr<EntrywiseMatrices> SemidiscreteSystem::entrywise_matrices() {
  return std::make_unique<CscEntrywiseMatrices>(*this);
}

}  // namespace biphasic
