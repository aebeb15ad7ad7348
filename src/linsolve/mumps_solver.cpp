// MUMPS (sequential build, multifrontal LU with BLAS-3 kernels) as a SUNLinearSolver:
// analysis once per pattern, a numeric factorisation at each setup.
#include <dmumps_c.h>

#include <utility>
#include <vector>

#include "direct_solver.hpp"

namespace biphasic {

namespace {

using detail::Clock;
using detail::seconds_since;

constexpr MUMPS_INT kUseCommWorld = -987654;

class MumpsSolver final : public detail::DirectSolver {
 public:
  MumpsSolver(Ordering ordering, LinearSolverStats* stats, const FillOrder& order)
      : DirectSolver(stats) {
    id_.comm_fortran = kUseCommWorld;
    id_.par = 1;  // the host works
    id_.sym = 0;  // unsymmetric
    id_.job = -1;
    dmumps_c(&id_);
    icntl(1) = -1;  // no messages
    icntl(2) = -1;
    icntl(3) = -1;
    icntl(4) = 0;
    icntl(28) = 1;  // sequential analysis
    switch (ordering) {
      case Ordering::Amd:
        icntl(7) = 0;
        break;
      case Ordering::Colamd:
        icntl(7) = 2;  // AMF (MUMPS has no COLAMD)
        break;
      case Ordering::Metis:
        icntl(7) = 5;
        break;
    }
    if (!order.empty()) {
      perm_in_.resize(order.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        perm_in_[static_cast<std::size_t>(order[k])] = static_cast<MUMPS_INT>(k + 1);
      id_.perm_in = perm_in_.data();
      icntl(7) = 1;  // the given order
    }
    icntl(14) = 40;  // working-space relaxation [%]
  }
  ~MumpsSolver() override {
    id_.job = -2;  // release MUMPS' memory
    dmumps_c(&id_);
  }

  int setup(SUNMatrix A) override {
    if (!analysed_) {
      const auto n = SUNSparseMatrix_Columns(A);
      const sunindextype* Ap = SUNSparseMatrix_IndexPointers(A);
      const sunindextype* Ai = SUNSparseMatrix_IndexValues(A);
      irn_.resize(static_cast<std::size_t>(Ap[n]));
      jcn_.resize(irn_.size());
      for (sunindextype j = 0; j < n; ++j)
        for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q) {
          irn_[q] = static_cast<MUMPS_INT>(Ai[q] + 1);
          jcn_[q] = static_cast<MUMPS_INT>(j + 1);
        }
      id_.n = static_cast<MUMPS_INT>(n);
      id_.nnz = static_cast<MUMPS_INT8>(Ap[n]);
      id_.irn = irn_.data();
      id_.jcn = jcn_.data();
      id_.a = SUNSparseMatrix_Data(A);
      const auto t0 = Clock::now();
      id_.job = 1;
      dmumps_c(&id_);
      stats().analysis_seconds += seconds_since(t0);
      ++stats().analyses;
      if (infog(1) < 0) return SUNLS_PACKAGE_FAIL_UNREC;
      analysed_ = true;
    }
    id_.a = SUNSparseMatrix_Data(A);  // values in CSC order, matching irn/jcn
    const auto t0 = Clock::now();
    id_.job = 2;
    dmumps_c(&id_);
    stats().factor_seconds += seconds_since(t0);
    ++stats().factorizations;
    if (infog(1) < 0) return SUNLS_LUFACT_FAIL;
    // INFOG(29): entries in the factors (negative: millions).
    const double entries = infog(29) >= 0 ? infog(29) : -1e6 * infog(29);
    stats().fill = entries / static_cast<double>(id_.nnz);
    return SUNLS_SUCCESS;
  }

  int solve(SUNMatrix, N_Vector x, N_Vector b) override {
    N_VScale(1.0, b, x);  // MUMPS overwrites the right-hand side with the solution
    id_.rhs = N_VGetArrayPointer(x);
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.job = 3;
    dmumps_c(&id_);
    return infog(1) >= 0 ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC;
  }

 private:
  /// ICNTL(i) and INFOG(i) in MUMPS' 1-based numbering.
  MUMPS_INT& icntl(int i) { return id_.icntl[i - 1]; }
  MUMPS_INT infog(int i) const { return id_.infog[i - 1]; }

  DMUMPS_STRUC_C id_{};
  bool analysed_ = false;
  std::vector<MUMPS_INT> irn_, jcn_;  ///< 1-based coordinates in CSC value order
  std::vector<MUMPS_INT> perm_in_;    ///< position of each unknown in the caller's order
};

}  // namespace

LinearSolverPtr make_mumps_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                  FillOrder order) {
  return detail::wrap_direct_solver(std::make_unique<MumpsSolver>(ordering, stats, order), ctx);
}

}  // namespace biphasic
