// Consistent initial values (y₀, ẏ₀) of the semidiscrete system F(t, y, ẏ) = 0 for IDA, with
// every stabilisation: F(t₀, y₀, ẏ₀) = 0 on every row, and the rates of the algebraic
// constraints (the differentiated momentum balance) satisfied as well. The algebra of each
// variant is in docs/formulation.md, "Consistent initial values".
#pragma once

#include <vector>

#include "biphasic/linsolve/linear_solver_config.hpp"
#include "biphasic/time/semidiscrete_system.hpp"
#include "biphasic/time/time_config.hpp"

namespace biphasic {

/// How the pressure enters the consistent start.
enum class PressureRole {
  /// p is algebraic and determined at t₀ together with u̇₀ (GLS without flux perturbation: the
  /// momentum rows hold u̇ through the GLS term, so p₀ is not free).
  Value,
  /// p₀ is kept and ṗ₀ solved for (no stabilisation: p₀ follows from equilibrium, which the
  /// given state must satisfy; flux perturbation: p is a differential unknown).
  Rate,
};

struct ConsistentState {
  std::vector<double> y;     ///< y₀: the given state, with p₀ replaced when PressureRole::Value
  std::vector<double> ydot;  ///< ẏ₀
  PressureRole pressure = PressureRole::Rate;
  double residual_u = 0.0;  ///< ‖F_u(t₀, y₀, ẏ₀)‖∞ over the free momentum rows [N]
  double residual_p = 0.0;  ///< ‖F_p(t₀, y₀, ẏ₀)‖∞ over the free mass rows [mm³/s]
};

/// The role the problem's stabilisation gives the pressure.
PressureRole pressure_role(const SemidiscreteSystem& problem);

/// Consistent (y₀, ẏ₀) at time t from the state `y` (its displacements are kept; see
/// PressureRole for its pressures), solved in double precision with the configured linear
/// solver: one factorisation, a few solves (counted in `stats` if given).
ConsistentState consistent_start(SemidiscreteSystem& problem, double t,
                                 const std::vector<double>& y, const LinearSolverConfig& solver,
                                 LinearSolverStats* stats = nullptr);

}  // namespace biphasic
