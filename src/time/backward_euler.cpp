#include "biphasic/time/backward_euler.hpp"

#include "biphasic/time/solver_messages.hpp"

#include <kinsol/kinsol.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace biphasic {

namespace {

/// Largest absolute Newton tolerance accepted, as a fraction of the residual the data drive:
/// 0.1 % of the force scale (stiffness × displacement scale) on the momentum rows and of the
/// volume-rate scale (conductance × pressure scale) on the mass rows.
constexpr double kMaxToleranceFraction = 1e-3;

/// Refuses (std::invalid_argument, naming key and value) an absolute tolerance that is no
/// longer small against the residuals the loads produce: KINSOL would then accept the initial
/// guess of every step after zero iterations, i.e. a solution that never moved (with
/// atol = 1e308, p ≡ 0). Where the data imply no scale (body forces alone), nothing is checked.
void check_absolute_tolerances(const SemidiscreteSystem& problem, const NewtonConfig& newton) {
  const auto [u_scale, p_scale] = problem.solution_scales();
  struct Field {
    const char* key;
    double atol;
    double scale;
    const char* unit;
    const char* what;
  };
  const Field fields[] = {
      {"time.newton.atol_displacement", newton.atol_displacement,
       problem.stiffness_scale() * u_scale, "N", "force scale H_A h u"},
      {"time.newton.atol_pressure", newton.atol_pressure, problem.conductance_scale() * p_scale,
       "mm^3/s", "volume-rate scale k h p"},
  };
  for (const Field& f : fields) {
    const double limit = kMaxToleranceFraction * f.scale;
    if (f.scale > 0.0 && !(f.atol <= limit)) {
      std::ostringstream msg;
      msg << f.key << " = " << f.atol << " " << f.unit << " is too large for this problem: "
          << "its " << f.what << " is " << f.scale << " " << f.unit << ", so at most " << limit
          << " " << f.unit << " (0.1 %) is accepted; a larger tolerance lets a step be "
          << "accepted without any Newton iteration (the default is 1e-12 N, 1e-15 mm^3/s)";
      throw std::invalid_argument(msg.str());
    }
  }
}

}  // namespace

struct BackwardEuler::Impl {
  SemidiscreteSystem& problem;
  TimeConfig time;
  SUNContext ctx = nullptr;
  void* kin = nullptr;
  N_Vector y = nullptr, uscale = nullptr, fscale = nullptr;
  SUNMatrix A = nullptr;
  LinearSolverPtr ls;
  std::vector<double> y_old, ydot, last_residual;
  double t = 0.0, dt = 1.0;
  CallbackFailure failure;  ///< an exception caught in the last residual or Jacobian callback

  // What carries from one step to the next (and over a restart, through resume_state()).
  double t_origin = 0.0;            ///< output times are t_origin + k·time.dt [s]
  bool resumed = false;             ///< set_resume_state was called: keep t_origin and the rest
  std::vector<double> y_previous;   ///< state before the last step (empty before the first)
  double dt_previous = 0.0;         ///< length of the last step [s]
  int level = 0;                    ///< cut-back depth: the sub-step is time.dt / 2^level
  int successes = 0;                ///< successful sub-steps at this level
  bool have_factorisation = false;  ///< the linear solver holds factors KINSOL may reuse
  // Where the held factorisation was evaluated: t, Δt, y and yₙ (ẏ = (y − yₙ)/Δt).
  double jac_t = 0.0, jac_dt = 0.0;
  std::vector<double> jac_y, jac_y_old;

  Impl(SemidiscreteSystem& p, const TimeConfig& tc) : problem(p), time(tc) {}
  ~Impl() {
    if (kin) KINFree(&kin);
    if (A) SUNMatDestroy(A);
    ls.reset();
    for (N_Vector v : {y, uscale, fscale})
      if (v) N_VDestroy(v);
    if (ctx) SUNContext_Free(&ctx);
  }

  void rate(const double* yv) {
    const Index n = problem.size();
    for (Index i = 0; i < n; ++i) ydot[i] = (yv[i] - y_old[i]) / dt;
  }

  // Callbacks: an inverted element is recoverable (KINSOL shortens its step; the step is cut
  // back), any other exception unrecoverable; either is stored for the failure message.
  static int residual_fn(N_Vector yv, N_Vector fv, void* data) {
    auto* self = static_cast<Impl*>(data);
    return guarded_callback(self->failure, [&] {
      self->rate(N_VGetArrayPointer(yv));
      self->problem.residual(self->t, N_VGetArrayPointer(yv), self->ydot.data(),
                             N_VGetArrayPointer(fv));
      std::copy_n(N_VGetArrayPointer(fv), self->problem.size(), self->last_residual.data());
    });
  }

  static int jacobian_fn(N_Vector yv, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    return guarded_callback(self->failure, [&] {
      const double* y = N_VGetArrayPointer(yv);
      self->rate(y);
      self->problem.jacobian_into(self->t, y, self->ydot.data(), 1.0 / self->dt, J);
      self->jac_t = self->t;
      self->jac_dt = self->dt;
      self->jac_y.assign(y, y + self->problem.size());
      self->jac_y_old = self->y_old;
    });
  }

  /// Evaluates and factorises the Jacobian at the recorded point (jac_t, jac_dt, jac_y,
  /// jac_y_old), as KINSOL's set-up would: the factors an uninterrupted run would hold.
  /// Returns false (leaving no factorisation) if either fails.
  bool refactorise_at_recorded_point() {
    t = jac_t;
    dt = jac_dt;
    if (time.volume_rate == VolumeRate::Conservative) problem.set_conservative_volume_rate(dt);
    y_old = jac_y_old;
    std::copy(jac_y.begin(), jac_y.end(), N_VGetArrayPointer(y));
    failure.clear();
    if (jacobian_fn(y, nullptr, A, this, nullptr, nullptr) != 0) return false;
    return SUNLinSolSetup(ls.get(), A) == 0;
  }
};

BackwardEuler::BackwardEuler(SemidiscreteSystem& problem, const TimeConfig& time,
                             const LinearSolverConfig& linear_solver)
    : impl_(std::make_unique<Impl>(problem, time)) {
  checked_interval_count(time.t_end, time.dt);  // a step count that fits, before any work
  check_absolute_tolerances(problem, time.newton);
  Impl& m = *impl_;
  if (SUNContext_Create(nullptr, &m.ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
  const Index n = problem.size();
  m.y = problem.new_vector(m.ctx);
  m.uscale = problem.new_vector(m.ctx);
  m.fscale = problem.new_vector(m.ctx);
  N_VConst(1.0, m.uscale);
  m.A = problem.new_jacobian_matrix(m.ctx);
  if (linear_solver.type == LinearSolverType::Iterative) {
    const SaddlePointStructure saddle = problem.saddle_point_structure([&m] {
      return std::pair{1.0 / m.dt, 1.0 / m.dt};
    });
    m.ls = problem.new_linear_solver(linear_solver, m.ctx, &ls_stats_, &saddle);
  } else {
    m.ls = problem.new_linear_solver(linear_solver, m.ctx, &ls_stats_, nullptr);
  }
  m.y_old.assign(n, 0.0);
  m.ydot.assign(n, 0.0);
  m.last_residual.assign(n, 0.0);

  m.kin = KINCreate(m.ctx);
  auto check = [](int flag, const char* what) {
    if (flag < 0) throw std::runtime_error(std::string("KINSOL set-up failed in ") + what);
  };
  check(KINInit(m.kin, Impl::residual_fn, m.y), "KINInit");
  check(KINSetUserData(m.kin, &m), "KINSetUserData");
  check(KINSetLinearSolver(m.kin, m.ls.get(), m.A), "KINSetLinearSolver");
  check(KINSetJacFn(m.kin, Impl::jacobian_fn), "KINSetJacFn");
  check(KINSetNumMaxIters(m.kin, time.newton.max_iterations), "KINSetNumMaxIters");
  check(KINSetMaxSetupCalls(m.kin, time.newton.max_setup_calls), "KINSetMaxSetupCalls");
  // The default maximum step (1000‖u₀‖, at least 1) would cut Newton steps from rest.
  check(KINSetMaxNewtonStep(m.kin, 1e30), "KINSetMaxNewtonStep");
  check(KINSetFuncNormTol(m.kin, 1.0),
        "KINSetFuncNormTol");  // per-field scales carry the tolerances
  check(KINSetScaledStepTol(m.kin, 1e-15), "KINSetScaledStepTol");
  check(KINSetPrintLevel(m.kin, std::getenv("BIPHASIC_KINSOL_PRINT") ? 3 : 0), "KINSetPrintLevel");
  check(KINSetErrHandlerFn(
            m.kin, [](int, const char*, const char*, char*, void*) {}, nullptr),
        "KINSetErrHandlerFn");
}

BackwardEuler::~BackwardEuler() = default;

int BackwardEuler::planned_outputs() const {
  return checked_interval_count(impl_->time.t_end, impl_->time.dt);
}

namespace {
// Layout of BackwardEuler::resume_state(): a header of kResumeHeader values, then y_previous
// (n values, if dt_previous > 0), then jac_y and jac_y_old (n each, if a factorisation is held).
constexpr double kResumeLayout = 1.0;
constexpr std::size_t kResumeHeader = BackwardEuler::kResumeHeaderSize;
}  // namespace

std::vector<double> BackwardEuler::resume_state() const {
  const Impl& m = *impl_;
  std::vector<double> s{kResumeLayout,
                        m.t_origin,
                        static_cast<double>(m.level),
                        static_cast<double>(m.successes),
                        m.y_previous.empty() ? 0.0 : m.dt_previous,
                        m.have_factorisation ? 1.0 : 0.0,
                        m.jac_t,
                        m.jac_dt};
  s.insert(s.end(), m.y_previous.begin(), m.y_previous.end());
  if (m.have_factorisation) {
    s.insert(s.end(), m.jac_y.begin(), m.jac_y.end());
    s.insert(s.end(), m.jac_y_old.begin(), m.jac_y_old.end());
  }
  return s;
}

void BackwardEuler::set_resume_state(const std::vector<double>& s) {
  Impl& m = *impl_;
  m.resumed = false;
  if (s.empty()) return;
  const std::size_t n = static_cast<std::size_t>(m.problem.size());
  auto refuse = [&](const std::string& why) {
    throw std::invalid_argument("backward Euler restart state: " + why);
  };
  if (s.size() < kResumeHeader || s[0] != kResumeLayout)
    refuse("unknown layout (written by another version)");
  const bool previous = s[4] > 0.0, factorised = s[5] != 0.0;
  const std::size_t expected = kResumeHeader + (previous ? n : 0) + (factorised ? 2 * n : 0);
  if (s.size() != expected) {
    refuse(std::to_string(s.size()) + " values where " + std::to_string(expected) +
           " were expected for " + std::to_string(n) + " unknowns");
  }
  if (!(s[2] >= 0.0 && s[2] <= m.time.newton.max_cutbacks && s[3] >= 0.0 && s[3] < 1e9))
    refuse("cut-back level " + std::to_string(s[2]) + " out of range");
  m.t_origin = s[1];
  m.level = static_cast<int>(s[2]);
  m.successes = static_cast<int>(s[3]);
  m.dt_previous = s[4];
  auto at = s.begin() + kResumeHeader;
  m.y_previous.assign(at, at + (previous ? n : 0));
  at += previous ? n : 0;
  m.have_factorisation = factorised;
  m.jac_t = s[6];
  m.jac_dt = s[7];
  if (factorised) {
    m.jac_y.assign(at, at + n);
    m.jac_y_old.assign(at + n, at + 2 * n);
  }
  m.resumed = true;
}

void BackwardEuler::run(double t0, std::vector<double>& y, const StepObserver& observer) {
  Impl& m = *impl_;
  SemidiscreteSystem& problem = m.problem;
  const NewtonConfig& newton = m.time.newton;
  const Index n = problem.size();
  const double t_end = m.time.t_end;
  double* yv = N_VGetArrayPointer(m.y);
  double* fs = N_VGetArrayPointer(m.fscale);
  std::vector<double> F(n);
  // Output times t_origin + k·time.dt: a restart at output k0 continues the same grid.
  long long k0 = 0;
  if (m.resumed) {
    k0 = std::llround((t0 - m.t_origin) / m.time.dt);
    if (m.have_factorisation && !m.refactorise_at_recorded_point()) {
      m.have_factorisation = false;
      note("restart: the factorisation held at the checkpoint could not be rebuilt (" +
           m.failure.message + "); the next step starts with a fresh one");
    }
  } else {
    m.t_origin = t0;
    m.y_previous.clear();
    m.dt_previous = 0.0;
    m.level = m.successes = 0;
    m.have_factorisation = false;
  }
  m.resumed = false;
  const long long total_steps = checked_interval_count(t_end - m.t_origin, m.time.dt);
  const int num_steps = static_cast<int>(std::max(1LL, total_steps - k0));
  std::vector<double>& y_previous = m.y_previous;
  double& dt_previous = m.dt_previous;
  bool& have_factorisation = m.have_factorisation;

  // One step from (t, y) to t_next; the solution is left in yv. Returns the reason of a
  // failure (empty on success) and adds the Newton iterations to `iterations`; `newton_ran`
  // tells whether KINSOL ran (its last residual is then meaningful), `fatal` that a smaller
  // step cannot help (an exception other than an inverted element).
  bool newton_ran = false;
  bool fatal = false;
  auto solve_step = [&](double t, double t_next, long& iterations) -> std::string {
    newton_ran = false;
    fatal = false;
    m.dt = t_next - t;
    m.t = t_next;
    if (m.time.volume_rate == VolumeRate::Conservative) problem.set_conservative_volume_rate(m.dt);
    m.y_old = y;
    // Residual scales from the "predictor" (previous state with the new Dirichlet values),
    // which measures the load increment: converged when ‖R_f‖ ≤ max(rtol_f ‖R_f(predictor)‖,
    // atol_f).
    std::copy(y.begin(), y.end(), yv);
    try {
      problem.apply_dirichlet(t_next, yv, nullptr);
      m.rate(yv);
      problem.residual(t_next, yv, m.ydot.data(), F.data());
    } catch (const InvertedElement& e) {
      return std::string(
                 "the step's first trial state (the previous state with the new "
                 "boundary values) is not admissible in an element (inverted, or outside a "
                 "material law's range): ") +
             e.what();
    } catch (const std::exception& e) {
      fatal = true;
      return std::string(
                 "the boundary values or the residual could not be evaluated at the step's "
                 "first trial state: ") +
             e.what();
    }
    const auto [ru0, rp0] = problem.field_norms(F.data());
    const double su = 1.0 / std::max(newton.rtol_displacement * ru0, newton.atol_displacement);
    const double sp = 1.0 / std::max(newton.rtol_pressure * rp0, newton.atol_pressure);
    for (Index i = 0; i < n; ++i) fs[i] = i < problem.num_u() ? su : sp;
    // Initial guess: the previous state extrapolated along the last step's increment (after
    // the first step), else the previous state itself. Both are smooth in the body; the linear
    // Dirichlet rows carry the boundary increment in on the first iteration, which converges
    // far better than the predictor's distorted boundary layer when GLS is strong.
    auto initial_guess = [&] {
      if (y_previous.empty()) {
        std::copy(y.begin(), y.end(), yv);
        return;
      }
      const double ratio = m.dt / dt_previous;
      for (Index i = 0; i < n; ++i) yv[i] = y[i] + ratio * (y[i] - y_previous[i]);
    };
    initial_guess();

    // The residual at the current iterate against what may be accepted, field by field (≤ 1:
    // acceptable): the step's tolerance, or round-off of the problem's own scales (a relative
    // tolerance against a predictor residual that is itself round-off, as in a hold with
    // atol = 0, cannot be met and need not be). A NaN or a failed evaluation is +inf.
    auto scaled_residual = [&]() -> double {
      try {
        m.rate(yv);
        problem.residual(m.t, yv, m.ydot.data(), F.data());
      } catch (const std::exception&) {
        return std::numeric_limits<double>::infinity();
      }
      constexpr double kRoundoff = 1e-10;
      const auto [u_scale, p_scale] = problem.solution_scales();
      const auto [ru, rp] = problem.field_norms(F.data());
      const double ratio_u =
          ru / std::max(1.0 / su, kRoundoff * problem.stiffness_scale() * u_scale);
      const double ratio_p =
          rp / std::max(1.0 / sp, kRoundoff * problem.conductance_scale() * p_scale);
      if (std::isnan(ratio_u) || std::isnan(ratio_p))
        return std::numeric_limits<double>::infinity();
      return std::max(ratio_u, ratio_p);
    };
    double stalled_residual = 0.0;
    int flag = 0;
    newton_ran = true;
    // Attempts: (1) reuse the factorisation (modified Newton); (2) fresh Jacobian every
    // iteration; (3) full Newton with a line search. Each restarts from the initial guess.
    for (int attempt = 0; attempt < 3; ++attempt) {
      const bool reuse = attempt == 0 && have_factorisation && newton.reuse_across_steps;
      if (attempt == 0 && !reuse && newton.max_setup_calls == 1) continue;  // same as (2)
      KINSetNoInitSetup(m.kin, reuse ? SUNTRUE : SUNFALSE);
      KINSetMaxSetupCalls(m.kin, attempt == 0 ? newton.max_setup_calls : 1);
      if (attempt > 0) initial_guess();
      m.failure.clear();
      ls_stats_.last_error.clear();
      flag = KINSol(m.kin, m.y, attempt == 2 ? KIN_LINESEARCH : KIN_NONE, m.uscale, m.fscale);
      long nni = 0;
      KINGetNumNonlinSolvIters(m.kin, &nni);
      iterations += nni;
      // KIN_STEP_LT_STPTOL means the Newton steps vanished, not that the residual is small
      // (a stagnating iteration): accepted only if the residual meets its tolerance.
      stalled_residual = 0.0;
      if (flag == KIN_STEP_LT_STPTOL) stalled_residual = scaled_residual();
      if (flag >= 0 && stalled_residual <= 1.0) return {};
      ++stats_.nonlinear_failures;
      // An exception other than an inverted element, in a callback or the linear solver: the
      // same again would fail the same way.
      if ((!m.failure.empty() && !m.failure.recoverable) || !ls_stats_.last_error.empty()) {
        fatal = true;
        break;
      }
    }
    // A linear solver that stopped with a cause of its own: that cause, not KINSOL's guess.
    std::string reason = ls_stats_.last_error.empty()
                             ? kinsol_flag_message(flag)
                             : "the linear solver failed: " + ls_stats_.last_error;
    if (stalled_residual > 1.0) {
      std::ostringstream r;
      r << ", with the residual still " << stalled_residual << " times its tolerance";
      reason += r.str();
    }
    if (!m.failure.empty()) reason += ": " + m.failure.message;
    return reason;
  };

  // Cut-back: a failed step is retried from the last converged state with half the step, down
  // to time.dt / 2^max_cutbacks; after kGrowAfter successful sub-steps at one size the step
  // doubles again. Sub-steps never pass the next output time t0 + k·time.dt.
  constexpr int kGrowAfter = 2;
  int& level = m.level;  // sub-step = time.dt / 2^level
  int& successes = m.successes;
  double t = t0;
  for (int step = 1; step <= num_steps; ++step) {
    const double t_out =
        (step == num_steps) ? t_end : m.t_origin + static_cast<double>(k0 + step) * m.time.dt;
    const long jac_before = problem.stats().jacobian_evaluations;
    long iterations = 0;
    int sub_steps = 0;
    while (t < t_out) {
      const double h = std::ldexp(m.time.dt, -level);
      // Land exactly on the output time (round-off of t + h, or a sliver, included).
      const double t_next = t + h >= t_out - kSliverFraction * h ? t_out : t + h;
      const std::string reason = solve_step(t, t_next, iterations);
      if (!reason.empty()) {
        if (level >= newton.max_cutbacks || fatal) {
          std::ostringstream msg;
          msg << "backward Euler step " << step << " (t = " << t_next << " s, dt = " << m.dt
              << " s";
          if (level > 0)
            msg << ", after " << level << " cut-backs of time.dt = " << m.time.dt << " s";
          msg << ") failed: " << reason;
          if (newton_ran) {
            const auto [ru, rp] = problem.field_norms(m.last_residual.data());
            msg << "; last residual |R_u| = " << ru << " N, |R_p| = " << rp << " mm^3/s";
          }
          throw StepFailure(msg.str());
        }
        ++level;
        successes = 0;
        have_factorisation = false;  // its c_j = 1/Δt belongs to the failed step
        const Cutback cut{step, t, std::ldexp(m.time.dt, -level), reason};
        stats_.cutbacks.push_back(cut);
        std::ostringstream msg;
        msg << "cut-back: step " << step << " at t = " << t << " s, dt = " << m.dt << " s failed ("
            << reason << "); retrying with dt = " << cut.dt << " s (time.dt/" << (1L << level)
            << ", limit time.dt/" << (1L << newton.max_cutbacks) << ")";
        note(msg.str());
        continue;
      }
      have_factorisation = true;
      y_previous = y;
      dt_previous = m.dt;
      std::copy(yv, yv + n, y.begin());
      t = t_next;
      ++sub_steps;
      if (sub_step_hook_) {
        m.rate(yv);
        sub_step_hook_(t, m.dt, y, m.ydot);
      }
      ++stats_.steps;
      if (level > 0 && ++successes >= kGrowAfter) {
        --level;
        successes = 0;
        have_factorisation = false;
      }
    }

    StepInfo info;
    info.step = step;
    info.t = t;
    info.dt = m.dt;
    info.sub_steps = sub_steps;
    info.newton_iterations = static_cast<int>(iterations);
    info.setups = static_cast<int>(problem.stats().jacobian_evaluations - jac_before);
    std::tie(info.residual_u, info.residual_p) = problem.field_norms(m.last_residual.data());
    stats_.newton_iterations += iterations;
    m.rate(yv);  // ẏ of the converged state
    if (observer) observer(info, y, m.ydot);
  }
}

}  // namespace biphasic
