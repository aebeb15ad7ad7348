// The matrices of the consistent start (time/consistent_start.cpp), each built entry by entry
// from dF/dy and dF/dẏ at one state, in the system's own layout: the CSC pattern in one
// process, PETSc matrices on several (parallel/distributed_system.hpp).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

class EntrywiseMatrices {
 public:
  virtual ~EntrywiseMatrices() = default;
  /// A0 = dF/dy (c_j = 0) and R = dF/dẏ at (t, y, ẏ), arrays of the system's size().
  virtual void evaluate(double t, const double* y, const double* ydot) = 0;
  /// A0's diagonal entry in row i (a Dirichlet row's scale s).
  virtual double a0_diagonal(Index i) const = 0;
  /// The value of an entry from its row's and column's kind and the entries of A0 and R.
  using Rule = std::function<double(bool u_row, bool u_col, bool fixed_row, double a0, double r)>;
  /// Matrix `slot` (0, 1 or 2) := `rule` applied to every entry of the pattern.
  virtual void build(int slot, const Rule& rule) = 0;
  /// r = b − matrix(slot) x.
  virtual void residual(int slot, const double* b, const double* x, double* r) const = 0;
  /// Factorises matrix(slot) with `config`'s solver (a direct solver in double precision) for
  /// solve(); throws std::runtime_error naming the cause.
  virtual void factorise(int slot, const LinearSolverConfig& config, LinearSolverStats* stats) = 0;
  /// x = matrix⁻¹ b with the last factorisation; throws std::runtime_error on failure.
  virtual void solve(const double* b, double* x) = 0;
};

}  // namespace biphasic
