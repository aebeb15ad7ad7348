// What a run asks of a discretised biphasic model beyond the semidiscrete system the
// integrators drive: reactions, the fluid-volume balance, and per-element coefficients for its
// notes. BiphasicProblem (tetrahedra) and SectionProblem (plane strain, axisymmetric triangles)
// implement it, so that one run loop (app/run.cpp) serves both.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "biphasic/material/material_laws.hpp"
#include "biphasic/physics/rigid_platen.hpp"
#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

/// Fluid volume rates at (t, y, ẏ) [mm³/s] (docs/formulation.md, *Fluid-volume balance*).
struct FluidRates {
  /// −Σ of the mass residual (element terms and loads) on the pressure-Dirichlet rows: the
  /// fluid leaving through the drained faces (the negative fluid reaction).
  double drained = 0.0;
  double prescribed = 0.0;  ///< ∫Γq q̄ dA of the flux conditions (outward)
  double source = 0.0;      ///< ∫Ω₀ s dX of the fluid source
};

class BiphasicModel : public SemidiscreteSystem {
 public:
  /// Reaction forces of the named boundaries at (t, y, ẏ) [N], components (x, y, z); with two
  /// or more names a last entry with the total over their union (each row once).
  virtual std::vector<std::array<double, 3>> reactions(const std::vector<std::string>& boundaries,
                                                       double t, const double* y,
                                                       const double* ydot) = 0;
  /// Summing all mass rows: at a converged state ∫Ω₀ J̇ dX = source − drained − prescribed.
  virtual FluidRates fluid_rates(double t, const double* y, const double* ydot) = 0;
  /// ∫Ω₀ (J − 1) dX [mm³]: the body's volume change from the reference configuration.
  virtual double volume_change(const double* y) const = 0;
  /// Number of elements (tetrahedra or triangles).
  virtual Index num_elements() const = 0;
  /// c_e of element e's GLS term (0 without it) [MPa s].
  virtual double gls_coefficient(Index e) const = 0;
  /// The material laws of element e.
  virtual const MaterialLaws& laws_of(Index e) const = 0;
  /// The rigid platens under a prescribed force (empty without rigid_platen conditions).
  virtual const RigidPlatens& platens() const = 0;
};

}  // namespace biphasic
