// Internal plumbing shared by the sparse direct solvers: a C++ object with setup/solve behind
// SUNDIALS' SUNLinearSolver operations (type DIRECT), which count and time the work.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <chrono>
#include <memory>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic::detail {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

class DirectSolver {
 public:
  explicit DirectSolver(LinearSolverStats* stats) : stats_(stats) {}
  virtual ~DirectSolver() = default;
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  /// Numeric factorisation of the CSC matrix A (symbolic analysis on the first call, recorded
  /// in the stats); returns a SUNLS_* flag.
  virtual int setup(SUNMatrix A) = 0;
  /// x = A⁻¹ b with the current factors (x and b may be the same vector); SUNLS_* flag.
  virtual int solve(SUNMatrix A, N_Vector x, N_Vector b) = 0;

  LinearSolverStats& stats() { return *stats_; }
  int last_flag = 0;

 private:
  LinearSolverStats* stats_;
};

/// The SUNLinearSolver that owns and forwards to `solver`.
LinearSolverPtr wrap_direct_solver(std::unique_ptr<DirectSolver> solver, SUNContext ctx);

}  // namespace biphasic::detail
