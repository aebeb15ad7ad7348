// UMFPACK (SuiteSparse, multifrontal LU with BLAS-3 kernels) as a SUNLinearSolver: symbolic
// analysis once per pattern, a numeric factorisation at each setup.
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <umfpack.h>

#include <chrono>
#include <utility>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct UmfContent {
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  void* symbolic = nullptr;
  void* numeric = nullptr;
  std::vector<double> rhs;
  LinearSolverStats* stats = nullptr;
  FillOrder order;  ///< caller's column pre-order (empty: UMFPACK orders)
  int last_flag = 0;
};

UmfContent* content(SUNLinearSolver S) { return static_cast<UmfContent*>(S->content); }
int set_flag(UmfContent* c, int flag) {
  c->last_flag = flag;
  return flag;
}

SUNLinearSolver_Type umf_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID umf_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int umf_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

int umf_setup(SUNLinearSolver S, SUNMatrix A) {
  UmfContent* c = content(S);
  const auto n = static_cast<SuiteSparse_long>(SUNSparseMatrix_Columns(A));
  const auto* Ap = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexPointers(A));
  const auto* Ai = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexValues(A));
  const double* Ax = SUNSparseMatrix_Data(A);
  if (!c->symbolic) {
    const auto t0 = Clock::now();
    std::vector<SuiteSparse_long> Q(c->order.begin(), c->order.end());
    const int status = static_cast<int>(umfpack_dl_qsymbolic(
        n, n, Ap, Ai, Ax, Q.empty() ? nullptr : Q.data(), &c->symbolic, c->control, c->info));
    c->stats->analysis_seconds += seconds_since(t0);
    ++c->stats->analyses;
    if (status != UMFPACK_OK) return set_flag(c, SUNLS_PACKAGE_FAIL_UNREC);
  }
  if (c->numeric) umfpack_dl_free_numeric(&c->numeric);
  const auto t0 = Clock::now();
  const int status = static_cast<int>(
      umfpack_dl_numeric(Ap, Ai, Ax, c->symbolic, &c->numeric, c->control, c->info));
  c->stats->factor_seconds += seconds_since(t0);
  ++c->stats->factorizations;
  if (status == UMFPACK_WARNING_singular_matrix) return set_flag(c, SUNLS_LUFACT_FAIL);
  if (status != UMFPACK_OK) return set_flag(c, SUNLS_PACKAGE_FAIL_UNREC);
  c->stats->fill = (c->info[UMFPACK_LNZ] + c->info[UMFPACK_UNZ]) / static_cast<double>(Ap[n]);
  return set_flag(c, SUNLS_SUCCESS);
}

int umf_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  UmfContent* c = content(S);
  const auto t0 = Clock::now();
  const auto* Ap = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexPointers(A));
  const auto* Ai = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexValues(A));
  // b and x may alias (SUNDIALS allows it): solve from a copy of the right-hand side.
  const auto n = static_cast<std::size_t>(SUNSparseMatrix_Columns(A));
  c->rhs.assign(N_VGetArrayPointer(b), N_VGetArrayPointer(b) + n);
  const int status = static_cast<int>(umfpack_dl_solve(UMFPACK_A, Ap, Ai, SUNSparseMatrix_Data(A),
                                                       N_VGetArrayPointer(x), c->rhs.data(),
                                                       c->numeric, c->control, c->info));
  c->stats->solve_seconds += seconds_since(t0);
  ++c->stats->solves;
  return set_flag(c, status == UMFPACK_OK ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC);
}

sunindextype umf_lastflag(SUNLinearSolver S) { return content(S)->last_flag; }

int umf_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  if (UmfContent* c = content(S)) {
    if (c->numeric) umfpack_dl_free_numeric(&c->numeric);
    if (c->symbolic) umfpack_dl_free_symbolic(&c->symbolic);
    delete c;
    S->content = nullptr;
  }
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolverPtr make_umfpack_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                    FillOrder order) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  auto* c = new UmfContent;
  c->stats = stats;
  c->order = std::move(order);
  umfpack_dl_defaults(c->control);
  // The P2/P1 matrix is structurally symmetric with a mostly symmetric numerical pattern:
  // order A + Aᵀ and prefer diagonal pivots.
  c->control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
  // No iterative refinement: each refinement step costs a residual and another solve, and
  // the Newton iteration around the solver corrects the same error.
  c->control[UMFPACK_IRSTEP] = 0;
  switch (ordering) {
    case Ordering::Amd:
      c->control[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
      break;
    case Ordering::Colamd:
      c->control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_UNSYMMETRIC;
      c->control[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;  // COLAMD under the unsymmetric strategy
      break;
    case Ordering::Metis:
      c->control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
      break;
  }
  S->content = c;
  S->ops->gettype = umf_gettype;
  S->ops->getid = umf_getid;
  S->ops->initialize = umf_initialize;
  S->ops->setup = umf_setup;
  S->ops->solve = umf_solve;
  S->ops->lastflag = umf_lastflag;
  S->ops->free = umf_free;
  return LinearSolverPtr(S);
}

}  // namespace biphasic
