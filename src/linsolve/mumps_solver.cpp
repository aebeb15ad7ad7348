// MUMPS (sequential build, multifrontal LU with BLAS-3 kernels) as a SUNLinearSolver:
// analysis once per pattern, a numeric factorisation at each setup; factors in double
// precision, or in single precision with each solve refined in double precision.
#include <dmumps_c.h>
#include <omp.h>
#include <smumps_c.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "direct_solver.hpp"

namespace biphasic {

namespace {

using detail::Clock;
using detail::seconds_since;

constexpr MUMPS_INT kUseCommWorld = -987654;

/// MUMPS' C interface in double (d) and single (s) precision.
struct DoublePrecision {
  using Struc = DMUMPS_STRUC_C;
  using Real = double;
  static void call(Struc* id) { dmumps_c(id); }
};
struct SinglePrecision {
  using Struc = SMUMPS_STRUC_C;
  using Real = float;
  static void call(Struc* id) { smumps_c(id); }
};

/// One MUMPS instance: analysis on the first factorisation, then numeric factorisations and
/// solves in the precision P (a single-precision instance keeps its own copy of the values).
template <class P>
class MumpsInstance {
 public:
  using Real = typename P::Real;
  static constexpr bool kDouble = std::is_same_v<Real, double>;

  MumpsInstance(Ordering ordering, const FillOrder& order) {
    id_.comm_fortran = kUseCommWorld;
    id_.par = 1;  // the host works
    id_.sym = 0;  // unsymmetric
    id_.job = -1;
    P::call(&id_);
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
  ~MumpsInstance() {
    id_.job = -2;  // release MUMPS' memory
    P::call(&id_);
  }
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;

  /// Numeric factorisation of A (analysis first if not yet done); false if MUMPS fails.
  bool factorise(SUNMatrix A, LinearSolverStats& stats) {
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
      set_values(A);
      const auto t0 = Clock::now();
      id_.job = 1;
      P::call(&id_);
      stats.analysis_seconds += seconds_since(t0);
      ++stats.analyses;
      if (infog(1) < 0) return false;
      analysed_ = true;
    }
    const auto t0 = Clock::now();
    set_values(A);  // values in CSC order, matching irn/jcn
    id_.job = 2;
    P::call(&id_);
    stats.factor_seconds += seconds_since(t0);
    ++stats.factorizations;
    if (infog(1) < 0) return false;
    // INFOG(29): entries in the factors (negative: millions).
    const double entries = infog(29) >= 0 ? infog(29) : -1e6 * infog(29);
    stats.fill = entries / static_cast<double>(id_.nnz);
    return true;
  }

  /// x = A⁻¹ b with the factors (x and b may alias); false if MUMPS fails.
  bool solve(const double* b, double* x) {
    const auto n = static_cast<std::size_t>(id_.n);
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.job = 3;
    if constexpr (kDouble) {
      std::copy_n(b, n, x);  // MUMPS overwrites the right-hand side with the solution
      id_.rhs = x;
      P::call(&id_);
    } else {
      rhs_.assign(b, b + n);
      id_.rhs = rhs_.data();
      P::call(&id_);
      std::copy(rhs_.begin(), rhs_.end(), x);
    }
    return infog(1) >= 0;
  }

 private:
  void set_values(SUNMatrix A) {
    double* a = SUNSparseMatrix_Data(A);
    if constexpr (kDouble) {
      id_.a = a;
    } else {
      values_.assign(a, a + id_.nnz);
      id_.a = values_.data();
    }
  }

  /// ICNTL(i) and INFOG(i) in MUMPS' 1-based numbering.
  MUMPS_INT& icntl(int i) { return id_.icntl[i - 1]; }
  MUMPS_INT infog(int i) const { return id_.infog[i - 1]; }

  typename P::Struc id_{};
  bool analysed_ = false;
  std::vector<MUMPS_INT> irn_, jcn_;  ///< 1-based coordinates in CSC value order
  std::vector<MUMPS_INT> perm_in_;    ///< position of each unknown in the caller's order
  std::vector<Real> values_, rhs_;    ///< single precision: the matrix and right-hand side
};

/// Componentwise backward error of x as a solution of A x = b (Oettli–Prager):
/// max_i |r_i| / (|A| |x| + |b|)_i with r = b − A x, which it stores. The product streams the
/// whole matrix (a sixth of a mixed-precision solve on mesh 1): two threads share the columns,
/// the second accumulating into `r2` and `scale2`, which are then added in.
double backward_error(SUNMatrix A, const double* b, const double* x, std::vector<double>& r,
                      std::vector<double>& scale, std::vector<double>& r2,
                      std::vector<double>& scale2) {
  const sunindextype n = SUNSparseMatrix_Columns(A);
  const sunindextype* Ap = SUNSparseMatrix_IndexPointers(A);
  const sunindextype* Ai = SUNSparseMatrix_IndexValues(A);
  const double* a = SUNSparseMatrix_Data(A);
  const auto size = static_cast<std::size_t>(n);
  r.resize(size);
  scale.resize(size);
  r2.resize(size);
  scale2.resize(size);
  // Columns [0, middle) to the first thread, the rest to the second: equal shares of entries.
  const sunindextype middle =
      static_cast<sunindextype>(std::upper_bound(Ap, Ap + n + 1, Ap[n] / 2) - Ap - 1);
  const bool two = Ap[n] > 100000;  // below this a second thread costs more than it saves
  double omega = 0.0;
#pragma omp parallel num_threads(two ? 2 : 1)
  {
    const bool second = two && omp_get_thread_num() == 1;
    double* rr = second ? r2.data() : r.data();
    double* ss = second ? scale2.data() : scale.data();
    if (second) {
      std::fill(rr, rr + n, 0.0);
      std::fill(ss, ss + n, 0.0);
    } else {
      for (sunindextype i = 0; i < n; ++i) {
        rr[i] = b[i];
        ss[i] = std::abs(b[i]);
      }
    }
    const sunindextype first = second ? middle : 0, last = (two && !second) ? middle : n;
    for (sunindextype j = first; j < last; ++j)
      for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q) {
        const double t = a[q] * x[j];
        rr[Ai[q]] -= t;
        ss[Ai[q]] += std::abs(t);
      }
#pragma omp barrier
#pragma omp for schedule(static) reduction(max : omega)
    for (sunindextype i = 0; i < n; ++i) {
      if (two) {
        r[i] += r2[i];
        scale[i] += scale2[i];
      }
      if (scale[i] > 0.0) omega = std::max(omega, std::abs(r[i]) / scale[i]);
    }
  }
  return omega;
}

/// MUMPS as a SUNLinearSolver, in double or mixed precision. Mixed: single-precision factors;
/// each solution is refined in double precision (x ← x + LU⁻¹(b − A x)) until its
/// componentwise backward error is at most kTargetBackwardError. A single-precision
/// factorisation that fails, or a refinement that stalls, falls back to double-precision
/// factors (counted in the stats) for the next few factorisations — 4, then twice as many
/// after each further fallback, up to 64 — before single precision is tried again: IDA's first
/// steps (h ~ 1e-6 s) need double precision, its later steps do not.
class MumpsSolver final : public detail::DirectSolver {
 public:
  static constexpr double kTargetBackwardError = 1e-6;
  static constexpr int kMaxRefinementSteps = 10;
  static constexpr int kFirstBackoff = 4, kMaxBackoff = 64;

  MumpsSolver(Ordering ordering, FactorPrecision precision, LinearSolverStats* stats,
              FillOrder order)
      : DirectSolver(stats),
        ordering_(ordering),
        order_(std::move(order)),
        mixed_(precision == FactorPrecision::Mixed) {}

  int setup(SUNMatrix A) override {
    if (mixed_ && double_factorisations_left_ == 0) {
      if (!single_) {
        double_.reset();  // one set of factors at a time
        single_ = std::make_unique<MumpsInstance<SinglePrecision>>(ordering_, order_);
      }
      if (single_->factorise(A, stats())) return SUNLS_SUCCESS;
      fall_back_to_double();
    }
    return factorise_double(A) ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
  }

  int solve(SUNMatrix A, N_Vector x, N_Vector b) override {
    const auto n = static_cast<std::size_t>(SUNSparseMatrix_Columns(A));
    double* xv = N_VGetArrayPointer(x);
    if (!single_)
      return double_->solve(N_VGetArrayPointer(b), xv) ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC;
    b_.assign(N_VGetArrayPointer(b), N_VGetArrayPointer(b) + n);  // x and b may alias
    if (!single_->solve(b_.data(), xv)) return SUNLS_PACKAGE_FAIL_UNREC;
    double omega = backward_error(A, b_.data(), xv, r_, scale_, r2_, scale2_);
    for (int k = 0; k < kMaxRefinementSteps && omega > kTargetBackwardError; ++k) {
      if (!single_->solve(r_.data(), r_.data())) return SUNLS_PACKAGE_FAIL_UNREC;
      for (std::size_t i = 0; i < n; ++i) xv[i] += r_[i];
      ++stats().refinement_steps;
      const double previous = omega;
      omega = backward_error(A, b_.data(), xv, r_, scale_, r2_, scale2_);
      if (omega > 0.5 * previous) break;  // stalled: single precision is not enough here
    }
    if (omega <= kTargetBackwardError) return SUNLS_SUCCESS;
    fall_back_to_double();
    if (!factorise_double(A)) return SUNLS_PACKAGE_FAIL_UNREC;
    return double_->solve(b_.data(), xv) ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC;
  }

 private:
  void fall_back_to_double() {
    ++stats().precision_fallbacks;
    double_factorisations_left_ = backoff_;
    backoff_ = std::min(2 * backoff_, kMaxBackoff);
  }
  bool factorise_double(SUNMatrix A) {
    if (!double_) {
      single_.reset();
      double_ = std::make_unique<MumpsInstance<DoublePrecision>>(ordering_, order_);
    }
    if (double_factorisations_left_ > 0) --double_factorisations_left_;
    return double_->factorise(A, stats());
  }

  Ordering ordering_;
  FillOrder order_;
  bool mixed_;
  int double_factorisations_left_ = 0;  ///< mixed: double-precision factorisations still due
  int backoff_ = kFirstBackoff;         ///< mixed: length of the next fallback
  std::unique_ptr<MumpsInstance<SinglePrecision>> single_;
  std::unique_ptr<MumpsInstance<DoublePrecision>> double_;
  std::vector<double> b_, r_, scale_, r2_, scale2_;  ///< refinement work vectors
};

}  // namespace

LinearSolverPtr make_mumps_solver(Ordering ordering, FactorPrecision precision, SUNContext ctx,
                                  LinearSolverStats* stats, FillOrder order) {
  return detail::wrap_direct_solver(
      std::make_unique<MumpsSolver>(ordering, precision, stats, std::move(order)), ctx);
}

}  // namespace biphasic
