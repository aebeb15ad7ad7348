// Variable-order, variable-step BDF (SUNDIALS IDA) on the semidiscrete system F(t, y, ẏ) = 0,
// GLS included in its Δt-free form, with the same sparse direct solvers as backward Euler.
// The Jacobian is dF/dy + c_j dF/dẏ in the fixed pattern. The consistent ẏ(0) comes from the
// differentiated equilibrium (IDACalcIC cannot solve this system); every load-curve kink is a
// stop time after which IDA restarts from a recomputed consistent ẏ. Outputs every time.dt by
// IDA's interpolation.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "biphasic/io/config.hpp"
#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace biphasic {

/// ẏ with F(t, y, ẏ) = 0 and the momentum rows differentiated in time: the saddle-point system
///   (∂F_u/∂y) ẏ = −∂F_u/∂t,   (∂F_p/∂ẏ) ẏ = −F_p(t, y, 0),   Dirichlet rows ẏ_i = dḡ_i/dt,
/// assembled in the problem's pattern and solved with the configured solver.
std::vector<double> consistent_rate(BiphasicProblem& problem, double t,
                                    const std::vector<double>& y, const LinearSolverConfig& solver);

class BdfIntegrator final : public TimeIntegrator {
 public:
  /// `step_log_path`: if not empty (and time.bdf.step_log), every internal step's t, h, order.
  BdfIntegrator(BiphasicProblem& problem, const TimeConfig& time,
                const LinearSolverConfig& linear_solver, std::string step_log_path = {});
  ~BdfIntegrator() override;
  BdfIntegrator(const BdfIntegrator&) = delete;
  BdfIntegrator& operator=(const BdfIntegrator&) = delete;

  void run(double t0, std::vector<double>& y, const StepObserver& observer) override;
  int planned_outputs() const override;
  const IntegratorStats& stats() const override { return stats_; }
  const LinearSolverStats& linear_solver_stats() const override { return ls_stats_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  IntegratorStats stats_;
  LinearSolverStats ls_stats_;
};

/// The integrator the configuration names.
std::unique_ptr<TimeIntegrator> make_time_integrator(BiphasicProblem& problem, const Config& config,
                                                     const std::string& output_dir);

}  // namespace biphasic
