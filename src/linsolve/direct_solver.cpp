#include "direct_solver.hpp"

namespace biphasic::detail {

namespace {

DirectSolver* solver_of(SUNLinearSolver S) { return static_cast<DirectSolver*>(S->content); }

SUNLinearSolver_Type op_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID op_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
/// Re-initialisation (every KINSol call, IDAReInit) keeps the analysis and the factors.
int op_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

int op_setup(SUNLinearSolver S, SUNMatrix A) {
  DirectSolver* s = solver_of(S);
  return s->last_flag = s->setup(A);
}

int op_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  DirectSolver* s = solver_of(S);
  const auto t0 = Clock::now();
  s->last_flag = s->solve(A, x, b);
  s->stats().solve_seconds += seconds_since(t0);
  ++s->stats().solves;
  return s->last_flag;
}

sunindextype op_lastflag(SUNLinearSolver S) { return solver_of(S)->last_flag; }

int op_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete solver_of(S);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolverPtr wrap_direct_solver(std::unique_ptr<DirectSolver> solver, SUNContext ctx) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::runtime_error("SUNLinSolNewEmpty failed");
  S->content = solver.release();
  S->ops->gettype = op_gettype;
  S->ops->getid = op_getid;
  S->ops->initialize = op_initialize;
  S->ops->setup = op_setup;
  S->ops->solve = op_solve;
  S->ops->lastflag = op_lastflag;
  S->ops->free = op_free;
  return LinearSolverPtr(S);
}

}  // namespace biphasic::detail
