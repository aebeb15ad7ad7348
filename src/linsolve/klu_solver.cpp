// KLU as a SUNLinearSolver: analysis once, klu_refactor while the pivot order stays good.
#include <klu.h>
#include <metis.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "direct_solver.hpp"

namespace biphasic {

namespace {

using detail::Clock;
using detail::seconds_since;

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

class KluSolver final : public detail::DirectSolver {
 public:
  KluSolver(Ordering ordering, LinearSolverStats* stats, FillOrder order)
      : DirectSolver(stats), order_(std::move(order)) {
    klu_l_defaults(&common_);
    switch (ordering) {
      case Ordering::Amd:
        common_.ordering = 0;
        break;
      case Ordering::Colamd:
        common_.ordering = 1;
        break;
      case Ordering::Metis:
        common_.ordering = 3;
        common_.user_order = metis_order;
        break;
    }
  }
  ~KluSolver() override {
    if (numeric_) klu_l_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_l_free_symbolic(&symbolic_, &common_);
  }

  int setup(SUNMatrix A) override {
    const auto n = static_cast<SuiteSparse_long>(SUNSparseMatrix_Columns(A));
    auto* Ap = reinterpret_cast<SuiteSparse_long*>(SUNSparseMatrix_IndexPointers(A));
    auto* Ai = reinterpret_cast<SuiteSparse_long*>(SUNSparseMatrix_IndexValues(A));
    double* Ax = SUNSparseMatrix_Data(A);
    if (!symbolic_) {
      const auto t0 = Clock::now();
      if (order_.empty()) {
        symbolic_ = klu_l_analyze(n, Ap, Ai, &common_);
      } else {
        std::vector<SuiteSparse_long> P(order_.begin(), order_.end());
        symbolic_ = klu_l_analyze_given(n, Ap, Ai, P.data(), P.data(), &common_);
      }
      stats().analysis_seconds += seconds_since(t0);
      ++stats().analyses;
      if (!symbolic_) return SUNLS_PACKAGE_FAIL_UNREC;
    }
    const auto t0 = Clock::now();
    bool fresh = true;
    if (numeric_) {
      // Same pivot order; fall back to a pivoting factorisation when it degrades.
      if (klu_l_refactor(Ap, Ai, Ax, symbolic_, numeric_, &common_) &&
          klu_l_rcond(symbolic_, numeric_, &common_) && common_.rcond > 1e-12) {
        fresh = false;
        ++stats().refactorizations;
      } else {
        klu_l_free_numeric(&numeric_, &common_);
      }
    }
    if (fresh) numeric_ = klu_l_factor(Ap, Ai, Ax, symbolic_, &common_);
    stats().factor_seconds += seconds_since(t0);
    ++stats().factorizations;
    if (!numeric_) return SUNLS_LUFACT_FAIL;
    stats().fill = static_cast<double>(numeric_->lnz + numeric_->unz + numeric_->nzoff) /
                   static_cast<double>(Ap[n]);
    return SUNLS_SUCCESS;
  }

  int solve(SUNMatrix A, N_Vector x, N_Vector b) override {
    N_VScale(1.0, b, x);
    const auto n = static_cast<SuiteSparse_long>(SUNSparseMatrix_Columns(A));
    return klu_l_solve(symbolic_, numeric_, n, 1, N_VGetArrayPointer(x), &common_)
               ? SUNLS_SUCCESS
               : SUNLS_PACKAGE_FAIL_UNREC;
  }

 private:
  klu_l_common common_{};
  klu_l_symbolic* symbolic_ = nullptr;
  klu_l_numeric* numeric_ = nullptr;
  FillOrder order_;  ///< caller's pivot order (empty: KLU orders)
};

}  // namespace

LinearSolverPtr make_klu_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                FillOrder order) {
  return detail::wrap_direct_solver(std::make_unique<KluSolver>(ordering, stats, std::move(order)),
                                    ctx);
}

}  // namespace biphasic
