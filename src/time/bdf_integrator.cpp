#include "biphasic/time/bdf_integrator.hpp"

#include <ida/ida.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

#include "biphasic/io/atomic_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "biphasic/time/progress_meter.hpp"
#include "biphasic/time/solver_messages.hpp"

namespace biphasic {

namespace {

/// Owning handles of the SUNDIALS objects used for one linear solve or one IDA run.
struct SundialsContext {
  SUNContext ctx = nullptr;
  SundialsContext() {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
  }
  ~SundialsContext() { SUNContext_Free(&ctx); }
};

/// The start must satisfy F(t₀, y₀, ẏ₀) = 0; a momentum residual beyond what the displacement
/// tolerance allows means a load or prescribed displacement that jumps at t₀ (IDA does not
/// compute the undrained response to a jump). Throws a StepFailure naming cause and remedy.
void require_consistent(const ConsistentState& start, double t0, double allowed) {
  if (start.residual_u <= allowed) return;
  std::ostringstream msg;
  msg << "BDF cannot start at t = " << t0 << " s: the initial state is not in equilibrium "
      << "(momentum residual " << start.residual_u << " N after the consistent start, allowed "
      << allowed << " N = displacement tolerance x stiffness): a load or prescribed displacement "
      << "is already nonzero at t = " << t0
      << " s, i.e. it jumps there, and IDA needs consistent initial values (it does not compute "
         "the undrained response to a jump). Ramp the load up from zero over a short time "
         "instead (a curve [[0.0, 0.0], [t_r, 1.0]] with t_r well below the times of interest), "
         "or use time.integrator = \"backward_euler\", whose first step gives the undrained "
         "response.";
  throw StepFailure(msg.str());
}

/// GMRES of the shift-corrected solver: its relative residual is 1 % of IDA's rtol (the
/// error estimates and the order selection difference Newton corrections, so a looser solve
/// shows up as noise in them: at 1e-4 with rtol 1e-6 IDA held order 2–3 where it otherwise
/// reached 5), and at most 20 iterations per solve (more costs more than the factorisation
/// it saves).
constexpr double kShiftCorrectionRtolFactor = 1e-2;
constexpr int kShiftCorrectionIterations = 20;

}  // namespace

std::pair<double, double> absolute_tolerances(const SemidiscreteSystem& problem,
                                              const BdfConfig& bdf) {
  const auto [u_scale, p_scale] = problem.solution_scales();
  // Without data to scale by (a run driven by body forces alone, say): the former fixed values.
  const double au = bdf.atol_displacement > 0.0 ? bdf.atol_displacement
                    : u_scale > 0.0             ? bdf.rtol * u_scale
                                                : 1e-8;
  const double ap = bdf.atol_pressure > 0.0 ? bdf.atol_pressure
                    : p_scale > 0.0         ? bdf.rtol * p_scale
                                            : 1e-10;
  return {au, ap};
}

struct BdfIntegrator::Impl {
  SemidiscreteSystem& problem;
  TimeConfig time;
  LinearSolverConfig solver;
  std::string step_log_path;
  SundialsContext sc;
  void* ida = nullptr;
  N_Vector yy = nullptr, yp = nullptr, atol = nullptr, tmp = nullptr;
  SUNMatrix A = nullptr;
  LinearSolverPtr ls;
  CallbackFailure failure;  ///< an exception caught in the last residual or Jacobian callback
  double cj = 1.0;          ///< shift of the last Jacobian [1/s]
  /// ∂F/∂ẏ and c_j of the last Jacobian, for the shift-corrected solver.
  ShiftedMatrixFamily family;
  bool shift_correction = false;

  Impl(SemidiscreteSystem& p, const TimeConfig& tc, const LinearSolverConfig& lc, std::string log)
      : problem(p), time(tc), solver(lc), step_log_path(std::move(log)) {}
  ~Impl() {
    if (ida) IDAFree(&ida);
    if (A) SUNMatDestroy(A);
    ls.reset();
    for (N_Vector v : {yy, yp, atol, tmp})
      if (v) N_VDestroy(v);
  }

  // Callbacks: no exception may cross IDA's C frames. An inverted element is recoverable (IDA
  // reduces the step), any other exception unrecoverable; either is stored for the message.
  static int residual_fn(realtype t, N_Vector y, N_Vector ydot, N_Vector r, void* data) {
    auto* self = static_cast<Impl*>(data);
    return guarded_callback(self->failure, [&] {
      self->problem.residual(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot),
                             N_VGetArrayPointer(r));
    });
  }

  static int jacobian_fn(realtype t, realtype cj, N_Vector y, N_Vector ydot, N_Vector, SUNMatrix J,
                         void* data, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    self->cj = cj;
    return guarded_callback(self->failure, [&] {
      self->problem.jacobian_into(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), cj, J,
                                  self->shift_correction && !self->family.rate_values.empty()
                                      ? self->family.rate_values.data()
                                      : nullptr);
      self->family.setup_shift = cj;
    });
  }
};

BdfIntegrator::BdfIntegrator(SemidiscreteSystem& problem, const TimeConfig& time,
                             const LinearSolverConfig& linear_solver, std::string step_log_path)
    : impl_(std::make_unique<Impl>(problem, time, linear_solver, std::move(step_log_path))) {
  checked_interval_count(time.t_end, time.dt);  // an output count that fits, before any work
  if (time.volume_rate != VolumeRate::Incremental)
    throw std::invalid_argument(
        "time.volume_rate = \"conservative\" applies only to backward Euler");
  Impl& m = *impl_;
  const Index n = problem.size();
  m.yy = problem.new_vector(m.sc.ctx);
  m.yp = problem.new_vector(m.sc.ctx);
  m.tmp = problem.new_vector(m.sc.ctx);
  m.atol = problem.new_vector(m.sc.ctx);
  if (time.integrator == Integrator::AdaptiveBackwardEuler) m.time.bdf.max_order = 1;
  std::tie(atol_displacement_, atol_pressure_) = absolute_tolerances(problem, m.time.bdf);
  double* atol = N_VGetArrayPointer(m.atol);
  for (Index i = 0; i < n; ++i) atol[i] = i < problem.num_u() ? atol_displacement_ : atol_pressure_;
  m.A = problem.new_jacobian_matrix(m.sc.ctx);
  const SaddlePointStructure saddle = problem.saddle_point_structure([&m] {
    return std::pair{m.cj, m.cj};
  });
  LinearSolverPtr inner = problem.new_linear_solver(linear_solver, m.sc.ctx, &ls_stats_, &saddle);
  // The iterative solver is a Krylov method already; it solves at the matrix it was given.
  m.shift_correction =
      time.bdf.shift_correction && linear_solver.type != LinearSolverType::Iterative;
  if (m.shift_correction) {
    m.family.current_shift = [&m] {
      realtype cj = 0.0;
      IDAGetCurrentCj(m.ida, &cj);
      return cj;
    };
    m.ls = problem.new_shift_corrected_solver(std::move(inner), &m.family, m.sc.ctx, &ls_stats_,
                                              kShiftCorrectionRtolFactor * time.bdf.rtol,
                                              kShiftCorrectionIterations);
  } else {
    m.ls = std::move(inner);
  }
  stats_.order_counts.assign(5, 0);
}

BdfIntegrator::~BdfIntegrator() = default;

int BdfIntegrator::planned_outputs() const {
  return checked_interval_count(impl_->time.t_end, impl_->time.dt);
}

void BdfIntegrator::run(double t0, std::vector<double>& y, const StepObserver& observer) {
  Impl& m = *impl_;
  SemidiscreteSystem& problem = m.problem;
  const BdfConfig& bdf = m.time.bdf;
  const Index n = problem.size();
  const double t_end = m.time.t_end;
  // steps.csv: every accepted internal step. A restart (t0 > 0) keeps the rows up to t0 and
  // appends; every write is checked (a full disk stops the run naming the file).
  std::ofstream step_log;
  const std::string& log_path = m.step_log_path;
  if (bdf.step_log && !log_path.empty()) {
    const bool append = t0 > 0.0 && std::ifstream(log_path).good();
    if (append) keep_csv_rows_until(log_path, t0);
    step_log.open(log_path, append ? std::ios::app : std::ios::trunc);
    if (!append) step_log << "t,h,order\n";
    step_log.precision(17);
    flush_checked(step_log, log_path);
  }

  // Breakpoints after t0 (load-curve kinks), then the end.
  std::vector<double> stops;
  for (double k : problem.breakpoints())
    if (k > t0 + 1e-12 * std::max(1.0, t_end) && k < t_end) stops.push_back(k);
  stops.push_back(t_end);

  auto check = [&](int flag, const char* what) {
    if (flag < 0) throw std::runtime_error(std::string("IDA set-up failed in ") + what);
  };
  // Counters of the current IDA segment, added to the totals at each restart and at the end.
  long setups = 0;  // Jacobian setups of the segments before the current one (progress lines)
  auto accumulate = [&] {
    long v = 0;
    IDAGetNumLinSolvSetups(m.ida, &v);
    setups += v;
    IDAGetNumSteps(m.ida, &v);
    stats_.steps += v;
    IDAGetNumNonlinSolvIters(m.ida, &v);
    stats_.newton_iterations += v;
    IDAGetNumNonlinSolvConvFails(m.ida, &v);
    stats_.nonlinear_failures += v;
    IDAGetNumErrTestFails(m.ida, &v);
    stats_.error_test_failures += v;
  };

  // First step: the configured one, else 1 % of the first output interval or of the time to
  // the first kink, whichever is shorter.
  auto first_step = [&](double t) {
    if (bdf.initial_step > 0) return bdf.initial_step;
    double horizon = std::min(m.time.dt, t_end - t);
    for (double k : stops)
      if (k > t + 1e-12 * std::max(1.0, t_end)) {
        horizon = std::min(horizon, k - t);
        break;
      }
    return default_first_step(horizon, horizon);
  };
  // This run's counts start here (stats_ may carry an earlier run's).
  const long steps_before = stats_.steps, error_test_failures_before = stats_.error_test_failures;
  const double allowed_imbalance = atol_displacement_ * problem.stiffness_scale();
  double last_step = 0.0;
  // IDA from a consistent (y, ẏ) at t: created on the first call, re-initialised after a kink.
  auto start = [&](double t, std::vector<double>& ys) {
    ConsistentState cs = consistent_start(problem, t, ys, m.solver, &ls_stats_);
    stats_.starts.push_back({t, cs.residual_u, cs.residual_p, cs.pressure == PressureRole::Value});
    if (stats_.starts.size() == 1) require_consistent(cs, t, allowed_imbalance);
    ys = cs.y;
    std::copy(cs.y.begin(), cs.y.end(), N_VGetArrayPointer(m.yy));
    std::copy(cs.ydot.begin(), cs.ydot.end(), N_VGetArrayPointer(m.yp));
    if (!m.ida) {
      m.ida = IDACreate(m.sc.ctx);
      check(IDAInit(m.ida, Impl::residual_fn, t, m.yy, m.yp), "IDAInit");
      check(IDASVtolerances(m.ida, bdf.rtol, m.atol), "IDASVtolerances");
      check(IDASetUserData(m.ida, &m), "IDASetUserData");
      check(IDASetLinearSolver(m.ida, m.ls.get(), m.A), "IDASetLinearSolver");
      check(IDASetJacFn(m.ida, Impl::jacobian_fn), "IDASetJacFn");
      // The shift-corrected solver returns the exact correction for the current c_j.
      if (m.shift_correction)
        check(IDASetLinearSolutionScaling(m.ida, SUNFALSE), "IDASetLinearSolutionScaling");
      check(IDASetMaxOrd(m.ida, bdf.max_order), "IDASetMaxOrd");
      // time.bdf.max_steps is counted here, between outputs: IDA's own limit (IDASetMaxNumSteps)
      // applies within one IDASolve call, which IDA_ONE_STEP makes a single step.
      if (bdf.max_step > 0) check(IDASetMaxStep(m.ida, bdf.max_step), "IDASetMaxStep");
      check(IDASetDeltaCjLSetup(m.ida, bdf.delta_cj), "IDASetDeltaCjLSetup");
      check(IDASetEtaMax(m.ida, bdf.max_growth), "IDASetEtaMax");
      check(IDASetErrHandlerFn(
                m.ida, [](int, const char*, const char*, char*, void*) {}, nullptr),
            "IDASetErrHandlerFn");
      check(IDASetInitStep(m.ida, first_step(t)), "IDASetInitStep");
    } else {
      accumulate();
      ++stats_.restarts;
      check(IDAReInit(m.ida, t, m.yy, m.yp), "IDAReInit");
      double h0 = first_step(t);
      if (bdf.restart_from_last_step && last_step > 0) {
        h0 = last_step;
        for (double k : stops)
          if (k > t + 1e-12 * std::max(1.0, t_end)) {
            h0 = std::min(h0, k - t);
            break;
          }
      }
      check(IDASetInitStep(m.ida, h0), "IDASetInitStep");
    }
  };

  start(t0, y);
  // From t0: a restarted run (t0 > 0) has fewer outputs left than planned_outputs().
  const int outputs = checked_interval_count(t_end - t0, m.time.dt);
  auto output_time = [&](int k) { return k == outputs ? t_end : t0 + k * m.time.dt; };
  // Totals so far: accumulated segments plus the current one (IDAReInit resets its counters).
  auto totals = [&] {
    long steps = 0, nni = 0;
    IDAGetNumSteps(m.ida, &steps);
    IDAGetNumNonlinSolvIters(m.ida, &nni);
    return std::pair<long, long>{stats_.steps + steps, stats_.newton_iterations + nni};
  };
  std::size_t stop = 0;
  int next_output = 1;
  // IDA's stop time: the next kink, or with stop_at_outputs the next output if it comes first.
  auto target = [&] {
    double s = stops[stop];
    if (bdf.stop_at_outputs && next_output <= outputs) s = std::min(s, output_time(next_output));
    return s;
  };
  check(IDASetStopTime(m.ida, target()), "IDASetStopTime");
  std::pair<long, long> at_last_output{0, 0};
  std::vector<double> y_out(n), ydot_out(n), F(n);
  long steps_since_output = 0;
  // Names the output interval, the internal step, t, h and the cause of a failure.
  auto failure = [&](double t, double h, const std::string& cause) {
    std::ostringstream msg;
    msg << "BDF output step " << next_output << " (towards t = " << output_time(next_output)
        << " s): internal step " << totals().first + 1 << " from t = " << t << " s, h = " << h
        << " s failed: " << cause;
    return StepFailure(msg.str());
  };
  // Progress lines between outputs. They are written between two IDA_ONE_STEP calls of the
  // loop below and read only IDA's counters (IDAGet*) and the wall clock; no solver input
  // changes (no stop time, step limit or extra IDASolve call in IDA_NORMAL mode towards a
  // progress time, which would shorten the step that crosses it), so the results are
  // bit-identical with or without them, whatever the interval.
  ProgressMeter progress(t0, t_end, progress_interval());
  auto progress_sample = [&](double t, double h, int q) {
    ProgressSample s{t, h, q, 0, 0, 0};
    long v = 0;
    IDAGetNumSteps(m.ida, &v);
    s.steps = stats_.steps - steps_before + v;
    IDAGetNumLinSolvSetups(m.ida, &v);
    s.setups = setups + v;
    IDAGetNumErrTestFails(m.ida, &v);
    s.error_test_failures = stats_.error_test_failures - error_test_failures_before + v;
    return s;
  };
  double t_reached = t0;
  while (next_output <= outputs) {
    if (steps_since_output >= bdf.max_steps) {
      double h = 0.0;
      IDAGetLastStep(m.ida, &h);
      std::ostringstream cause;
      cause << "time.bdf.max_steps = " << bdf.max_steps
            << " internal steps taken since the previous output, the last of h = " << h
            << " s; the step size collapsed (a stiff or singular response), or the output "
               "interval time.dt is long for the solution's time scale (IDA_TOO_MUCH_WORK)";
      throw failure(t_reached, h, cause.str());
    }
    double tret = t0;
    m.failure.clear();
    ls_stats_.last_error.clear();
    const int flag = IDASolve(m.ida, target(), &tret, m.yy, m.yp, IDA_ONE_STEP);
    if (flag < 0) {
      double h = 0.0;
      IDAGetCurrentStep(m.ida, &h);
      std::string cause = ls_stats_.last_error.empty()
                              ? ida_flag_message(flag, h)
                              : "the linear solver failed: " + ls_stats_.last_error;
      if (!m.failure.empty()) cause += ": " + m.failure.message;
      throw failure(tret, h, cause);
    }
    ++steps_since_output;
    t_reached = tret;
    double h = 0.0;
    int q = 0;
    IDAGetLastStep(m.ida, &h);
    IDAGetLastOrder(m.ida, &q);
    stats_.step_sizes.push_back(h);
    last_step = h;
    if (q >= 1 && q <= 5) ++stats_.order_counts[q - 1];
    if (step_log.is_open()) {
      step_log << tret << ',' << h << ',' << q << '\n';
      if (!step_log) flush_checked(step_log, log_path);  // throws, naming the file and cause
    }
    // Outputs passed by this step, by IDA's interpolation.
    const int first_output = next_output;
    while (next_output <= outputs && output_time(next_output) <= tret + 1e-12 * t_end) {
      const double to = std::min(output_time(next_output), tret);
      IDAGetDky(m.ida, to, 0, m.tmp);
      std::copy_n(N_VGetArrayPointer(m.tmp), n, y_out.begin());
      IDAGetDky(m.ida, to, 1, m.tmp);
      std::copy_n(N_VGetArrayPointer(m.tmp), n, ydot_out.begin());
      const auto now = totals();
      StepInfo info;
      info.step = next_output;
      info.t = to;
      info.dt = h;
      info.order = q;
      info.internal_steps = static_cast<int>(now.first - at_last_output.first);
      info.newton_iterations = static_cast<int>(now.second - at_last_output.second);
      at_last_output = now;
      steps_since_output = 0;
      try {
        problem.residual(to, y_out.data(), ydot_out.data(), F.data());
      } catch (const std::exception& e) {
        throw failure(tret, h,
                      std::string("the solution interpolated at the output time could not be "
                                  "evaluated: ") +
                          e.what());
      }
      std::tie(info.residual_u, info.residual_p) = problem.field_norms(F.data());
      if (step_log.is_open()) flush_checked(step_log, log_path);  // on disk with the checkpoint
      if (observer) observer(info, y_out, ydot_out);
      progress.restart();  // the output line shows the progress
      ++next_output;
    }
    // A step that wrote an output line needs no progress line.
    if (next_output == first_output && progress.due())
      note(progress.line(progress_sample(tret, h, q)));
    if (flag == IDA_TSTOP_RETURN) {
      const bool kink =
          stop + 1 < stops.size() && std::abs(tret - stops[stop]) <= 1e-12 * std::max(1.0, t_end);
      if (kink) {
        // A kink of a load curve: restart from the values consistent after it.
        std::copy_n(N_VGetArrayPointer(m.yy), n, y.begin());
        start(tret, y);
        ++stop;
      }
      if (next_output <= outputs) check(IDASetStopTime(m.ida, target()), "IDASetStopTime");
    }
  }
  std::copy_n(N_VGetArrayPointer(m.yy), n, y.begin());
  accumulate();
  if (step_log.is_open()) flush_checked(step_log, log_path);
}

std::unique_ptr<TimeIntegrator> make_time_integrator(SemidiscreteSystem& problem,
                                                     const TimeConfig& time,
                                                     const LinearSolverConfig& linear_solver,
                                                     const std::string& output_dir) {
  switch (time.integrator) {
    case Integrator::BackwardEuler:
      return std::make_unique<BackwardEuler>(problem, time, linear_solver);
    case Integrator::Bdf:
    case Integrator::AdaptiveBackwardEuler:
      return std::make_unique<BdfIntegrator>(
          problem, time, linear_solver,
          output_dir.empty() ? std::string() : output_dir + "/steps.csv");
  }
  return nullptr;
}

}  // namespace biphasic
