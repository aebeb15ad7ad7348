// Backward Euler with a fixed step (the paper's scheme): each step solves
//   F(tₙ₊₁, y, (y − yₙ)/Δt) = 0
// (with time.volume_rate = conservative, J̇ = (J − Jₙ)/Δt: BiphasicProblem::
// set_conservative_volume_rate before each step) by KINSOL's Newton iteration with the configured
// sparse direct solver, the Jacobian being dF/dy + (1/Δt) dF/dẏ. Factorisations are reused across
// iterations and steps while convergence allows (KINSetMaxSetupCalls, KINSetNoInitSetup).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/linsolve/linear_solver_config.hpp"
#include "biphasic/time/semidiscrete_system.hpp"
#include "biphasic/time/time_config.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace biphasic {

class BackwardEuler final : public TimeIntegrator {
 public:
  BackwardEuler(SemidiscreteSystem& problem, const TimeConfig& time,
                const LinearSolverConfig& linear_solver);
  ~BackwardEuler() override;
  BackwardEuler(const BackwardEuler&) = delete;
  BackwardEuler& operator=(const BackwardEuler&) = delete;

  /// Integrates from t0 (y = initial state, overwritten with the final one) to time.t_end in
  /// steps of time.dt (the last one shortened to land on t_end). A failed step is retried from
  /// the last converged state with Δt/2, at most time.newton.max_cutbacks halvings deep; the
  /// step doubles back after 2 successful sub-steps, and the observer sees only the output
  /// times t0 + k·time.dt. Throws StepFailure when a step fails at the smallest size.
  void run(double t0, std::vector<double>& y, const StepObserver& observer) override;
  int planned_outputs() const override;
  /// Called after every converged (sub-)step with its end time t, its length Δt [s], y and
  /// ẏ = (y − yₙ)/Δt, while the problem still holds that step's settings (e.g. to integrate
  /// boundary fluxes as backward Euler does, step by step, cut-backs included).
  using SubStepHook = std::function<void(double t, double dt, const std::vector<double>& y,
                                         const std::vector<double>& ydot)>;
  void set_sub_step_hook(SubStepHook hook) { sub_step_hook_ = std::move(hook); }

  /// Backward Euler's state beyond (t, y): the time origin of the output grid, the state and
  /// length of the previous step (the next Newton guess extrapolates along it), the cut-back
  /// level, and the point (t, Δt, y, yₙ) where the kept factorisation was evaluated; restored,
  /// it reproduces an uninterrupted run to round-off.
  /// resume_state() is this many scalars, then up to three vectors of the system's size.
  static constexpr std::size_t kResumeHeaderSize = 8;
  std::vector<double> resume_state() const override;
  void set_resume_state(const std::vector<double>& state) override;

  const IntegratorStats& stats() const override { return stats_; }
  const LinearSolverStats& linear_solver_stats() const override { return ls_stats_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  IntegratorStats stats_;
  LinearSolverStats ls_stats_;
  SubStepHook sub_step_hook_;
};

}  // namespace biphasic
