#include "biphasic/parallel/petsc_linear_solver.hpp"

#include <nvector/nvector_parallel.h>

#include <chrono>
#include <string>

#include "biphasic/parallel/petsc_check.hpp"

namespace biphasic {

SUNMatrix wrap_petsc_matrix(Mat A, SUNContext ctx) {
  SUNMatrix M = SUNMatNewEmpty(ctx);
  if (!M) throw std::runtime_error("SUNMatNewEmpty failed");
  M->content = A;
  M->ops->getid = [](SUNMatrix) { return SUNMATRIX_CUSTOM; };
  M->ops->zero = [](SUNMatrix) { return 0; };
  M->ops->destroy = [](SUNMatrix S) {
    if (!S) return;
    Mat a = static_cast<Mat>(S->content);
    if (a) MatDestroy(&a);
    S->content = nullptr;
    SUNMatFreeEmpty(S);
  };
  return M;
}

Mat petsc_matrix(SUNMatrix M) { return static_cast<Mat>(M->content); }

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct KspContent {
  MPI_Comm comm;
  KSP ksp = nullptr;
  Vec x = nullptr, b = nullptr;  ///< shells over the N_Vectors' local arrays
  LinearSolverStats* stats = nullptr;
  bool configured = false;
  int last_flag = 0;
};

KspContent* content(SUNLinearSolver S) { return static_cast<KspContent*>(S->content); }

/// A vector without storage of its own, laid out as `v` (an N_Vector_Parallel).
Vec shell_like(MPI_Comm comm, N_Vector v) {
  Vec w = nullptr;
  petsc_check(VecCreateMPIWithArray(comm, 1, static_cast<PetscInt>(NV_LOCLENGTH_P(v)),
                                    static_cast<PetscInt>(NV_GLOBLENGTH_P(v)), nullptr, &w),
              "VecCreateMPIWithArray");
  return w;
}

int ksp_setup(SUNLinearSolver S, SUNMatrix A) {
  KspContent& c = *content(S);
  try {
    c.stats->last_error.clear();
    const auto t0 = Clock::now();
    Mat J = petsc_matrix(A);
    petsc_check(KSPSetOperators(c.ksp, J, J), "KSPSetOperators");
    if (!c.configured) {
      PC pc = nullptr;
      petsc_check(KSPSetType(c.ksp, KSPPREONLY), "KSPSetType");
      petsc_check(KSPGetPC(c.ksp, &pc), "KSPGetPC");
      petsc_check(PCSetType(pc, PCLU), "PCSetType");
      petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
      petsc_check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
      Mat F = nullptr;
      petsc_check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
      petsc_check(MatMumpsSetIcntl(F, 7, 4), "MatMumpsSetIcntl(7: PORD)");
      petsc_check(KSPSetOptionsPrefix(c.ksp, "biphasic_"), "KSPSetOptionsPrefix");
      petsc_check(KSPSetFromOptions(c.ksp), "KSPSetFromOptions");
      c.configured = true;
      ++c.stats->analyses;
    }
    petsc_check(KSPSetUp(c.ksp), "KSPSetUp (factorisation)");
    ++c.stats->factorizations;
    c.stats->factor_seconds += seconds_since(t0);
    c.last_flag = 0;
  } catch (const std::exception& e) {
    c.stats->last_error = e.what();
    c.last_flag = SUNLS_PSET_FAIL_UNREC;
  }
  return c.last_flag;
}

int ksp_solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  KspContent& c = *content(S);
  try {
    const auto t0 = Clock::now();
    if (!c.x) {
      c.x = shell_like(c.comm, x);
      c.b = shell_like(c.comm, b);
    }
    petsc_check(VecPlaceArray(c.x, N_VGetArrayPointer(x)), "VecPlaceArray");
    petsc_check(VecPlaceArray(c.b, N_VGetArrayPointer(b)), "VecPlaceArray");
    const PetscErrorCode code = KSPSolve(c.ksp, c.b, c.x);
    VecResetArray(c.x);
    VecResetArray(c.b);
    petsc_check(code, "KSPSolve");
    KSPConvergedReason reason;
    petsc_check(KSPGetConvergedReason(c.ksp, &reason), "KSPGetConvergedReason");
    if (reason < 0)
      throw std::runtime_error("the PETSc solve did not converge (KSPConvergedReason " +
                               std::to_string(static_cast<int>(reason)) + ")");
    ++c.stats->solves;
    c.stats->solve_seconds += seconds_since(t0);
    c.last_flag = 0;
  } catch (const std::exception& e) {
    c.stats->last_error = e.what();
    c.last_flag = SUNLS_PACKAGE_FAIL_UNREC;
  }
  return c.last_flag;
}

}  // namespace

LinearSolverPtr make_petsc_direct_solver(MPI_Comm comm, SUNContext ctx, LinearSolverStats* stats) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::runtime_error("SUNLinSolNewEmpty failed");
  auto* c = new KspContent{};
  c->comm = comm;
  c->stats = stats;
  S->content = c;
  S->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  S->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  S->ops->initialize = [](SUNLinearSolver) { return 0; };
  S->ops->setup = ksp_setup;
  S->ops->solve = ksp_solve;
  S->ops->lastflag = [](SUNLinearSolver s) -> sunindextype { return content(s)->last_flag; };
  S->ops->free = [](SUNLinearSolver s) -> int {
    if (!s) return 0;
    if (KspContent* k = content(s)) {
      if (k->ksp) KSPDestroy(&k->ksp);
      if (k->x) VecDestroy(&k->x);
      if (k->b) VecDestroy(&k->b);
      delete k;
    }
    s->content = nullptr;
    SUNLinSolFreeEmpty(s);
    return 0;
  };
  LinearSolverPtr owner(S);
  petsc_check(KSPCreate(comm, &c->ksp), "KSPCreate");
  return owner;
}

}  // namespace biphasic
