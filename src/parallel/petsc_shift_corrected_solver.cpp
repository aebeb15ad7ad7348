#include "biphasic/parallel/petsc_shift_corrected_solver.hpp"

#include <nvector/nvector_parallel.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "biphasic/parallel/petsc_check.hpp"
#include "biphasic/parallel/petsc_linear_solver.hpp"

namespace biphasic {

namespace {

class PetscShiftCorrectedSolver {
 public:
  PetscShiftCorrectedSolver(MPI_Comm comm, LinearSolverPtr inner, const ShiftedMatrixFamily* family,
                            Mat rate, SUNContext ctx, LinearSolverStats* stats, double rtol,
                            int max_iterations)
      : comm_(comm),
        inner_(std::move(inner)),
        family_(family),
        rate_(rate),
        ctx_(ctx),
        stats_(stats),
        rtol_(rtol),
        max_iterations_(max_iterations) {}
  ~PetscShiftCorrectedSolver() {
    if (ksp_) KSPDestroy(&ksp_);
    if (op_) MatDestroy(&op_);
    for (Vec* v : {&scale_, &rhs_, &solution_, &work_, &in_, &out_})
      if (*v) VecDestroy(v);
    for (N_Vector v : {nin_, nout_})
      if (v) N_VDestroy(v);
  }
  PetscShiftCorrectedSolver(const PetscShiftCorrectedSolver&) = delete;
  PetscShiftCorrectedSolver& operator=(const PetscShiftCorrectedSolver&) = delete;

  LinearSolverStats* stats() const { return stats_; }
  int last_flag() const { return last_flag_; }

  int setup(SUNMatrix A) {
    matrix_ = A;
    Mat a = petsc_matrix(A);
    if (!ksp_) create(a);
    setup_shift_ = family_->setup_shift;
    // D = 1 / max_j |A(c_s)_ij| (1 for an empty row).
    petsc_check(MatGetRowMaxAbs(a, scale_, nullptr), "MatGetRowMaxAbs");
    PetscScalar* d = nullptr;
    PetscInt n = 0;
    petsc_check(VecGetLocalSize(scale_, &n), "VecGetLocalSize");
    petsc_check(VecGetArray(scale_, &d), "VecGetArray");
    for (PetscInt i = 0; i < n; ++i) d[i] = d[i] > 0.0 ? 1.0 / d[i] : 1.0;
    VecRestoreArray(scale_, &d);
    return last_flag_ = SUNLinSolSetup(inner_.get(), A);
  }

  int solve(SUNMatrix A, N_Vector x, N_Vector b) {
    const double c = family_->current_shift ? family_->current_shift() : setup_shift_;
    if (!(std::abs(c / setup_shift_ - 1.0) > 1e-13))
      return last_flag_ = SUNLinSolSolve(inner_.get(), A, x, b, 0.0);
    shift_difference_ = c - setup_shift_;
    ++stats_->shift_corrected_solves;
    // rhs = D b; GMRES on D A(c) x = D b.
    petsc_check(VecPlaceArray(in_, N_VGetArrayPointer(b)), "VecPlaceArray");
    petsc_check(VecPointwiseMult(rhs_, scale_, in_), "VecPointwiseMult");
    VecResetArray(in_);
    inner_flag_ = 0;
    petsc_check(KSPSolve(ksp_, rhs_, solution_), "KSPSolve (shift correction)");
    if (inner_flag_ != 0) return last_flag_ = SUNLS_PSOLVE_FAIL_REC;
    KSPConvergedReason reason;
    PetscInt its = 0;
    petsc_check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
    petsc_check(KSPGetIterationNumber(ksp_, &its), "KSPGetIterationNumber");
    stats_->shift_correction_iterations += its;
    if (reason < 0) {
      ++stats_->shift_correction_failures;
      return last_flag_ = SUNLS_CONV_FAIL;  // recoverable: IDA sets up a new matrix and retries
    }
    const PetscScalar* s = nullptr;
    petsc_check(VecGetArrayRead(solution_, &s), "VecGetArrayRead");
    std::copy_n(s, NV_LOCLENGTH_P(x), N_VGetArrayPointer(x));
    VecRestoreArrayRead(solution_, &s);
    return last_flag_ = SUNLS_SUCCESS;
  }

 private:
  /// The KSP, its shell operator D A(c) and shell preconditioner, and the work vectors.
  void create(Mat a) {
    PetscInt local = 0, global = 0;
    petsc_check(MatGetLocalSize(a, &local, nullptr), "MatGetLocalSize");
    petsc_check(MatGetSize(a, &global, nullptr), "MatGetSize");
    for (Vec* v : {&scale_, &rhs_, &solution_, &work_})
      petsc_check(VecCreateMPI(comm_, local, global, v), "VecCreateMPI");
    for (Vec* v : {&in_, &out_})
      petsc_check(VecCreateMPIWithArray(comm_, 1, local, global, nullptr, v),
                  "VecCreateMPIWithArray");
    nin_ = N_VNew_Parallel(comm_, local, global, ctx_);
    nout_ = N_VNew_Parallel(comm_, local, global, ctx_);
    petsc_check(MatCreateShell(comm_, local, local, global, global, this, &op_), "MatCreateShell");
    petsc_check(
        MatShellSetOperation(op_, MATOP_MULT,
                             reinterpret_cast<void (*)(void)>(&PetscShiftCorrectedSolver::mult)),
        "MatShellSetOperation");
    petsc_check(KSPCreate(comm_, &ksp_), "KSPCreate");
    petsc_check(KSPSetOperators(ksp_, op_, op_), "KSPSetOperators");
    petsc_check(KSPSetType(ksp_, KSPGMRES), "KSPSetType");
    petsc_check(KSPGMRESSetRestart(ksp_, max_iterations_), "KSPGMRESSetRestart");
    petsc_check(KSPSetPCSide(ksp_, PC_RIGHT), "KSPSetPCSide");
    petsc_check(KSPSetTolerances(ksp_, rtol_, 0.0, PETSC_DEFAULT, max_iterations_),
                "KSPSetTolerances");
    PC pc = nullptr;
    petsc_check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    petsc_check(PCSetType(pc, PCSHELL), "PCSetType");
    petsc_check(PCShellSetContext(pc, this), "PCShellSetContext");
    petsc_check(PCShellSetApply(pc, &PetscShiftCorrectedSolver::precondition), "PCShellSetApply");
  }

  /// y = D (A(c_s) v + (c − c_s) R v).
  static PetscErrorCode mult(Mat op, Vec v, Vec y) {
    void* ctx = nullptr;
    PetscCall(MatShellGetContext(op, &ctx));
    auto* self = static_cast<PetscShiftCorrectedSolver*>(ctx);
    PetscCall(MatMult(petsc_matrix(self->matrix_), v, y));
    PetscCall(MatMult(self->rate_, v, self->work_));
    PetscCall(VecAXPY(y, self->shift_difference_, self->work_));
    PetscCall(VecPointwiseMult(y, y, self->scale_));
    return 0;
  }

  /// z = A(c_s)⁻¹ D⁻¹ v by the inner solver's factors.
  static PetscErrorCode precondition(PC pc, Vec v, Vec z) {
    void* ctx = nullptr;
    PetscCall(PCShellGetContext(pc, &ctx));
    auto* self = static_cast<PetscShiftCorrectedSolver*>(ctx);
    PetscCall(VecPlaceArray(self->in_, N_VGetArrayPointer(self->nin_)));
    PetscCall(VecPointwiseDivide(self->in_, v, self->scale_));
    PetscCall(VecResetArray(self->in_));
    const int flag =
        SUNLinSolSolve(self->inner_.get(), self->matrix_, self->nout_, self->nin_, 0.0);
    if (flag != 0) {
      self->inner_flag_ = flag;
      PetscCall(VecSet(z, 0.0));
      return 0;
    }
    PetscCall(VecPlaceArray(self->out_, N_VGetArrayPointer(self->nout_)));
    PetscCall(VecCopy(self->out_, z));
    PetscCall(VecResetArray(self->out_));
    return 0;
  }

  MPI_Comm comm_;
  LinearSolverPtr inner_;
  const ShiftedMatrixFamily* family_;
  Mat rate_;
  SUNContext ctx_;
  LinearSolverStats* stats_;
  double rtol_;
  int max_iterations_;
  SUNMatrix matrix_ = nullptr;  ///< A(c_s), the matrix last set up
  double setup_shift_ = 0.0, shift_difference_ = 0.0;
  KSP ksp_ = nullptr;
  Mat op_ = nullptr;
  Vec scale_ = nullptr, rhs_ = nullptr, solution_ = nullptr, work_ = nullptr;
  Vec in_ = nullptr, out_ = nullptr;  ///< storage-less, over the N_Vectors' arrays
  N_Vector nin_ = nullptr, nout_ = nullptr;
  int inner_flag_ = 0;
  int last_flag_ = 0;
};

PetscShiftCorrectedSolver* solver_of(SUNLinearSolver S) {
  return static_cast<PetscShiftCorrectedSolver*>(S->content);
}

}  // namespace

LinearSolverPtr make_petsc_shift_corrected_solver(MPI_Comm comm, LinearSolverPtr inner,
                                                  const ShiftedMatrixFamily* family, Mat rate,
                                                  SUNContext ctx, LinearSolverStats* stats,
                                                  double rtol, int max_iterations) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::runtime_error("SUNLinSolNewEmpty failed");
  S->content = new PetscShiftCorrectedSolver(comm, std::move(inner), family, rate, ctx, stats, rtol,
                                             max_iterations);
  S->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  S->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  S->ops->initialize = [](SUNLinearSolver) { return 0; };
  S->ops->setup = [](SUNLinearSolver s, SUNMatrix A) {
    return guarded_solver_call(solver_of(s)->stats(), [&] { return solver_of(s)->setup(A); });
  };
  S->ops->solve = [](SUNLinearSolver s, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
    return guarded_solver_call(solver_of(s)->stats(), [&] { return solver_of(s)->solve(A, x, b); });
  };
  S->ops->lastflag = [](SUNLinearSolver s) -> sunindextype { return solver_of(s)->last_flag(); };
  S->ops->free = [](SUNLinearSolver s) -> int {
    if (!s) return 0;
    delete solver_of(s);
    s->content = nullptr;
    SUNLinSolFreeEmpty(s);
    return 0;
  };
  return LinearSolverPtr(S);
}

}  // namespace biphasic
