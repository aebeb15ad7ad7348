// MUMPS (sequential build, multifrontal LU with BLAS-3 kernels) as a SUNLinearSolver:
// analysis (METIS ordering) once per pattern, a numeric factorisation at each setup.
#include <dmumps_c.h>
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <chrono>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

constexpr MUMPS_INT kUseCommWorld = -987654;

struct MumpsContent {
  DMUMPS_STRUC_C id{};
  bool analysed = false;
  bool factorised = false;
  std::vector<MUMPS_INT> irn, jcn;  ///< 1-based coordinates in CSC value order
  std::vector<MUMPS_INT> perm_in;   ///< position of each unknown in the caller's order (1-based)
  LinearSolverStats* stats = nullptr;
  int last_flag = 0;
};

MumpsContent* content(SUNLinearSolver S) { return static_cast<MumpsContent*>(S->content); }
int set_flag(MumpsContent* c, int flag) {
  c->last_flag = flag;
  return flag;
}
/// ICNTL(i) in MUMPS' 1-based numbering.
MUMPS_INT& icntl(DMUMPS_STRUC_C& id, int i) { return id.icntl[i - 1]; }
MUMPS_INT infog(const DMUMPS_STRUC_C& id, int i) { return id.infog[i - 1]; }

SUNLinearSolver_Type mumps_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID mumps_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int mumps_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

int mumps_setup(SUNLinearSolver S, SUNMatrix A) {
  MumpsContent* c = content(S);
  DMUMPS_STRUC_C& id = c->id;
  if (!c->analysed) {
    const auto n = SUNSparseMatrix_Columns(A);
    const sunindextype* Ap = SUNSparseMatrix_IndexPointers(A);
    const sunindextype* Ai = SUNSparseMatrix_IndexValues(A);
    c->irn.resize(static_cast<std::size_t>(Ap[n]));
    c->jcn.resize(c->irn.size());
    for (sunindextype j = 0; j < n; ++j)
      for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q) {
        c->irn[q] = static_cast<MUMPS_INT>(Ai[q] + 1);
        c->jcn[q] = static_cast<MUMPS_INT>(j + 1);
      }
    id.n = static_cast<MUMPS_INT>(n);
    id.nnz = static_cast<MUMPS_INT8>(Ap[n]);
    id.irn = c->irn.data();
    id.jcn = c->jcn.data();
    id.a = SUNSparseMatrix_Data(A);
    const auto t0 = Clock::now();
    id.job = 1;
    dmumps_c(&id);
    c->stats->analysis_seconds += seconds_since(t0);
    ++c->stats->analyses;
    if (infog(id, 1) < 0) return set_flag(c, SUNLS_PACKAGE_FAIL_UNREC);
    c->analysed = true;
  }
  id.a = SUNSparseMatrix_Data(A);
  const auto t0 = Clock::now();
  id.job = 2;
  dmumps_c(&id);
  c->stats->factor_seconds += seconds_since(t0);
  ++c->stats->factorizations;
  c->factorised = infog(id, 1) >= 0;
  if (!c->factorised) return set_flag(c, SUNLS_LUFACT_FAIL);
  // INFOG(29): entries in the factors (negative: millions).
  const double entries = infog(id, 29) >= 0 ? infog(id, 29) : -1e6 * infog(id, 29);
  c->stats->fill = entries / static_cast<double>(id.nnz);
  return set_flag(c, SUNLS_SUCCESS);
}

int mumps_solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  MumpsContent* c = content(S);
  DMUMPS_STRUC_C& id = c->id;
  const auto t0 = Clock::now();
  N_VScale(1.0, b, x);  // MUMPS overwrites the right-hand side with the solution
  id.rhs = N_VGetArrayPointer(x);
  id.nrhs = 1;
  id.lrhs = id.n;
  id.job = 3;
  dmumps_c(&id);
  c->stats->solve_seconds += seconds_since(t0);
  ++c->stats->solves;
  return set_flag(c, infog(id, 1) >= 0 ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC);
}

sunindextype mumps_lastflag(SUNLinearSolver S) { return content(S)->last_flag; }

int mumps_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  if (MumpsContent* c = content(S)) {
    c->id.job = -2;  // release MUMPS' memory
    dmumps_c(&c->id);
    delete c;
    S->content = nullptr;
  }
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolverPtr make_mumps_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                  FillOrder order) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  auto* c = new MumpsContent;
  c->stats = stats;
  DMUMPS_STRUC_C& id = c->id;
  id.comm_fortran = kUseCommWorld;
  id.par = 1;  // the host works
  id.sym = 0;  // unsymmetric
  id.job = -1;
  dmumps_c(&id);
  icntl(id, 1) = -1;  // no messages
  icntl(id, 2) = -1;
  icntl(id, 3) = -1;
  icntl(id, 4) = 0;
  icntl(id, 28) = 1;  // sequential analysis
  switch (ordering) {
    case Ordering::Amd:
      icntl(id, 7) = 0;
      break;
    case Ordering::Colamd:
      icntl(id, 7) = 2;  // AMF (MUMPS has no COLAMD)
      break;
    case Ordering::Metis:
      icntl(id, 7) = 5;
      break;
  }
  if (!order.empty()) {
    c->perm_in.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      c->perm_in[static_cast<std::size_t>(order[k])] = static_cast<MUMPS_INT>(k + 1);
    id.perm_in = c->perm_in.data();
    icntl(id, 7) = 1;  // the given order
  }
  icntl(id, 14) = 40;  // working-space relaxation [%]
  S->content = c;
  S->ops->gettype = mumps_gettype;
  S->ops->getid = mumps_getid;
  S->ops->initialize = mumps_initialize;
  S->ops->setup = mumps_setup;
  S->ops->solve = mumps_solve;
  S->ops->lastflag = mumps_lastflag;
  S->ops->free = mumps_free;
  return LinearSolverPtr(S);
}

}  // namespace biphasic
