#include "direct_solver.hpp"

namespace biphasic::detail {

namespace {

DirectSolver* solver_of(SUNLinearSolver S) { return static_cast<DirectSolver*>(S->content); }

SUNLinearSolver_Type op_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID op_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
/// Re-initialisation (every KINSol call, IDAReInit) keeps the analysis and the factors.
int op_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

/// Runs a set-up or solve of `s` inside SUNDIALS' C frames: an exception is stored in the
/// stats (last_error) and reported as an unrecoverable package failure.
template <class Call>
int guarded(DirectSolver* s, Call&& call) noexcept {
  s->stats().last_error.clear();
  try {
    return s->last_flag = call();
  } catch (const std::exception& e) {
    s->stats().last_error = e.what();
  } catch (...) {
    s->stats().last_error = "an exception of unknown type";
  }
  return s->last_flag = SUNLS_PACKAGE_FAIL_UNREC;
}

int op_setup(SUNLinearSolver S, SUNMatrix A) {
  DirectSolver* s = solver_of(S);
  return guarded(s, [&] { return s->setup(A); });
}

int op_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  DirectSolver* s = solver_of(S);
  const auto t0 = Clock::now();
  const int flag = guarded(s, [&] { return s->solve(A, x, b); });
  s->stats().solve_seconds += seconds_since(t0);
  ++s->stats().solves;
  return flag;
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
