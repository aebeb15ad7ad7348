// Per-element, per-quadrature-point reference data of the isoparametric P2 tetrahedron.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "biphasic/fe/quadrature.hpp"
#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

/// Reference-configuration data at one quadrature point.
struct PointGeometry {
  Eigen::Matrix<double, 10, 3> dN;  ///< ∇₀N_a (P2) [1/mm]
  Eigen::Matrix<double, 4, 3> dNp;  ///< ∇₀N^p_c (P1) [1/mm]
  Eigen::Vector4d Np;               ///< P1 values
  double weight;                    ///< quadrature weight × det(∂X/∂ξ) [mm³]
};

/// The quadrature-point data of one element with reference nodes X (10 × 3, mm).
/// Throws std::domain_error if the isoparametric map is not invertible at a point.
void element_point_geometry(const Eigen::Matrix<double, 10, 3>& X, const QuadratureRule& rule,
                            std::vector<PointGeometry>& out);

}  // namespace biphasic
