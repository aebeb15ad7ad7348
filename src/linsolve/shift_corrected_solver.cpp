// A SUNLinearSolver for the matrix family A(c) = ∂F/∂y + c ∂F/∂ẏ that keeps the factors of the
// matrix last set up, A(c_s), while IDA's c_j drifts: A(c) x = b is solved by GMRES on
// A(c) = A(c_s) + (c − c_s) ∂F/∂ẏ, right-preconditioned by the factors of A(c_s), so that each
// Newton correction is the exact one for the current c_j (no stale-matrix error for IDA's
// error control to absorb) at the price of a few solves with the old factors.
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

namespace {

class ShiftCorrectedSolver {
 public:
  ShiftCorrectedSolver(LinearSolverPtr inner, const ShiftedMatrixFamily* family, SUNContext ctx,
                       LinearSolverStats* stats, double rtol, int max_iterations)
      : inner_(std::move(inner)),
        family_(family),
        stats_(stats),
        rtol_(rtol),
        m_(max_iterations),
        ctx_(ctx) {}
  ~ShiftCorrectedSolver() {
    for (N_Vector v : {t1_, t2_})
      if (v) N_VDestroy(v);
  }
  ShiftCorrectedSolver(const ShiftCorrectedSolver&) = delete;
  ShiftCorrectedSolver& operator=(const ShiftCorrectedSolver&) = delete;

  LinearSolverStats* stats() const { return stats_; }

  int setup(SUNMatrix A) {
    const sunindextype n = SUNSparseMatrix_Columns(A);
    const sunindextype nnz = SUNSparseMatrix_NNZ(A);
    const double* a = SUNSparseMatrix_Data(A);
    values_.assign(a, a + nnz);
    setup_shift_ = family_->setup_shift;
    // Row equilibration for the residual norm: 1 / max_j |A_ij|.
    row_scale_.assign(static_cast<std::size_t>(n), 0.0);
    const sunindextype* cp = SUNSparseMatrix_IndexPointers(A);
    const sunindextype* ri = SUNSparseMatrix_IndexValues(A);
    for (sunindextype j = 0; j < n; ++j)
      for (sunindextype q = cp[j]; q < cp[j + 1]; ++q)
        row_scale_[ri[q]] = std::max(row_scale_[ri[q]], std::abs(a[q]));
    for (double& s : row_scale_) s = s > 0.0 ? 1.0 / s : 1.0;
    if (!t1_) {
      t1_ = N_VNew_Serial(n, ctx_);
      t2_ = N_VNew_Serial(n, ctx_);
    }
    return last_flag_ = SUNLinSolSetup(inner_.get(), A);
  }

  int solve(SUNMatrix A, N_Vector x, N_Vector b) {
    const double c = family_->current_shift ? family_->current_shift() : setup_shift_;
    const double ratio = c / setup_shift_;
    if (!(std::abs(ratio - 1.0) > 1e-13))
      return last_flag_ = SUNLinSolSolve(inner_.get(), A, x, b, 0.0);
    return last_flag_ = gmres(A, c - setup_shift_, x, b);
  }

  int last_flag() const { return last_flag_; }

 private:
  /// y = P⁻¹ v with the factors of A(c_s).
  int precondition(SUNMatrix A, const std::vector<double>& v, std::vector<double>& y) {
    std::copy(v.begin(), v.end(), N_VGetArrayPointer(t1_));
    const int flag = SUNLinSolSolve(inner_.get(), A, t2_, t1_, 0.0);
    const double* r = N_VGetArrayPointer(t2_);
    y.assign(r, r + v.size());
    return flag;
  }

  /// y = A(c) v = A(c_s) v + dc ∂F/∂ẏ v.
  void apply(SUNMatrix A, double dc, const std::vector<double>& v, std::vector<double>& y) const {
    const sunindextype n = SUNSparseMatrix_Columns(A);
    const sunindextype* cp = SUNSparseMatrix_IndexPointers(A);
    const sunindextype* ri = SUNSparseMatrix_IndexValues(A);
    const std::vector<double>& r = family_->rate_values;
    y.assign(static_cast<std::size_t>(n), 0.0);
    for (sunindextype j = 0; j < n; ++j) {
      const double vj = v[j];
      if (vj == 0.0) continue;
      for (sunindextype q = cp[j]; q < cp[j + 1]; ++q) y[ri[q]] += (values_[q] + dc * r[q]) * vj;
    }
  }

  /// Right-preconditioned GMRES (no restart) on the row-equilibrated system, from x = 0.
  int gmres(SUNMatrix A, double dc, N_Vector xv, N_Vector bv) {
    const std::size_t n = row_scale_.size();
    const double* b = N_VGetArrayPointer(bv);
    std::vector<double> r0(n);
    for (std::size_t i = 0; i < n; ++i) r0[i] = row_scale_[i] * b[i];
    const double beta = std::sqrt(dot(r0, r0));
    ++stats_->shift_corrected_solves;
    double* x = N_VGetArrayPointer(xv);
    if (beta == 0.0) {
      std::fill(x, x + n, 0.0);
      return SUNLS_SUCCESS;
    }
    std::vector<std::vector<double>> V(1, r0), Z;
    for (double& v : V[0]) v /= beta;
    std::vector<std::vector<double>> H;  // columns of the Hessenberg matrix
    std::vector<double> cs, sn, g{beta};
    std::vector<double> z, w;
    int k = 0;
    bool converged = false;
    for (; k < m_; ++k) {
      // z = P⁻¹ D⁻¹ v_k, w = D A(c) z.
      std::vector<double> unscaled(n);
      for (std::size_t i = 0; i < n; ++i) unscaled[i] = V[k][i] / row_scale_[i];
      if (precondition(A, unscaled, z) != SUNLS_SUCCESS) return SUNLS_PSOLVE_FAIL_REC;
      apply(A, dc, z, w);
      for (std::size_t i = 0; i < n; ++i) w[i] *= row_scale_[i];
      Z.push_back(z);
      std::vector<double> h(static_cast<std::size_t>(k) + 2, 0.0);
      for (int j = 0; j <= k; ++j) {
        h[j] = dot(w, V[j]);
        for (std::size_t i = 0; i < n; ++i) w[i] -= h[j] * V[j][i];
      }
      h[k + 1] = std::sqrt(dot(w, w));
      for (int j = 0; j < k; ++j) {
        const double t = cs[j] * h[j] + sn[j] * h[j + 1];
        h[j + 1] = -sn[j] * h[j] + cs[j] * h[j + 1];
        h[j] = t;
      }
      const double rr = std::hypot(h[k], h[k + 1]);
      cs.push_back(h[k] / rr);
      sn.push_back(h[k + 1] / rr);
      h[k] = rr;
      g.push_back(-sn[k] * g[k]);
      g[k] *= cs[k];
      H.push_back(h);
      ++stats_->shift_correction_iterations;
      if (std::abs(g[k + 1]) <= rtol_ * beta) {
        converged = true;
        ++k;
        break;
      }
      if (h[k + 1] == 0.0) {  // the Krylov space holds the exact solution
        converged = true;
        ++k;
        break;
      }
      std::vector<double> next(n);
      const double hn = std::sqrt(dot(w, w));
      for (std::size_t i = 0; i < n; ++i) next[i] = w[i] / hn;
      V.push_back(std::move(next));
    }
    if (!converged) {
      ++stats_->shift_correction_failures;
      return SUNLS_CONV_FAIL;  // recoverable: IDA sets up a new matrix and retries
    }
    // Back substitution H y = g, x = Σ y_j z_j.
    std::vector<double> y(static_cast<std::size_t>(k), 0.0);
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= H[j][i] * y[j];
      y[i] = s / H[i][i];
    }
    std::fill(x, x + n, 0.0);
    for (int j = 0; j < k; ++j)
      for (std::size_t i = 0; i < n; ++i) x[i] += y[j] * Z[j][i];
    return SUNLS_SUCCESS;
  }

  static double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
  }

  LinearSolverPtr inner_;
  const ShiftedMatrixFamily* family_;
  LinearSolverStats* stats_;
  double rtol_;
  int m_;
  SUNContext ctx_;
  std::vector<double> values_;     ///< A(c_s)
  std::vector<double> row_scale_;  ///< 1 / max_j |A(c_s)_ij|
  double setup_shift_ = 0.0;
  N_Vector t1_ = nullptr, t2_ = nullptr;
  int last_flag_ = 0;
};

ShiftCorrectedSolver* solver_of(SUNLinearSolver S) {
  return static_cast<ShiftCorrectedSolver*>(S->content);
}

SUNLinearSolver_Type op_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID op_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int op_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
int op_setup(SUNLinearSolver S, SUNMatrix A) {
  return guarded_solver_call(solver_of(S)->stats(), [&] { return solver_of(S)->setup(A); });
}
int op_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  return guarded_solver_call(solver_of(S)->stats(), [&] { return solver_of(S)->solve(A, x, b); });
}
sunindextype op_lastflag(SUNLinearSolver S) { return solver_of(S)->last_flag(); }
int op_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete solver_of(S);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolverPtr make_shift_corrected_solver(LinearSolverPtr inner,
                                            const ShiftedMatrixFamily* family, SUNContext ctx,
                                            LinearSolverStats* stats, double rtol,
                                            int max_iterations) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::runtime_error("SUNLinSolNewEmpty failed");
  S->content = new ShiftCorrectedSolver(std::move(inner), family, ctx, stats, rtol, max_iterations);
  S->ops->gettype = op_gettype;
  S->ops->getid = op_getid;
  S->ops->initialize = op_initialize;
  S->ops->setup = op_setup;
  S->ops->solve = op_solve;
  S->ops->lastflag = op_lastflag;
  S->ops->free = op_free;
  return LinearSolverPtr(S);
}

}  // namespace biphasic
