// The [time] section of a case file: the time integrator and its settings (units: s). The
// integrators (backward_euler.hpp, bdf_integrator.hpp) read these; the case-file schema fills
// them.
#pragma once

namespace biphasic {

/// BackwardEuler: fixed step (the paper's). Bdf: IDA, orders 1–time.bdf.max_order.
/// AdaptiveBackwardEuler: IDA at order 1 (error-controlled backward Euler, time.bdf settings).
enum class Integrator { BackwardEuler, Bdf, AdaptiveBackwardEuler };
/// Whether the integrator runs on IDA (variable step, outputs by interpolation).
inline bool uses_ida(Integrator i) { return i != Integrator::BackwardEuler; }
/// How backward Euler discretises J̇ (in the mass rows and the GLS term). Incremental:
/// J F⁻ᵀ:∇₀(u − uₙ)/Δt (the paper's u̇ = Δu/Δt in div v). Conservative: (J − Jₙ)/Δt, so the
/// discrete fluid volume balance holds exactly. BDF always uses J F⁻ᵀ:∇₀u̇.
enum class VolumeRate { Incremental, Conservative };

struct NewtonConfig {
  int max_iterations = 25;
  /// Converged when, per field, ‖R_f‖_∞ ≤ max(rtol_f ‖R_f⁰‖_∞, atol_f), R_f⁰ = the residual at
  /// the step's predictor.
  double rtol_displacement = 1e-8;   ///< momentum rows [-]
  double rtol_pressure = 1e-8;       ///< mass rows [-]
  double atol_displacement = 1e-12;  ///< momentum rows [N]
  double atol_pressure = 1e-15;      ///< mass rows [mm³/s]
  int max_setup_calls = 10;          ///< Newton iterations between Jacobian refreshes (1 = full)
  bool reuse_across_steps = true;    ///< keep the factorisation from the previous step
  /// Backward Euler: successive halvings of the step after a failed Newton solve, down to
  /// time.dt / 2^max_cutbacks (0 = a failure stops the run).
  int max_cutbacks = 4;
};

/// Variable-order, variable-step BDF (SUNDIALS IDA). Defaults chosen by measurement
/// (docs/integrators.md).
struct BdfConfig {
  double rtol = 1e-4;  ///< relative tolerance of the local error test [-]
  /// Absolute tolerances [mm], [MPa]; 0 = rtol times the solution's own scale (the largest
  /// prescribed displacement; H_A times the applied strain, or the prescribed pressure or
  /// traction), see BiphasicProblem::solution_scales.
  double atol_displacement = 0.0;
  double atol_pressure = 0.0;
  int max_order = 5;  ///< 1–5
  /// First step [s] (also after a restart when restart_from_last_step is off); 0 = 1 % of the
  /// first output interval (or of the time to the first load-curve kink if shorter).
  double initial_step = 0.0;
  double max_step = 0.0;    ///< [s]; 0 = unlimited
  long max_steps = 100000;  ///< internal steps allowed between two outputs
  double max_growth = 2.0;  ///< largest step-size ratio between steps (IDASetEtaMax) [-]
  /// Relative change of c_j = α/h that forces a new factorisation (IDASetDeltaCjLSetup): with
  /// shift_correction, 0.9 (c_j may drift by a factor 19 on one factorisation).
  double delta_cj = 0.9;
  /// Solve with the current c_j on the last factorisation (GMRES preconditioned by it) instead
  /// of IDA's scaled stale-c_j correction, so that the Newton iteration sees the exact matrix.
  bool shift_correction = true;
  /// After a load-curve kink, start from the last accepted step instead of a fresh estimate.
  bool restart_from_last_step = true;
  /// End an internal step on every output time, so that outputs are step values (y, ẏ with
  /// F = 0) rather than interpolated: with GLS the reactions depend on ẏ.
  bool stop_at_outputs = true;
  bool step_log = false;  ///< write steps.csv (t, h, order) of every internal step
};

struct TimeConfig {
  Integrator integrator = Integrator::BackwardEuler;
  double t_end = 32.0;  ///< [s]
  double dt = 6.4;      ///< backward Euler step; output interval of BDF [s]
  VolumeRate volume_rate = VolumeRate::Incremental;  ///< backward Euler only
  NewtonConfig newton;
  BdfConfig bdf;
};

}  // namespace biphasic
