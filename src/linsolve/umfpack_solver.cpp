// UMFPACK (SuiteSparse, multifrontal LU with BLAS-3 kernels) as a SUNLinearSolver: symbolic
// analysis once per pattern, a numeric factorisation at each setup.
#include <umfpack.h>

#include <utility>
#include <vector>

#include "direct_solver.hpp"

namespace biphasic {

namespace {

using detail::Clock;
using detail::seconds_since;

class UmfpackSolver final : public detail::DirectSolver {
 public:
  UmfpackSolver(Ordering ordering, LinearSolverStats* stats, FillOrder order)
      : DirectSolver(stats), order_(std::move(order)) {
    umfpack_dl_defaults(control_);
    // The P2/P1 matrix is structurally symmetric with a mostly symmetric numerical pattern:
    // order A + Aᵀ and prefer diagonal pivots.
    control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    // No iterative refinement: each refinement step costs a residual and another solve, and
    // the Newton iteration around the solver corrects the same error.
    control_[UMFPACK_IRSTEP] = 0;
    switch (ordering) {
      case Ordering::Amd:
        control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
        break;
      case Ordering::Colamd:  // COLAMD is what AMD means under the unsymmetric strategy
        control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_UNSYMMETRIC;
        control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
        break;
      case Ordering::Metis:
        control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
        break;
    }
  }
  ~UmfpackSolver() override {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
  }

  int setup(SUNMatrix A) override {
    const auto n = static_cast<SuiteSparse_long>(SUNSparseMatrix_Columns(A));
    const auto* Ap = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexPointers(A));
    const auto* Ai = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexValues(A));
    const double* Ax = SUNSparseMatrix_Data(A);
    if (!symbolic_) {
      const auto t0 = Clock::now();
      std::vector<SuiteSparse_long> Q(order_.begin(), order_.end());
      const auto status = umfpack_dl_qsymbolic(n, n, Ap, Ai, Ax, Q.empty() ? nullptr : Q.data(),
                                               &symbolic_, control_, info_);
      stats().analysis_seconds += seconds_since(t0);
      ++stats().analyses;
      if (status != UMFPACK_OK) return SUNLS_PACKAGE_FAIL_UNREC;
    }
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    const auto t0 = Clock::now();
    const auto status = umfpack_dl_numeric(Ap, Ai, Ax, symbolic_, &numeric_, control_, info_);
    stats().factor_seconds += seconds_since(t0);
    ++stats().factorizations;
    if (status == UMFPACK_WARNING_singular_matrix) return SUNLS_LUFACT_FAIL;
    if (status != UMFPACK_OK) return SUNLS_PACKAGE_FAIL_UNREC;
    stats().fill = (info_[UMFPACK_LNZ] + info_[UMFPACK_UNZ]) / static_cast<double>(Ap[n]);
    return SUNLS_SUCCESS;
  }

  int solve(SUNMatrix A, N_Vector x, N_Vector b) override {
    const auto* Ap = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexPointers(A));
    const auto* Ai = reinterpret_cast<const SuiteSparse_long*>(SUNSparseMatrix_IndexValues(A));
    // x and b may alias: solve from a copy of the right-hand side.
    const auto n = static_cast<std::size_t>(SUNSparseMatrix_Columns(A));
    rhs_.assign(N_VGetArrayPointer(b), N_VGetArrayPointer(b) + n);
    const auto status =
        umfpack_dl_solve(UMFPACK_A, Ap, Ai, SUNSparseMatrix_Data(A), N_VGetArrayPointer(x),
                         rhs_.data(), numeric_, control_, info_);
    return status == UMFPACK_OK ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC;
  }

 private:
  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::vector<double> rhs_;
  FillOrder order_;  ///< caller's column pre-order (empty: UMFPACK orders)
};

}  // namespace

LinearSolverPtr make_umfpack_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                    FillOrder order) {
  return detail::wrap_direct_solver(
      std::make_unique<UmfpackSolver>(ordering, stats, std::move(order)), ctx);
}

}  // namespace biphasic
