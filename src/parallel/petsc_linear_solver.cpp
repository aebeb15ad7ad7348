#include "biphasic/parallel/petsc_linear_solver.hpp"

#include <nvector/nvector_parallel.h>

#include <algorithm>
#include <chrono>
#include <functional>
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
  /// Sets the KSP and PC up on the first set-up (the operators are known then).
  std::function<void(KSP)> configure;
};

/// LU by the parallel MUMPS, ordering PORD.
void configure_direct(KSP ksp) {
  PC pc = nullptr;
  petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCLU), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  petsc_check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
  Mat F = nullptr;
  petsc_check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
  petsc_check(MatMumpsSetIcntl(F, 7, 4), "MatMumpsSetIcntl(7: PORD)");
}

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
      // The prefix first: the splits take theirs from it when they are made.
      petsc_check(KSPSetOptionsPrefix(c.ksp, "biphasic_"), "KSPSetOptionsPrefix");
      c.configure(c.ksp);
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
    PetscInt its = 0;
    petsc_check(KSPGetIterationNumber(c.ksp, &its), "KSPGetIterationNumber");
    c.stats->krylov_iterations += its;
    c.stats->max_krylov_iterations = std::max<long>(c.stats->max_krylov_iterations, its);
    if (reason < 0) {
      // Recoverable: a new Jacobian or a shorter step may converge.
      c.last_flag = SUNLS_CONV_FAIL;
      return c.last_flag;
    }
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

namespace {

LinearSolverPtr make_ksp_solver(MPI_Comm comm, SUNContext ctx, LinearSolverStats* stats,
                                std::function<void(KSP)> configure) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::runtime_error("SUNLinSolNewEmpty failed");
  auto* c = new KspContent{};
  c->comm = comm;
  c->stats = stats;
  c->configure = std::move(configure);
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

}  // namespace

LinearSolverPtr make_petsc_direct_solver(MPI_Comm comm, SUNContext ctx, LinearSolverStats* stats) {
  return make_ksp_solver(comm, ctx, stats, configure_direct);
}

LinearSolverPtr make_petsc_fieldsplit_solver(MPI_Comm comm, const KrylovConfig& config,
                                             FieldSplitLayout layout, SUNContext ctx,
                                             LinearSolverStats* stats) {
  auto configure = [comm, config, layout = std::move(layout)](KSP ksp) {
    petsc_check(KSPSetType(ksp, KSPFGMRES), "KSPSetType");
    petsc_check(KSPGMRESSetRestart(ksp, config.restart), "KSPGMRESSetRestart");
    petsc_check(KSPSetTolerances(ksp, config.rtol, 0.0, PETSC_DEFAULT, config.max_iterations),
                "KSPSetTolerances");
    petsc_check(KSPSetPCSide(ksp, PC_RIGHT), "KSPSetPCSide");
    PC pc = nullptr;
    petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
    petsc_check(PCSetType(pc, PCFIELDSPLIT), "PCSetType");
    IS u = nullptr, p = nullptr;
    const auto owned_u = static_cast<PetscInt>(layout.owned_u);
    const auto owned_p = static_cast<PetscInt>(layout.owned - layout.owned_u);
    const auto first = static_cast<PetscInt>(layout.first_owned);
    petsc_check(ISCreateStride(comm, owned_u, first, 1, &u), "ISCreateStride");
    petsc_check(ISSetBlockSize(u, 3), "ISSetBlockSize");
    petsc_check(ISCreateStride(comm, owned_p, first + owned_u, 1, &p), "ISCreateStride");
    // The rigid-body modes of the owned nodes, picked up by the displacement split's matrix.
    Vec xyz = nullptr;
    petsc_check(VecCreateMPI(comm, owned_u, PETSC_DETERMINE, &xyz), "VecCreateMPI");
    petsc_check(VecSetBlockSize(xyz, 3), "VecSetBlockSize");
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(xyz, &a), "VecGetArray");
    std::copy(layout.coordinates.begin(), layout.coordinates.end(), a);
    VecRestoreArray(xyz, &a);
    MatNullSpace modes = nullptr;
    petsc_check(MatNullSpaceCreateRigidBody(xyz, &modes), "MatNullSpaceCreateRigidBody");
    petsc_check(PetscObjectCompose(reinterpret_cast<PetscObject>(u), "nearnullspace",
                                   reinterpret_cast<PetscObject>(modes)),
                "PetscObjectCompose");
    MatNullSpaceDestroy(&modes);
    VecDestroy(&xyz);
    petsc_check(PCFieldSplitSetIS(pc, "u", u), "PCFieldSplitSetIS");
    petsc_check(PCFieldSplitSetIS(pc, "p", p), "PCFieldSplitSetIS");
    ISDestroy(&u);
    ISDestroy(&p);
    petsc_check(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR), "PCFieldSplitSetType");
    petsc_check(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER),
                "PCFieldSplitSetSchurFactType");
    petsc_check(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_SELFP, nullptr),
                "PCFieldSplitSetSchurPre");
    // Defaults of the splits, as options so that the user's options (read later) win.
    const char* defaults[][2] = {{"-biphasic_fieldsplit_u_ksp_type", "preonly"},
                                 {"-biphasic_fieldsplit_u_pc_type", "gamg"},
                                 {"-biphasic_fieldsplit_p_ksp_type", "preonly"},
                                 {"-biphasic_fieldsplit_p_pc_type", "lu"},
                                 {"-biphasic_fieldsplit_p_pc_factor_mat_solver_type", "mumps"},
                                 {"-biphasic_fieldsplit_p_mat_mumps_icntl_7", "4"}};
    for (const auto& d : defaults) {
      PetscBool set = PETSC_FALSE;
      petsc_check(PetscOptionsHasName(nullptr, nullptr, d[0], &set), "PetscOptionsHasName");
      if (!set) petsc_check(PetscOptionsSetValue(nullptr, d[0], d[1]), "PetscOptionsSetValue");
    }
  };
  return make_ksp_solver(comm, ctx, stats, configure);
}

}  // namespace biphasic
