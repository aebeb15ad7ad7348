#include "biphasic/time/consistent_start.hpp"

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
  std::vector<double> zero(n, 0.0), F0(n), dFdt(n), g(n), gdot(n);
  const std::unique_ptr<EntrywiseMatrices> matrices = problem.entrywise_matrices();
  matrices->evaluate(t, base.data(), zero.data());
  problem.residual(t, base.data(), zero.data(), F0.data());
  problem.time_derivative(t, dFdt.data());
  problem.apply_dirichlet(t, g.data(), gdot.data());

  // M = M₀ + ε·(regulariser) (slot 0) and M₀ (slot 1), columns z = (u̇, p or ṗ).
  constexpr int kM = 0, kM0 = 1, kA0u = 2;
  matrices->build(kM, [&](bool u_row, bool u_col, bool fixed_row, double a0, double r) {
    if (fixed_row) return a0;
    if (u_row && u_col) return r + eps * a0;    // GLS: ∂F_u/∂u̇, regularised
    if (u_row) return p_value ? a0 : eps * a0;  // ∂F_u/∂p
    if (u_col) return r;                        // ∂F_p/∂u̇
    return p_value ? a0 : r;  // Darcy ∂F_p/∂p, or flux perturbation ∂F_p/∂ṗ
  });
  matrices->build(kM0, [&](bool u_row, bool u_col, bool fixed_row, double a0, double r) {
    if (fixed_row) return a0;
    if (u_row && u_col) return r;
    if (u_row) return p_value ? a0 : 0.0;
    if (u_col) return r;
    return p_value ? a0 : r;
  });
  std::vector<double> b0(n), b(n);
  for (Index i = 0; i < n; ++i) {
    if (fixed[i]) {
      const double s = matrices->a0_diagonal(i);
      b0[i] = b[i] = s * (p_value && i >= nu ? g[i] : gdot[i]);
    } else if (i < nu) {
      b0[i] = gls ? -F0[i] : 0.0;
      b[i] = b0[i] - eps * dFdt[i];
    } else {
      b0[i] = b[i] = -F0[i];
    }
  }

  std::vector<double> z(n), r(n), dz(n);
  try {
    matrices->factorise(kM, solver, stats);
    matrices->solve(b.data(), z.data());
    // Refinement on the exact equations M₀ z = b₀: leaves the rates M₀ does not determine where
    // the regularised solve put them, and drives the residual to round-off.
    // Norms over the whole system: on several processes every one takes the same branch.
    const double target = 1e-14 * std::max(problem.max_norm(b0.data()), problem.max_norm(b.data()));
    for (int k = 0; k < 4; ++k) {
      matrices->residual(kM0, b0.data(), z.data(), r.data());
      if (problem.max_norm(r.data()) <= target) break;
      matrices->solve(r.data(), dz.data());
      for (Index i = 0; i < n; ++i) z[i] += dz[i];
    }
    out.y = y;
    out.ydot = z;
    if (p_value) {
      std::copy(z.begin() + nu, z.end(), out.y.begin() + nu);
      // ṗ₀ from the differentiated system, whose matrix is M₀ again (columns ü, ṗ):
      // ∂F/∂u̇ ü + ∂F/∂p ṗ = −∂F/∂t − ∂F/∂u u̇₀ at (y₀, u̇₀).
      std::fill(out.ydot.begin() + nu, out.ydot.end(), 0.0);
      matrices->evaluate(t, out.y.data(), out.ydot.data());
      matrices->build(kA0u, [](bool, bool u_col, bool fixed_row, double a0, double) {
        return u_col && !fixed_row ? a0 : 0.0;
      });
      std::vector<double> start(n), rhs(n);
      for (Index i = 0; i < n; ++i) start[i] = fixed[i] ? 0.0 : -dFdt[i];
      matrices->residual(kA0u, start.data(), out.ydot.data(), rhs.data());
      for (Index i = nu; i < n; ++i)
        if (fixed[i]) rhs[i] = matrices->a0_diagonal(i) * gdot[i];
      std::vector<double> w(n);
      matrices->solve(rhs.data(), w.data());
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
      std::vector<double> rhs(n, 0.0), w(n);
      for (Index i = 0; i < nu; ++i)
        if (!fixed[i]) rhs[i] = -eps * F[i];
      matrices->solve(rhs.data(), w.data());
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
