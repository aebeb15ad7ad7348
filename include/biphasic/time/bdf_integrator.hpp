// Variable-order, variable-step BDF (SUNDIALS IDA) on the semidiscrete system F(t, y, ẏ) = 0,
// GLS included in its Δt-free form, with the same sparse direct solvers as backward Euler.
// The Jacobian is dF/dy + c_j dF/dẏ in the fixed pattern. The start and every restart at a
// load-curve kink (a stop time) are consistent (consistent_start.hpp; IDACalcIC cannot solve
// this system). Outputs every time.dt by IDA's interpolation.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/linsolve/linear_solver_config.hpp"
#include "biphasic/time/consistent_start.hpp"
#include "biphasic/time/semidiscrete_system.hpp"
#include "biphasic/time/time_config.hpp"
#include "biphasic/time/time_integrator.hpp"

namespace biphasic {

/// IDA's absolute tolerances (displacement [mm], pressure [MPa]): the configured ones, or
/// where they are 0, rtol times the problem's solution scales.
std::pair<double, double> absolute_tolerances(const SemidiscreteSystem& problem,
                                              const BdfConfig& bdf);

class BdfIntegrator final : public TimeIntegrator {
 public:
  /// `step_log_path`: if not empty (and time.bdf.step_log), every internal step's t, h, order.
  BdfIntegrator(SemidiscreteSystem& problem, const TimeConfig& time,
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
  double atol_displacement_ = 0.0, atol_pressure_ = 0.0;
};

/// The integrator `time.integrator` names, with its settings and the linear solver's; BDF's
/// step log (time.bdf.step_log) goes to `output_dir`/steps.csv.
std::unique_ptr<TimeIntegrator> make_time_integrator(SemidiscreteSystem& problem,
                                                     const TimeConfig& time,
                                                     const LinearSolverConfig& linear_solver,
                                                     const std::string& output_dir);

}  // namespace biphasic
