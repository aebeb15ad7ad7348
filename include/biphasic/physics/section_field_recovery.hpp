// Element fields of a two-dimensional model's state (plane strain or axisymmetric) for the
// field output: the counterpart of recover_cell_fields (field_recovery.hpp) on triangles.
#pragma once

#include "biphasic/physics/field_recovery.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {

/// The cell fields of the state `y` of a section problem (u: 2 per node, then p per vertex),
/// one value per triangle, each the mean over its quadrature points weighted by the model's
/// measure (dX dY, or 2πR dR dZ axisymmetric: Σ_q w_q f_q / Σ_q w_q as recover_cell_fields).
/// F is the section kernel's 3 × 3 gradient: F(2,2) = 1 in plane strain, the hoop stretch
/// 1 + u_r/R axisymmetric, so a stress's (2,2) entry is σ_zz (plane strain) or σ_θθ
/// (axisymmetric) [MPa]. The flux is (w_x, w_y, 0) or (w_r, w_z, 0) [mm/s]; Darcy's alone, as
/// in three dimensions. Tensors have 9 components row by row, made exactly symmetric. Throws
/// InvertedElement naming the triangle if det F ≤ 0 at a point or a law refuses J there.
CellFields recover_section_cell_fields(const SectionProblem& problem, const double* y);

}  // namespace biphasic
