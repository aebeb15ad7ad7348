#include "biphasic/time/consistent_start.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "biphasic/time/solver_messages.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace biphasic {

namespace {

/// Relative size ε/τ of the regularising step: the momentum rows are solved at t₀ + ε along
/// the motion (first order in ε), ε = kRegularisation · min_e c_e/H_A. It selects the rates
/// the GLS term leaves undetermined (divergence-free at the quadrature points) through the
/// differentiated momentum balance, with an O(ε/τ) error in them only; the rest is refined to
/// round-off on the exact equations.
constexpr double kRegularisation = 1e-6;

/// Corrections of the algebraic constraints at a restart or a step load. Each costs a
/// factorisation and gains about two digits at small strain (the regulariser's stiffness is the
/// one at zero pressure and rate): from a state IDA left at its Newton tolerance, 1e-7 N fell to
/// 1e-15 N in four on a column; a step load with a 6 % undrained strain (a cartilage plug under a
/// platen force) needs five or six. They stop as soon as the residual is below the tolerance or
/// stops falling.
constexpr int kMaxCorrections = 12;

/// r = b − M x for a CSC matrix M in the pattern.
void residual_of(const SparsityPattern& pat, const std::vector<double>& M,
                 const std::vector<double>& b, const std::vector<double>& x,
                 std::vector<double>& r) {
  r = b;
  const auto& cp = pat.colptr();
  const auto& ri = pat.rowind();
  const Index n = pat.size();
  for (Index j = 0; j < n; ++j)
    for (Index q = cp[j]; q < cp[j + 1]; ++q) r[ri[q]] -= M[q] * x[j];
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// One factorisation of the regularised matrix, solves with it.
class RegularisedSystem {
 public:
  RegularisedSystem(const SemidiscreteSystem& problem, const std::vector<double>& values,
                    const LinearSolverConfig& solver, LinearSolverStats* stats) {
    if (SUNContext_Create(nullptr, &ctx_) != 0)
      throw std::runtime_error("SUNContext_Create failed");
    const SparsityPattern& pat = problem.pattern();
    M_ = pat.new_matrix(ctx_);
    std::copy(values.begin(), values.end(), SUNSparseMatrix_Data(M_));
    const SaddlePointStructure saddle = problem.saddle_point_structure([] {
      return std::pair{1.0, 0.0};
    });
    // A few solves with no Newton iteration after them: double-precision factors. The
    // regularised matrix is GLS-dominated (a step of ε ≪ the GLS time), where the iterative
    // solver's multigrid fails: a direct factorisation then, once per start.
    LinearSolverConfig exact = solver;
    exact.precision = FactorPrecision::Double;
    if (exact.type == LinearSolverType::Iterative) {
      exact.type = LinearSolverType::Mumps;
      exact.ordering = Ordering::Metis;
    }
    ls_ = make_linear_solver(exact, ctx_, stats ? stats : &own_stats_, fill_order(exact, pat),
                             &saddle);
    const Index n = problem.size();
    x_ = N_VNew_Serial(n, ctx_);
    b_ = N_VNew_Serial(n, ctx_);
    const int flag = SUNLinSolSetup(ls_.get(), M_);
    if (flag != 0) {
      const LinearSolverStats& st = stats ? *stats : own_stats_;
      throw std::runtime_error("the consistent start's regularised system could not be " +
                               std::string("factorised: ") + linear_solver_flag_message(flag) +
                               (st.last_error.empty() ? "" : ": " + st.last_error));
    }
  }
  ~RegularisedSystem() {
    N_VDestroy(x_);
    N_VDestroy(b_);
    ls_.reset();
    SUNMatDestroy(M_);
    SUNContext_Free(&ctx_);
  }
  RegularisedSystem(const RegularisedSystem&) = delete;
  RegularisedSystem& operator=(const RegularisedSystem&) = delete;

  std::vector<double> solve(const std::vector<double>& rhs) {
    std::copy(rhs.begin(), rhs.end(), N_VGetArrayPointer(b_));
    const int flag = SUNLinSolSolve(ls_.get(), M_, x_, b_, 0.0);
    if (flag != 0)
      throw std::runtime_error("the consistent start's regularised system could not be solved: " +
                               linear_solver_flag_message(flag));
    const double* x = N_VGetArrayPointer(x_);
    return {x, x + rhs.size()};
  }

 private:
  SUNContext ctx_ = nullptr;
  SUNMatrix M_ = nullptr;
  LinearSolverStats own_stats_;
  LinearSolverPtr ls_;
  N_Vector x_ = nullptr, b_ = nullptr;
};

}  // namespace

PressureRole pressure_role(const SemidiscreteSystem& problem) {
  return problem.has_gls() && !problem.has_flux_perturbation() ? PressureRole::Value
                                                               : PressureRole::Rate;
}

namespace {

std::string consistent_start_failure(double t, const std::string& cause) {
  std::ostringstream msg;
  msg << "the consistent initial values at t = " << t << " s could not be computed: " << cause;
  return msg.str();
}

/// One pass: (y₀, ẏ₀) from the given displacements. If the momentum rows that no rate can
/// balance (the algebraic constraints) are left out of balance by more than `tolerance` [N],
/// `correction` receives the change of y that restores them to first order with the
/// differential unknowns (the volumes the rates act on) held: the same regularised matrix with
/// the right-hand side (−ε F_u, 0).
ConsistentState consistent_pass(SemidiscreteSystem& problem, double t, const std::vector<double>& y,
                                const LinearSolverConfig& solver, LinearSolverStats* stats,
                                double tolerance, std::vector<double>& correction) {
  correction.clear();
  const Index n = problem.size();
  const Index nu = problem.num_u();
  const SparsityPattern& pat = problem.pattern();
  const std::vector<char>& fixed = problem.constrained();
  const bool gls = problem.has_gls();
  ConsistentState out;
  out.pressure = pressure_role(problem);
  const bool p_value = out.pressure == PressureRole::Value;
  // Without GLS the momentum rows hold no rate: they enter only differentiated, at unit weight.
  const double eps = gls ? kRegularisation * problem.gls_time_scale() : 1.0;

  // Base state: the given one; with p as an unknown value, its pressures zeroed so that F is
  // F(base) + ∂F/∂u̇ u̇ + ∂F/∂p p (F is affine in u̇ and p at fixed u).
  std::vector<double> base = y;
  if (p_value) std::fill(base.begin() + nu, base.end(), 0.0);
  std::vector<double> zero(n, 0.0), F0(n), dFdt(n), A0(pat.nnz()), R(pat.nnz()), g(n), gdot(n);
  problem.jacobian(t, base.data(), zero.data(), 0.0, A0.data(), R.data());
  problem.residual(t, base.data(), zero.data(), F0.data());
  problem.time_derivative(t, dFdt.data());
  problem.apply_dirichlet(t, g.data(), gdot.data());

  // M = M₀ + ε·(regulariser), columns z = (u̇, p or ṗ).
  std::vector<double> M(pat.nnz()), M0(pat.nnz());
  const auto& cp = pat.colptr();
  const auto& ri = pat.rowind();
  for (Index j = 0; j < n; ++j)
    for (Index q = cp[j]; q < cp[j + 1]; ++q) {
      const Index i = ri[q];
      const bool u_row = i < nu, u_col = j < nu;
      if (fixed[i]) {
        M0[q] = M[q] = A0[q];
      } else if (u_row && u_col) {
        M0[q] = R[q];  // GLS: ∂F_u/∂u̇
        M[q] = R[q] + eps * A0[q];
      } else if (u_row) {
        M0[q] = p_value ? A0[q] : 0.0;  // ∂F_u/∂p
        M[q] = p_value ? A0[q] : eps * A0[q];
      } else if (u_col) {
        M0[q] = M[q] = R[q];  // ∂F_p/∂u̇
      } else {
        M0[q] = M[q] = p_value ? A0[q] : R[q];  // Darcy ∂F_p/∂p, or flux perturbation ∂F_p/∂ṗ
      }
    }
  std::vector<double> b0(n), b(n);
  for (Index i = 0; i < n; ++i) {
    if (fixed[i]) {
      const double s = A0[pat.find(i, i)];
      b0[i] = b[i] = s * (p_value && i >= nu ? g[i] : gdot[i]);
    } else if (i < nu) {
      b0[i] = gls ? -F0[i] : 0.0;
      b[i] = b0[i] - eps * dFdt[i];
    } else {
      b0[i] = b[i] = -F0[i];
    }
  }

  std::vector<double> z, r;
  try {
    RegularisedSystem system(problem, M, solver, stats);
    z = system.solve(b);
    // Refinement on the exact equations M₀ z = b₀: leaves the rates M₀ does not determine where
    // the regularised solve put them, and drives the residual to round-off.
    const double target = 1e-14 * std::max(max_abs(b0), max_abs(b));
    for (int k = 0; k < 4; ++k) {
      residual_of(pat, M0, b0, z, r);
      if (max_abs(r) <= target) break;
      const std::vector<double> dz = system.solve(r);
      for (Index i = 0; i < n; ++i) z[i] += dz[i];
    }
    out.y = y;
    out.ydot = z;
    if (p_value) {
      std::copy(z.begin() + nu, z.end(), out.y.begin() + nu);
      // ṗ₀ from the differentiated system, whose matrix is M₀ again (columns ü, ṗ):
      // ∂F/∂u̇ ü + ∂F/∂p ṗ = −∂F/∂t − ∂F/∂u u̇₀ at (y₀, u̇₀).
      std::fill(out.ydot.begin() + nu, out.ydot.end(), 0.0);
      problem.jacobian(t, out.y.data(), out.ydot.data(), 0.0, A0.data());
      std::vector<double> rhs(n);
      for (Index i = 0; i < n; ++i) rhs[i] = fixed[i] ? 0.0 : -dFdt[i];
      for (Index j = 0; j < nu; ++j)
        for (Index q = cp[j]; q < cp[j + 1]; ++q)
          if (!fixed[ri[q]]) rhs[ri[q]] -= A0[q] * out.ydot[j];
      for (Index i = nu; i < n; ++i)
        if (fixed[i]) rhs[i] = A0[pat.find(i, i)] * gdot[i];
      const std::vector<double> w = system.solve(rhs);
      std::copy(w.begin() + nu, w.end(), out.ydot.begin() + nu);
    }
    // Dirichlet rows exactly (and unknowns tied to a rigid platen equal to its master's).
    problem.apply_dirichlet(t, out.y.data(), out.ydot.data());
    std::vector<double> F(n);
    problem.residual(t, out.y.data(), out.ydot.data(), F.data());
    std::tie(out.residual_u, out.residual_p) = problem.field_norms(F.data());
    // With the flux perturbation p is differential and u wholly algebraic: this matrix's
    // correction would move p as well, so the state is left as given there.
    if (out.residual_u > tolerance && !problem.has_flux_perturbation()) {
      std::vector<double> rhs(n, 0.0);
      for (Index i = 0; i < nu; ++i)
        if (!fixed[i]) rhs[i] = -eps * F[i];
      const std::vector<double> w = system.solve(rhs);
      correction.assign(n, 0.0);
      for (Index i = 0; i < n; ++i)
        if (!fixed[i]) correction[i] = i < nu || p_value ? w[i] : eps * w[i];
    }
  } catch (const std::runtime_error& e) {
    throw StepFailure(consistent_start_failure(t, e.what()));
  }
  return out;
}

}  // namespace

ConsistentState consistent_start(SemidiscreteSystem& problem, double t,
                                 const std::vector<double>& y, const LinearSolverConfig& solver,
                                 LinearSolverStats* stats) {
  // Momentum residual left by the algebraic constraints that calls for a correction of y: a
  // state from IDA satisfies them only to its Newton tolerance (a restart at a kink).
  const double force_scale = problem.stiffness_scale() * problem.solution_scales().first;
  const double tolerance = 1e-12 * (force_scale > 0.0 ? force_scale : problem.stiffness_scale());
  std::vector<double> correction;
  try {
    ConsistentState out = consistent_pass(problem, t, y, solver, stats, tolerance, correction);
    for (int k = 0; k < kMaxCorrections && !correction.empty(); ++k) {
      std::vector<double> corrected = out.y;
      for (std::size_t i = 0; i < corrected.size(); ++i) corrected[i] += correction[i];
      ConsistentState next =
          consistent_pass(problem, t, corrected, solver, stats, tolerance, correction);
      if (!(next.residual_u < out.residual_u)) break;
      out = std::move(next);
    }
    return out;
  } catch (const StepFailure&) {
    throw;
  } catch (const std::exception& e) {  // e.g. an element inverted by the given state
    throw StepFailure(consistent_start_failure(t, e.what()));
  }
}

}  // namespace biphasic
