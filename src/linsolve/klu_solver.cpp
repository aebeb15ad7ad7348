// KLU as a SUNLinearSolver: analysis once, klu_refactor while the pivot order stays good.
#include <klu.h>
#include <metis.h>
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
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

/// Fill-reducing nested-dissection ordering of A + Aᵀ by METIS (KLU's user_order hook).
/// Perm[k] = original index of the k-th pivot. Returns 0 on failure.
SuiteSparse_long metis_order(SuiteSparse_long n, SuiteSparse_long* Ap, SuiteSparse_long* Ai,
                             SuiteSparse_long* Perm, klu_l_common* /*common*/) {
  // Symmetrised adjacency without the diagonal.
  std::vector<std::vector<idx_t>> adj(static_cast<std::size_t>(n));
  for (SuiteSparse_long j = 0; j < n; ++j)
    for (SuiteSparse_long q = Ap[j]; q < Ap[j + 1]; ++q) {
      const SuiteSparse_long i = Ai[q];
      if (i == j) continue;
      adj[i].push_back(static_cast<idx_t>(j));
      adj[j].push_back(static_cast<idx_t>(i));
    }
  std::vector<idx_t> xadj(static_cast<std::size_t>(n) + 1, 0), adjncy;
  for (SuiteSparse_long i = 0; i < n; ++i) {
    auto& list = adj[i];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    xadj[i + 1] = xadj[i] + static_cast<idx_t>(list.size());
    adjncy.insert(adjncy.end(), list.begin(), list.end());
    std::vector<idx_t>().swap(list);
  }
  if (n == 1) {
    Perm[0] = 0;
    return 1;
  }
  idx_t nv = static_cast<idx_t>(n);
  std::vector<idx_t> perm(static_cast<std::size_t>(n)), iperm(static_cast<std::size_t>(n));
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  if (METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data()) !=
      METIS_OK)
    return 0;
  for (SuiteSparse_long k = 0; k < n; ++k) Perm[k] = perm[k];
  return 1;
}

struct KluContent {
  klu_l_common common{};
  klu_l_symbolic* symbolic = nullptr;
  klu_l_numeric* numeric = nullptr;
  LinearSolverStats* stats = nullptr;
  FillOrder order;  ///< caller's pivot order (empty: KLU orders)
  int last_flag = 0;
};

KluContent* content(SUNLinearSolver S) { return static_cast<KluContent*>(S->content); }
int set_flag(KluContent* c, int flag) {
  c->last_flag = flag;
  return flag;
}

SUNLinearSolver_Type klu_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID klu_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int klu_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

int klu_setup(SUNLinearSolver S, SUNMatrix A) {
  KluContent* c = content(S);
  const auto n = static_cast<SuiteSparse_long>(SUNSparseMatrix_Columns(A));
  auto* Ap = reinterpret_cast<SuiteSparse_long*>(SUNSparseMatrix_IndexPointers(A));
  auto* Ai = reinterpret_cast<SuiteSparse_long*>(SUNSparseMatrix_IndexValues(A));
  double* Ax = SUNSparseMatrix_Data(A);
  if (!c->symbolic) {
    const auto t0 = Clock::now();
    if (c->order.empty()) {
      c->symbolic = klu_l_analyze(n, Ap, Ai, &c->common);
    } else {
      std::vector<SuiteSparse_long> P(c->order.begin(), c->order.end());
      c->symbolic = klu_l_analyze_given(n, Ap, Ai, P.data(), P.data(), &c->common);
    }
    c->stats->analysis_seconds += seconds_since(t0);
    ++c->stats->analyses;
    if (!c->symbolic) return set_flag(c, SUNLS_PACKAGE_FAIL_UNREC);
  }
  const auto t0 = Clock::now();
  bool fresh = true;
  if (c->numeric) {
    // Same pivot order; fall back to a pivoting factorisation when it degrades.
    if (klu_l_refactor(Ap, Ai, Ax, c->symbolic, c->numeric, &c->common) &&
        klu_l_rcond(c->symbolic, c->numeric, &c->common) && c->common.rcond > 1e-12) {
      fresh = false;
      ++c->stats->refactorizations;
    } else {
      klu_l_free_numeric(&c->numeric, &c->common);
    }
  }
  if (fresh) c->numeric = klu_l_factor(Ap, Ai, Ax, c->symbolic, &c->common);
  c->stats->factor_seconds += seconds_since(t0);
  ++c->stats->factorizations;
  if (!c->numeric) return set_flag(c, SUNLS_LUFACT_FAIL);
  const double nnzA = static_cast<double>(Ap[n]);
  c->stats->fill =
      static_cast<double>(c->numeric->lnz + c->numeric->unz + c->numeric->nzoff) / nnzA;
  return set_flag(c, SUNLS_SUCCESS);
}

int klu_solve_op(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  KluContent* c = content(S);
  const auto t0 = Clock::now();
  N_VScale(1.0, b, x);
  const auto n = static_cast<SuiteSparse_long>(SUNSparseMatrix_Columns(A));
  const int ok = static_cast<int>(
      klu_l_solve(c->symbolic, c->numeric, n, 1, N_VGetArrayPointer(x), &c->common));
  c->stats->solve_seconds += seconds_since(t0);
  ++c->stats->solves;
  return set_flag(c, ok ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC);
}

sunindextype klu_lastflag(SUNLinearSolver S) { return content(S)->last_flag; }

int klu_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  if (KluContent* c = content(S)) {
    if (c->numeric) klu_l_free_numeric(&c->numeric, &c->common);
    if (c->symbolic) klu_l_free_symbolic(&c->symbolic, &c->common);
    delete c;
    S->content = nullptr;
  }
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolverPtr make_klu_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                FillOrder order) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  auto* c = new KluContent;
  c->stats = stats;
  c->order = std::move(order);
  klu_l_defaults(&c->common);
  switch (ordering) {
    case Ordering::Amd:
      c->common.ordering = 0;
      break;
    case Ordering::Colamd:
      c->common.ordering = 1;
      break;
    case Ordering::Metis:
      c->common.ordering = 3;
      c->common.user_order = metis_order;
      break;
  }
  S->content = c;
  S->ops->gettype = klu_gettype;
  S->ops->getid = klu_getid;
  S->ops->initialize = klu_initialize;
  S->ops->setup = klu_setup;
  S->ops->solve = klu_solve_op;
  S->ops->lastflag = klu_lastflag;
  S->ops->free = klu_free;
  return LinearSolverPtr(S);
}

}  // namespace biphasic
