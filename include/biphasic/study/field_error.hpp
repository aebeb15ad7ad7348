// Errors of a computed state against exact fields, integrated over the mesh (verification).
#pragma once

#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic {

/// L² norms over Ω₀ (the field's unit times mm^{3/2}).
struct FieldErrors {
  double displacement = 0.0;       ///< ‖u_h − u‖
  double pressure = 0.0;           ///< ‖p_h − p‖
  double displacement_norm = 0.0;  ///< ‖u‖, to make the error relative
  double pressure_norm = 0.0;      ///< ‖p‖
};

/// ‖u_h − u(·, t)‖ and ‖p_h − p(·, t)‖ of the state y (the problem's unknown layout): u_h
/// interpolated with the P2 shape functions, p_h with the P1 ones, on the isoparametric map of
/// each element, integrated with the `quadrature_points` rule of tet_quadrature (default 64
/// points, degree 7).
FieldErrors l2_errors(const BiphasicProblem& problem, const double* y, const VectorField& u,
                      const ScalarField& p, double t, int quadrature_points = 64);

}  // namespace biphasic
