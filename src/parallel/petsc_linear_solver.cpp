#include "biphasic/parallel/petsc_linear_solver.hpp"

#include <nvector/nvector_parallel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <memory>
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
  /// Before every set-up, with the new matrix (may be empty).
  std::function<void(KSP, Mat)> refresh;
  /// Once, after the first set-up, when the field split's sub-solvers exist (may be empty).
  std::function<void(KSP)> after_first_setup;
  /// After every converged solve, with its iterations (may be empty).
  std::function<void(PetscInt)> after_solve;
};

/// The user Schur preconditioner S̃ = A_pp + C of the field-split solver, rebuilt at every
/// set-up: A_pp taken from the Jacobian, C (the coupling term) assembled through COO.
struct SchurApproximation {
  MPI_Comm comm;
  std::function<void(std::vector<PressureEntry>&)> term;
  PetscInt owned_p = 0;
  IS p = nullptr;
  Mat App = nullptr, C = nullptr, Sp = nullptr;
  std::vector<PressureEntry> entries;
  std::vector<PetscScalar> values;
  ~SchurApproximation() {
    if (p) ISDestroy(&p);
    for (Mat* m : {&App, &C, &Sp})
      if (*m) MatDestroy(m);
  }

  void refresh(KSP ksp, Mat J) {
    petsc_check(MatCreateSubMatrix(J, p, p, App ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &App),
                "MatCreateSubMatrix");
    entries.clear();
    term(entries);
    if (!C) {
      petsc_check(MatCreate(comm, &C), "MatCreate");
      petsc_check(MatSetSizes(C, owned_p, owned_p, PETSC_DETERMINE, PETSC_DETERMINE),
                  "MatSetSizes");
      petsc_check(MatSetType(C, MATAIJ), "MatSetType");
      std::vector<PetscInt> rows(entries.size()), cols(entries.size());
      for (std::size_t k = 0; k < entries.size(); ++k) {
        rows[k] = static_cast<PetscInt>(entries[k].row);
        cols[k] = static_cast<PetscInt>(entries[k].col);
      }
      petsc_check(MatSetPreallocationCOO(C, static_cast<PetscCount>(entries.size()), rows.data(),
                                         cols.data()),
                  "MatSetPreallocationCOO");
    }
    values.resize(entries.size());
    for (std::size_t k = 0; k < entries.size(); ++k) values[k] = entries[k].value;
    petsc_check(MatSetValuesCOO(C, values.data(), INSERT_VALUES), "MatSetValuesCOO");
    if (!Sp) {
      petsc_check(MatDuplicate(App, MAT_COPY_VALUES, &Sp), "MatDuplicate");
      petsc_check(MatAXPY(Sp, 1.0, C, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
    } else {
      petsc_check(MatZeroEntries(Sp), "MatZeroEntries");
      petsc_check(MatAXPY(Sp, 1.0, App, SUBSET_NONZERO_PATTERN), "MatAXPY");
      petsc_check(MatAXPY(Sp, 1.0, C, SUBSET_NONZERO_PATTERN), "MatAXPY");
    }
    PC pc = nullptr;
    petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
    petsc_check(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_USER, Sp),
                "PCFieldSplitSetSchurPre");
  }
};

/// `value` as a PETSc option's text, to full precision.
std::string option_number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.17g", value);
  return text.data();
}

/// Sets each option not given by the user (so that the user's options, read later, win).
void default_options(std::initializer_list<std::array<const char*, 2>> defaults) {
  for (const auto& d : defaults) {
    PetscBool set = PETSC_FALSE;
    petsc_check(PetscOptionsHasName(nullptr, nullptr, d[0], &set), "PetscOptionsHasName");
    if (!set) petsc_check(PetscOptionsSetValue(nullptr, d[0], d[1]), "PetscOptionsSetValue");
  }
}

/// LU by SuperLU_DIST through PETSc, with its METIS column order on A + Aᵀ and no row
/// permutation. (Debian's SuperLU_DIST has no MC64,
/// whose licence forbids redistribution, and aborts when asked for it; its AWPM matching needs
/// a square process grid. The biphasic matrices have a non-zero diagonal in every row, so
/// SuperLU_DIST's static pivoting works without one.)
void configure_superlu_dist(KSP ksp) {
  PC pc = nullptr;
  petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCLU), "PCSetType");
  default_options({{"-biphasic_mat_superlu_dist_colperm", "METIS_AT_PLUS_A"},
                   {"-biphasic_mat_superlu_dist_rowperm", "NOROWPERM"}});
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERSUPERLU_DIST), "PCFactorSetMatSolverType");
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
      if (c.refresh) c.refresh(c.ksp, J);
      petsc_check(KSPSetFromOptions(c.ksp), "KSPSetFromOptions");
      c.configured = true;
      ++c.stats->analyses;
    } else if (c.refresh) {
      c.refresh(c.ksp, J);
    }
    petsc_check(KSPSetUp(c.ksp), "KSPSetUp (factorisation)");
    if (c.after_first_setup) {
      c.after_first_setup(c.ksp);
      c.after_first_setup = nullptr;
    }
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
    if (c.after_solve) c.after_solve(its);
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
                                std::function<void(KSP)> configure,
                                std::function<void(KSP, Mat)> refresh = {},
                                std::function<void(KSP)> after_first_setup = {},
                                std::function<void(PetscInt)> after_solve = {}) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::runtime_error("SUNLinSolNewEmpty failed");
  auto* c = new KspContent{};
  c->comm = comm;
  c->stats = stats;
  c->configure = std::move(configure);
  c->refresh = std::move(refresh);
  c->after_first_setup = std::move(after_first_setup);
  c->after_solve = std::move(after_solve);
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

LinearSolverPtr make_superlu_dist_solver(MPI_Comm comm, SUNContext ctx, LinearSolverStats* stats) {
  return make_ksp_solver(comm, ctx, stats, configure_superlu_dist);
}

LinearSolverPtr make_petsc_fieldsplit_solver(MPI_Comm comm, const KrylovConfig& config,
                                             FieldSplitLayout layout, SUNContext ctx,
                                             LinearSolverStats* stats) {
  std::shared_ptr<SchurApproximation> schur;
  if (layout.schur_term) {
    schur = std::make_shared<SchurApproximation>();
    schur->comm = comm;
    schur->term = layout.schur_term;
    schur->owned_p = static_cast<PetscInt>(layout.owned - layout.owned_u);
    petsc_check(
        ISCreateStride(comm, schur->owned_p,
                       static_cast<PetscInt>(layout.first_owned + layout.owned_u), 1, &schur->p),
        "ISCreateStride");
  }
  auto configure = [comm, config, schur, layout = std::move(layout)](KSP ksp) {
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
    petsc_check(ISSetBlockSize(u, layout.components), "ISSetBlockSize");
    petsc_check(ISCreateStride(comm, owned_p, first + owned_u, 1, &p), "ISCreateStride");
    if (layout.rigid_body_modes) {
      // The rigid-body modes of the owned nodes, picked up by the displacement split's matrix.
      Vec xyz = nullptr;
      petsc_check(VecCreateMPI(comm, owned_u, PETSC_DETERMINE, &xyz), "VecCreateMPI");
      petsc_check(VecSetBlockSize(xyz, layout.components), "VecSetBlockSize");
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
    }
    petsc_check(PCFieldSplitSetIS(pc, "u", u), "PCFieldSplitSetIS");
    petsc_check(PCFieldSplitSetIS(pc, "p", p), "PCFieldSplitSetIS");
    ISDestroy(&u);
    ISDestroy(&p);
    petsc_check(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR), "PCFieldSplitSetType");
    petsc_check(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER),
                "PCFieldSplitSetSchurFactType");
    if (!schur)
      petsc_check(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_SELFP, nullptr),
                  "PCFieldSplitSetSchurPre");
    // Defaults of the splits, as options so that the user's options (read later) win. The
    // case file's AMG threshold and cycles, and its inner solve of the displacement block
    // (block_rtol > 0: GMRES + AMG to that relative residual, as in one process).
    const std::string threshold = option_number(config.amg_threshold);
    const std::string cycles = std::to_string(config.amg_cycles);
    const std::string block_rtol = option_number(config.block_rtol);
    if (config.block_rtol > 0.0)
      default_options({{"-biphasic_fieldsplit_u_ksp_type", "gmres"},
                       {"-biphasic_fieldsplit_u_ksp_rtol", block_rtol.c_str()},
                       {"-biphasic_fieldsplit_u_ksp_max_it", "100"}});
    default_options(
        {{"-biphasic_fieldsplit_u_ksp_type", "preonly"},
         {"-biphasic_fieldsplit_u_pc_type", "hypre"},
         {"-biphasic_fieldsplit_u_pc_hypre_boomeramg_strong_threshold", threshold.c_str()},
         {"-biphasic_fieldsplit_u_pc_hypre_boomeramg_max_iter", cycles.c_str()},
         {"-biphasic_fieldsplit_u_pc_hypre_boomeramg_coarsen_type", "HMIS"},
         {"-biphasic_fieldsplit_u_pc_hypre_boomeramg_interp_type", "ext+i"},
         {"-biphasic_fieldsplit_p_ksp_type", "preonly"},
         {"-biphasic_fieldsplit_p_pc_type", "lu"},
         {"-biphasic_fieldsplit_p_pc_factor_mat_solver_type", "mumps"},
         {"-biphasic_fieldsplit_p_mat_mumps_icntl_7", "4"}});
  };
  std::function<void(KSP, Mat)> refresh;
  if (schur) refresh = [schur](KSP ksp, Mat J) { schur->refresh(ksp, J); };
  // AMG cycles on the displacement block: one per outer iteration (times the cycles per
  // application) when the block is not solved by an inner Krylov method, else one per inner
  // iteration, counted by a monitor on the block's solver.
  auto cycles_per_outer = std::make_shared<long>(0);
  auto after_first_setup = [stats, cycles = config.amg_cycles, cycles_per_outer](KSP ksp) {
    PC pc = nullptr;
    petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
    PetscInt n = 0;
    KSP* subs = nullptr;
    petsc_check(PCFieldSplitGetSubKSP(pc, &n, &subs), "PCFieldSplitGetSubKSP");
    KSP block = subs[0];
    PetscFree(subs);
    PetscBool preonly = PETSC_FALSE;
    petsc_check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(block), KSPPREONLY, &preonly),
                "PetscObjectTypeCompare");
    if (preonly) {
      *cycles_per_outer = cycles;
      return;
    }
    auto count = [](KSP, PetscInt, PetscReal, void* counter) -> PetscErrorCode {
      ++static_cast<LinearSolverStats*>(counter)->amg_cycles;
      return 0;
    };
    petsc_check(KSPMonitorSet(block, count, stats, nullptr), "KSPMonitorSet");
  };
  auto after_solve = [stats, cycles_per_outer](PetscInt its) {
    stats->amg_cycles += *cycles_per_outer * static_cast<long>(its);
  };
  return make_ksp_solver(comm, ctx, stats, configure, refresh, after_first_setup, after_solve);
}

}  // namespace biphasic
