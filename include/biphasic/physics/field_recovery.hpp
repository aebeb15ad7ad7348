// Element fields recovered from a state for the field output (docs/output_fields.md): the
// Cauchy stress, the volume ratio, the Darcy flux and the permeability, one value per element.
#pragma once

#include <vector>

#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic {

/// Per-element values of a state, each the mean over the element's quadrature points weighted
/// by their reference volume, Σ_q w_q f_q / Σ_q w_q (the quadrature rule of the problem,
/// `quadrature_points`). Element-major; a tensor holds its 9 components row by row (xx, xy, xz,
/// yx, yy, yz, zx, zy, zz), the stresses made exactly symmetric (σ + σᵀ)/2.
struct CellFields {
  std::vector<double> stress;            ///< total Cauchy stress σ = σ_eff − p I [MPa], 9 each
  std::vector<double> effective_stress;  ///< σ_eff = J⁻¹ P_eff Fᵀ [MPa], 9 each
  std::vector<double> J;                 ///< det F [-], 1 each (the mean is v_e / V_e)
  std::vector<double> flux;  ///< Darcy flux w = −k(J) ∇ₓp relative to the solid [mm/s], 3 each
  std::vector<double> permeability;  ///< k(J) [mm⁴ N⁻¹ s⁻¹], 1 each
};

/// The cell fields of the state `y` (the problem's unknowns: displacement, then pressure).
/// F = I + ∇₀u and ∇ₓp = F⁻ᵀ∇₀p at each point; the laws are chosen once per element. The flux
/// is Darcy's alone: the flux perturbation's −β∇ₓṗ (stabilisation.type = "flux_perturbation")
/// is not in it. Elements run in parallel (OpenMP), each written by one thread: the values do
/// not depend on the number of threads. Throws InvertedElement naming the element if det F ≤ 0
/// at a point or the permeability law refuses J there.
CellFields recover_cell_fields(const BiphasicProblem& problem, const double* y);

}  // namespace biphasic
