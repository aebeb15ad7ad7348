// Integrals over a 6-node (isoparametric) boundary triangle with nodes X (6 × 3, mm),
// in the reference configuration: the consistent nodal loads of dead tractions and fluxes.
#pragma once

#include <Eigen/Core>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

/// ∫ N_a dA for the six P2 functions [mm²].
Eigen::Matrix<double, 6, 1> face_p2_integrals(const Eigen::Matrix<double, 6, 3>& X);
/// ∫ L_c dA for the three P1 functions on the corners [mm²].
Eigen::Vector3d face_p1_integrals(const Eigen::Matrix<double, 6, 3>& X);
/// ∫ N_a N dA, N the unit normal pointing away from `inward` (a vector from the face into
/// the body) [mm²].
Eigen::Matrix<double, 6, 3> face_normal_integrals(const Eigen::Matrix<double, 6, 3>& X,
                                                  const Vec3& inward);

}  // namespace biphasic
