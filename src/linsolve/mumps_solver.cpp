// MUMPS (sequential build, multifrontal LU with BLAS-3 kernels) as a SUNLinearSolver:
// analysis once per pattern, a numeric factorisation at each setup; factors in double
// precision, or in single precision with each solve refined in double precision.
#include <dmumps_c.h>
#include <omp.h>
#include <smumps_c.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/assembly/threads.hpp"
#include "direct_solver.hpp"
#include "mixed_precision.hpp"
#include "mumps_steps.hpp"

namespace biphasic {

namespace {

using detail::DoublePrecision;
using detail::PrecisionBackoff;
using detail::RefinementTarget;
using detail::SinglePrecision;

constexpr MUMPS_INT kUseCommWorld = -987654;

/// One MUMPS instance: analysis on the first factorisation, then numeric factorisations and
/// solves in the precision P (MUMPS gets its own copy of the values).
///
/// Decoupled rows — a diagonal entry and nothing else, as the Dirichlet rows (s (y_i − g_i) = 0)
/// of the Jacobian are — are taken out of the factorisation: x_j = b_j / a_jj is known, so
/// column j's other entries move to the right-hand side (b_i ← b_i − a_ij x_j) and MUMPS sees
/// unknown j as an isolated 1×1 block instead of a member of the fronts. The same linear
/// system, solved exactly as before; on the paper's mesh 1 (3 008 of 24 910 rows) a quarter
/// fewer flops and a sixth fewer factor entries. Each factorisation checks that the rows are
/// still decoupled and analyses the whole matrix again if not.
template <class P>
class MumpsInstance {
 public:
  using Real = typename P::Real;

  MumpsInstance(Ordering ordering, const FillOrder& order, const std::string& out_of_core) {
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
    detail::mumps_factors_out_of_core(id_, out_of_core);
  }
  ~MumpsInstance() {
    id_.job = -2;  // release MUMPS' memory
    P::call(&id_);
  }
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;

  /// Numeric factorisation of A (analysis first if not yet done, or again if a decoupled row
  /// is coupled now); false if MUMPS fails.
  bool factorise(SUNMatrix A, LinearSolverStats& stats) {
    const double* a = SUNSparseMatrix_Data(A);
    const bool analyse = !analysed_ || !still_decoupled(a);
    if (analyse) plan(A, analysed_);  // the second time round: no decoupled rows
    set_values(a);
    if (analyse) {
      if (!detail::mumps_analyse(id_, P::call, stats)) return false;
      analysed_ = true;
      if (icntl(22) == 1)  // out of core
        detail::require_free_space(id_.ooc_tmpdir,
                                   detail::factor_file_bytes(id_, sizeof(typename P::Real)));
    }
    for (Coupling& c : coupling_) c.value = a[c.position];
    for (std::size_t k = 0; k < decoupled_.size(); ++k) diagonal_[k] = a[decoupled_diagonal_[k]];
    return detail::mumps_factorise(id_, P::call, static_cast<double>(SUNSparseMatrix_NNZ(A)),
                                   stats);
  }

  /// x = A⁻¹ b with the factors (x and b may alias); false if MUMPS fails.
  bool solve(const double* b, double* x) {
    const auto n = static_cast<std::size_t>(id_.n);
    corrected_.assign(b, b + n);
    for (const Coupling& c : coupling_)  // decoupled unknowns' columns to the right-hand side
      corrected_[c.row] -= c.value * (b[c.col] / diagonal_[c.decoupled_index]);
    rhs_.assign(corrected_.begin(), corrected_.end());  // MUMPS overwrites it with the solution
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.rhs = rhs_.data();
    id_.job = 3;
    P::call(&id_);
    detail::throw_if_factor_files_failed(id_);
    if (infog(1) < 0) return false;
    std::copy(rhs_.begin(), rhs_.end(), x);
    for (std::size_t k = 0; k < decoupled_.size(); ++k)  // exact, also in single precision
      x[decoupled_[k]] = corrected_[decoupled_[k]] / diagonal_[k];
    return true;
  }

 private:
  /// An entry a_row,col of a decoupled column, moved to the right-hand side.
  struct Coupling {
    sunindextype position, row, col;  ///< position in A's values
    std::size_t decoupled_index;      ///< col's index in decoupled_
    double value = 0.0;               ///< at the last factorisation
  };

  /// The entries MUMPS gets: all but the off-diagonal ones of decoupled rows and columns
  /// (unless `whole`).
  void plan(SUNMatrix A, bool whole) {
    const auto n = SUNSparseMatrix_Columns(A);
    const sunindextype* Ap = SUNSparseMatrix_IndexPointers(A);
    const sunindextype* Ai = SUNSparseMatrix_IndexValues(A);
    const double* a = SUNSparseMatrix_Data(A);
    // Row j is decoupled if its only non-zero value is a non-zero diagonal.
    std::vector<char> has_diagonal(static_cast<std::size_t>(n), 0), coupled(has_diagonal);
    for (sunindextype j = 0; j < n; ++j)
      for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q) {
        if (a[q] == 0.0) continue;
        (Ai[q] == j ? has_diagonal : coupled)[static_cast<std::size_t>(Ai[q])] = 1;
      }
    std::vector<std::size_t> index(static_cast<std::size_t>(n), kNone);
    decoupled_.clear();
    decoupled_diagonal_.clear();
    coupling_.clear();
    zero_.clear();
    kept_.clear();
    irn_.clear();
    jcn_.clear();
    if (!whole)
      for (sunindextype j = 0; j < n; ++j)
        if (has_diagonal[j] && !coupled[j]) {
          index[j] = decoupled_.size();
          decoupled_.push_back(j);
        }
    decoupled_diagonal_.resize(decoupled_.size());
    for (sunindextype j = 0; j < n; ++j)
      for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q) {
        const sunindextype i = Ai[q];
        const bool row_out = index[i] != kNone, col_out = index[j] != kNone;
        if (i == j && row_out) decoupled_diagonal_[index[i]] = q;
        if (i == j || (!row_out && !col_out)) {
          kept_.push_back(q);
          irn_.push_back(static_cast<MUMPS_INT>(i + 1));
          jcn_.push_back(static_cast<MUMPS_INT>(j + 1));
        } else if (row_out) {
          zero_.push_back(q);  // off-diagonal of a decoupled row: must stay zero
        } else {
          coupling_.push_back({q, i, j, index[j], 0.0});
        }
      }
    diagonal_.resize(decoupled_.size());
    id_.n = static_cast<MUMPS_INT>(n);
    id_.nnz = static_cast<MUMPS_INT8>(kept_.size());
    id_.irn = irn_.data();
    id_.jcn = jcn_.data();
  }

  bool still_decoupled(const double* a) const {
    return std::all_of(zero_.begin(), zero_.end(), [&](sunindextype q) { return a[q] == 0.0; }) &&
           std::all_of(decoupled_diagonal_.begin(), decoupled_diagonal_.end(),
                       [&](sunindextype q) { return a[q] != 0.0; });
  }

  void set_values(const double* a) {
    values_.resize(kept_.size());
    for (std::size_t k = 0; k < kept_.size(); ++k) values_[k] = static_cast<Real>(a[kept_[k]]);
    id_.a = values_.data();
  }

  /// ICNTL(i) and INFOG(i) in MUMPS' 1-based numbering.
  MUMPS_INT& icntl(int i) { return id_.icntl[i - 1]; }
  MUMPS_INT infog(int i) const { return id_.infog[i - 1]; }

  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  typename P::Struc id_{};
  bool analysed_ = false;
  std::vector<MUMPS_INT> irn_, jcn_;  ///< 1-based coordinates of the kept entries
  std::vector<sunindextype> kept_;    ///< positions in A's values of the entries MUMPS gets
  std::vector<MUMPS_INT> perm_in_;    ///< position of each unknown in the caller's order
  std::vector<sunindextype> decoupled_, decoupled_diagonal_, zero_;
  std::vector<Coupling> coupling_;
  std::vector<double> diagonal_, corrected_;  ///< a_jj of decoupled rows; corrected b
  std::vector<Real> values_, rhs_;            ///< MUMPS' copy of the kept values; right-hand side
};

/// How far x is from solving A x = b.
struct SolutionError {
  double backward;      ///< componentwise backward error max_i |r_i| / (|A| |x| + |b|)_i
  double residual_max;  ///< max_i |r_i|
};

/// The error of x as a solution of A x = b, r = b − A x (Oettli–Prager), storing r. The
/// product streams the whole matrix (a sixth of a mixed-precision solve on mesh 1): two threads
/// share the columns, the second accumulating into `r2` and `scale2`, which are then added in.
SolutionError solution_error(SUNMatrix A, const double* b, const double* x, std::vector<double>& r,
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
  // Below ~1e5 entries a second thread costs more than it saves.
  static const bool two_threads = worker_threads() >= 2;
  const bool two = two_threads && Ap[n] > 100000;
  double omega = 0.0, r_max = 0.0;
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
#pragma omp for schedule(static) reduction(max : omega, r_max)
    for (sunindextype i = 0; i < n; ++i) {
      if (two) {
        r[i] += r2[i];
        scale[i] += scale2[i];
      }
      if (scale[i] > 0.0) omega = std::max(omega, std::abs(r[i]) / scale[i]);
      r_max = std::max(r_max, std::abs(r[i]));
    }
  }
  return {omega, r_max};
}

/// MUMPS as a SUNLinearSolver, in double or mixed precision. Mixed: single-precision factors;
/// each solution is refined in double precision (x ← x + LU⁻¹(b − A x)) until it meets the
/// RefinementTarget; a single-precision factorisation that fails, or a refinement that stalls,
/// falls back to double-precision factors as PrecisionBackoff schedules (mixed_precision.hpp).
class MumpsSolver final : public detail::DirectSolver {
 public:
  MumpsSolver(Ordering ordering, FactorPrecision precision, LinearSolverStats* stats,
              FillOrder order, std::string out_of_core)
      : DirectSolver(stats),
        ordering_(ordering),
        order_(std::move(order)),
        out_of_core_(std::move(out_of_core)),
        mixed_(precision == FactorPrecision::Mixed) {}

  int setup(SUNMatrix A) override {
    if (mixed_ && backoff_.single_due()) {
      if (!single_) {
        double_.reset();  // one set of factors at a time
        single_ = std::make_unique<MumpsInstance<SinglePrecision>>(ordering_, order_, out_of_core_);
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
    double b_max = 0.0;
    for (const double v : b_) b_max = std::max(b_max, std::abs(v));
    auto excess = [&] {
      const SolutionError e = solution_error(A, b_.data(), xv, r_, scale_, r2_, scale2_);
      return RefinementTarget::excess(e.backward, e.residual_max, b_max);
    };
    auto correct = [&] {
      if (!single_->solve(r_.data(), r_.data())) return false;
      for (std::size_t i = 0; i < n; ++i) xv[i] += r_[i];
      return true;
    };
    switch (RefinementTarget::refine(correct, excess, stats())) {
      case RefinementTarget::Outcome::Accurate:
        return SUNLS_SUCCESS;
      case RefinementTarget::Outcome::SolverFailed:
        return SUNLS_PACKAGE_FAIL_UNREC;
      case RefinementTarget::Outcome::NotAccurate:
        break;
    }
    fall_back_to_double();
    if (!factorise_double(A)) return SUNLS_PACKAGE_FAIL_UNREC;
    return double_->solve(b_.data(), xv) ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_UNREC;
  }

 private:
  void fall_back_to_double() { backoff_.fall_back(stats()); }
  bool factorise_double(SUNMatrix A) {
    if (!double_) {
      single_.reset();
      double_ = std::make_unique<MumpsInstance<DoublePrecision>>(ordering_, order_, out_of_core_);
    }
    backoff_.double_factorised();
    return double_->factorise(A, stats());
  }

  Ordering ordering_;
  FillOrder order_;
  std::string out_of_core_;  ///< directory of out-of-core factors; empty: in memory
  bool mixed_;
  PrecisionBackoff backoff_;  ///< mixed: when to factorise in double precision
  std::unique_ptr<MumpsInstance<SinglePrecision>> single_;
  std::unique_ptr<MumpsInstance<DoublePrecision>> double_;
  std::vector<double> b_, r_, scale_, r2_, scale2_;  ///< refinement work vectors
};

}  // namespace

LinearSolverPtr make_mumps_solver(Ordering ordering, FactorPrecision precision, SUNContext ctx,
                                  LinearSolverStats* stats, FillOrder order,
                                  std::string out_of_core_directory) {
  return detail::wrap_direct_solver(
      std::make_unique<MumpsSolver>(ordering, precision, stats, std::move(order),
                                    std::move(out_of_core_directory)),
      ctx);
}

}  // namespace biphasic
