// FGMRES (SUNDIALS SPFGMR) with a block upper-triangular preconditioner for the P2/P1
// saddle-point system, behind the same SUNLinearSolver adaptor as the direct solvers: each
// solve is converged to a tight tolerance, so the Newton iterations of KINSOL and IDA see an
// exact solve whichever solver is configured.
//
//   A = [A_uu A_up; A_pu A_pp],  P = [Ã_uu A_up; 0 S̃],  P⁻¹r: z_p = S̃⁻¹ r_p,
//                                                          z_u = Ã_uu⁻¹ (r_u − A_up z_p),
// Ã_uu⁻¹ = BoomerAMG V-cycles, S̃ = A_pp + (approximation of −A_pu A_uu⁻¹ A_up) by LDLᵀ.
#include <sunlinsol/sunlinsol_spfgmr.h>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>
#include <vector>

#include "boomer_amg.hpp"
#include "direct_solver.hpp"

namespace biphasic {

namespace {

using detail::Clock;
using detail::seconds_since;

/// FGMRES cycles that make exactly `max_iterations` iterations at most: `full_cycles` of
/// `dimension` = min(restart, max_iterations) Krylov vectors, then one of `remainder` vectors
/// (0 = none).
struct KrylovCycles {
  int dimension;
  int full_cycles;
  int remainder;
};
KrylovCycles krylov_cycles(int max_iterations, int restart) {
  const int dimension = std::min(restart, max_iterations);
  return {dimension, max_iterations / dimension, max_iterations % dimension};
}

class IterativeSolver final : public detail::DirectSolver {
 public:
  static constexpr double kAcceptedReduction = 1e-6;

  IterativeSolver(const KrylovConfig& config, SaddlePointStructure saddle, SUNContext ctx,
                  LinearSolverStats* stats)
      : DirectSolver(stats),
        config_(config),
        saddle_(std::move(saddle)),
        amg_({saddle_.components, config.amg_threshold, config.amg_cycles, config.block_rtol}) {
    const auto n = static_cast<sunindextype>(saddle_.constrained.size());
    if (n <= saddle_.num_u || (saddle_.components != 2 && saddle_.components != 3) ||
        saddle_.num_u % saddle_.components != 0 || !saddle_.schur_term)
      throw std::invalid_argument("iterative solver: inconsistent saddle-point structure");
    rhs_ = N_VNew_Serial(n, ctx);
    // Exactly max_iterations iterations at most: ⌊max/m⌋ cycles of m = min(restart, max)
    // vectors, then, if needed, one shorter cycle of the remainder from where they stopped.
    const KrylovCycles cycles = krylov_cycles(config.max_iterations, config.restart);
    krylov_ = make_fgmres(cycles.dimension, cycles.full_cycles - 1, ctx);
    SUNLinSolSetZeroGuess(krylov_, SUNTRUE);
    if (cycles.remainder > 0) krylov_tail_ = make_fgmres(cycles.remainder, 0, ctx);
  }
  ~IterativeSolver() override {
    if (krylov_) SUNLinSolFree(krylov_);
    if (krylov_tail_) SUNLinSolFree(krylov_tail_);
    if (rhs_) N_VDestroy(rhs_);
  }

  int setup(SUNMatrix A) override {
    try {
      if (row_ptr_.empty()) {
        const auto t0 = Clock::now();
        build_structure(A);
        stats().analysis_seconds += seconds_since(t0);
        ++stats().analyses;
      }
      const auto t0 = Clock::now();
      const double* Ax = SUNSparseMatrix_Data(A);
      for (std::size_t k = 0; k < value_.size(); ++k) value_[k] = Ax[csc_pos_[k]];
      for (std::size_t k = 0; k < uu_.value.size(); ++k) uu_.value[k] = value_[uu_pos_[k]];
      amg_.setup(uu_);
      setup_schur();
      stats().factor_seconds += seconds_since(t0);
      ++stats().factorizations;
      return SUNLS_SUCCESS;
    } catch (const std::exception& e) {
      stats().last_error = std::string("iterative solver set-up: ") + e.what();
      return SUNLS_PSET_FAIL_UNREC;
    }
  }

  int solve(SUNMatrix, N_Vector x, N_Vector b) override {
    // Stop at rtol times the right-hand side's 2-norm, unscaled: a field-by-field scaling
    // would demand a relative reduction of a field whose right-hand side has fallen to
    // round-off (IDA's momentum rows after a good predictor), which cannot be met.
    if (N_VMaxNorm(b) == 0.0) {
      N_VConst(0.0, x);
      return SUNLS_SUCCESS;
    }
    const double b_norm = std::sqrt(N_VDotProd(b, b));
    const double target = config_.rtol * b_norm;
    N_VScale(1.0, b, rhs_);  // x may be b itself
    int flag = SUNLinSolSolve(krylov_, nullptr, x, rhs_, target);
    int iterations = SUNLinSolNumIters(krylov_);
    double residual = SUNLinSolResNorm(krylov_);
    if (flag != SUNLS_SUCCESS && flag > 0 && krylov_tail_) {
      // The last, shorter cycle: from the iterate reached if the residual fell, else from 0.
      if (flag != SUNLS_RES_REDUCED) N_VConst(0.0, x);
      SUNLinSolSetZeroGuess(krylov_tail_, flag == SUNLS_RES_REDUCED ? SUNFALSE : SUNTRUE);
      flag = SUNLinSolSolve(krylov_tail_, nullptr, x, rhs_, target);
      iterations += SUNLinSolNumIters(krylov_tail_);
      residual = SUNLinSolResNorm(krylov_tail_);
    }
    stats().krylov_iterations += iterations;
    stats().max_krylov_iterations = std::max(stats().max_krylov_iterations, long{iterations});
    if (print_)
      std::fprintf(stderr, "fgmres: flag %d, %d iterations, residual %.3e (target %.3e)\n", flag,
                   iterations, residual, target);
    if (flag == SUNLS_SUCCESS) return SUNLS_SUCCESS;
    // Stopped short of rtol (at very large c_j the pressure rows' round-off, ε c_j |B u|, can
    // exceed the target): a residual reduced by kAcceptedReduction is still a good inexact
    // Newton direction; the Newton iteration corrects the remainder.
    if (flag > 0 && residual <= kAcceptedReduction * b_norm) return SUNLS_SUCCESS;
    return flag < 0 ? flag : SUNLS_CONV_FAIL;  // recoverable: the integrator sets up anew
  }

 private:
  /// CSR copy of the CSC pattern (row-parallel products), the displacement block for the
  /// AMG (Dirichlet rows and columns reduced to their diagonal) and the pressure block.
  void build_structure(SUNMatrix A) {
    const sunindextype n = SUNSparseMatrix_Columns(A);
    const sunindextype* cp = SUNSparseMatrix_IndexPointers(A);
    const sunindextype* ri = SUNSparseMatrix_IndexValues(A);
    const sunindextype nu = saddle_.num_u;
    const auto& fixed = saddle_.constrained;
    row_ptr_.assign(n + 1, 0);
    for (sunindextype k = 0; k < cp[n]; ++k) ++row_ptr_[ri[k] + 1];
    for (sunindextype i = 0; i < n; ++i) row_ptr_[i + 1] += row_ptr_[i];
    col_.resize(cp[n]);
    csc_pos_.resize(cp[n]);
    value_.resize(cp[n]);
    std::vector<sunindextype> next(row_ptr_.begin(), row_ptr_.end() - 1);
    for (sunindextype j = 0; j < n; ++j)  // columns in order: each row's columns come sorted
      for (sunindextype k = cp[j]; k < cp[j + 1]; ++k) {
        const sunindextype q = next[ri[k]]++;
        col_[q] = j;
        csc_pos_[q] = k;
      }
    p_start_.resize(n);
    uu_.row_ptr.assign(nu + 1, 0);
    uu_.col.clear();
    uu_pos_.clear();
    for (sunindextype i = 0; i < n; ++i) {
      sunindextype q = row_ptr_[i];
      while (q < row_ptr_[i + 1] && col_[q] < nu) {
        if (i < nu && (i == col_[q] || (!fixed[i] && !fixed[col_[q]]))) {
          uu_.col.push_back(static_cast<int>(col_[q]));
          uu_pos_.push_back(q);
        }
        ++q;
      }
      p_start_[i] = q;
      if (i < nu) uu_.row_ptr[i + 1] = static_cast<int>(uu_.col.size());
    }
    uu_.value.resize(uu_.col.size());
    const sunindextype np = n - nu;
    schur_.resize(np, np);
    work_.resize(n);
  }

  /// S̃ = A_pp + coupling term, Dirichlet pressures kept as their diagonal only.
  void setup_schur() {
    const sunindextype nu = saddle_.num_u, n = static_cast<sunindextype>(row_ptr_.size()) - 1;
    const auto& fixed = saddle_.constrained;
    std::vector<PressureEntry> entries;
    saddle_.schur_term(entries);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(entries.size() + value_.size() / 8);
    for (const PressureEntry& e : entries)
      if (!fixed[nu + e.row] && !fixed[nu + e.col]) t.emplace_back(e.row, e.col, e.value);
    for (sunindextype i = nu; i < n; ++i)
      for (sunindextype q = p_start_[i]; q < row_ptr_[i + 1]; ++q) {
        const sunindextype j = col_[q];
        if (i == j || (!fixed[i] && !fixed[j])) t.emplace_back(i - nu, j - nu, value_[q]);
      }
    schur_.setFromTriplets(t.begin(), t.end());
    if (!schur_analysed_) {
      ldlt_.analyzePattern(schur_);
      schur_analysed_ = true;
    }
    ldlt_.factorize(schur_);
    if (ldlt_.info() != Eigen::Success)
      throw std::runtime_error("pressure Schur approximation is not factorisable");
  }

  /// z = A x with the matrix of the last set-up.
  static int atimes(void* data, N_Vector xv, N_Vector zv) {
    auto* self = static_cast<IterativeSolver*>(data);
    const double* x = N_VGetArrayPointer(xv);
    double* z = N_VGetArrayPointer(zv);
    const auto n = static_cast<sunindextype>(self->row_ptr_.size()) - 1;
    const auto& rp = self->row_ptr_;
    const auto& c = self->col_;
    const auto& v = self->value_;
#pragma omp parallel for schedule(static)
    for (sunindextype i = 0; i < n; ++i) {
      double sum = 0.0;
      for (sunindextype q = rp[i]; q < rp[i + 1]; ++q) sum += v[q] * x[c[q]];
      z[i] = sum;
    }
    return 0;
  }

  /// z = P⁻¹ r (right preconditioning).
  static int psolve(void* data, N_Vector rv, N_Vector zv, double, int) {
    auto* self = static_cast<IterativeSolver*>(data);
    try {
      self->apply_preconditioner(N_VGetArrayPointer(rv), N_VGetArrayPointer(zv));
      return 0;
    } catch (const std::exception& e) {
      self->stats().last_error = std::string("preconditioner: ") + e.what();
      return SUNLS_PSOLVE_FAIL_UNREC;
    } catch (...) {
      self->stats().last_error = "preconditioner: an exception of unknown type";
      return SUNLS_PSOLVE_FAIL_UNREC;
    }
  }

  void apply_preconditioner(const double* r, double* z) {
    const sunindextype nu = saddle_.num_u, n = static_cast<sunindextype>(row_ptr_.size()) - 1;
    const Eigen::Map<const Eigen::VectorXd> rp(r + nu, n - nu);
    Eigen::Map<Eigen::VectorXd>(z + nu, n - nu) = ldlt_.solve(rp);
    double* t = work_.data();
#pragma omp parallel for schedule(static)
    for (sunindextype i = 0; i < nu; ++i) {
      double sum = r[i];
      for (sunindextype q = p_start_[i]; q < row_ptr_[i + 1]; ++q) sum -= value_[q] * z[col_[q]];
      t[i] = sum;
    }
    stats().amg_cycles += amg_.apply(t, z);
  }

  /// Right-preconditioned FGMRES (classical Gram–Schmidt) of `dimension` vectors, restarted
  /// at most `restarts` times.
  SUNLinearSolver make_fgmres(int dimension, int restarts, SUNContext ctx) {
    SUNLinearSolver s = SUNLinSol_SPFGMR(rhs_, SUN_PREC_RIGHT, dimension, ctx);
    if (!s) throw std::runtime_error("SUNLinSol_SPFGMR failed");
    SUNLinSol_SPFGMRSetMaxRestarts(s, restarts);
    SUNLinSol_SPFGMRSetGSType(s, SUN_CLASSICAL_GS);
    SUNLinSolSetATimes(s, this, atimes);
    SUNLinSolSetPreconditioner(s, this, nullptr, psolve);
    if (SUNLinSolInitialize(s) != SUNLS_SUCCESS) {
      SUNLinSolFree(s);
      throw std::runtime_error("SPFGMR initialisation failed");
    }
    return s;
  }

  KrylovConfig config_;
  SaddlePointStructure saddle_;
  detail::BoomerAmg amg_;
  SUNLinearSolver krylov_ = nullptr;
  SUNLinearSolver krylov_tail_ = nullptr;  ///< the remainder cycle (max_iterations mod restart)
  N_Vector rhs_ = nullptr;  ///< copy of the right-hand side; SPFGMR's template vector
  const bool print_ = std::getenv("BIPHASIC_KRYLOV_PRINT") != nullptr;  ///< a line per solve
  std::vector<sunindextype> row_ptr_, col_, csc_pos_, p_start_;
  std::vector<double> value_, work_;
  detail::CsrMatrix uu_;
  std::vector<sunindextype> uu_pos_;
  Eigen::SparseMatrix<double> schur_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
  bool schur_analysed_ = false;
};

}  // namespace

LinearSolverPtr make_iterative_solver(const KrylovConfig& config, SaddlePointStructure saddle,
                                      SUNContext ctx, LinearSolverStats* stats) {
  return detail::wrap_direct_solver(
      std::make_unique<IterativeSolver>(config, std::move(saddle), ctx, stats), ctx);
}

}  // namespace biphasic
