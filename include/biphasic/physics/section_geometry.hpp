// Per-element, per-quadrature-point reference data of the isoparametric P2/P1 triangle of a
// two-dimensional model (docs/two_dimensional_models.md).
//
// Plane strain: the section (x, y) of a body long in z, u_z = 0, ∂/∂z = 0; integrals are per
// unit thickness, dΩ₀ = dX dY (1 mm deep). Axisymmetric: the meridian section (r, z) of a body
// of revolution, u_θ = 0, ∂/∂θ = 0; F gains the hoop stretch F_θΘ = 1 + u_r/R and integrals are
// over the full circle, dΩ₀ = 2π R dR dZ.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

/// The kinematics of a two-dimensional model.
enum class SectionModel {
  PlaneStrain,   ///< (x, y); F_zz = 1
  Axisymmetric,  ///< (r, z); F_θΘ = 1 + u_r/R
};

/// Case-file name of the model: "plane_strain" or "axisymmetric".
std::string to_string(SectionModel model);

/// Reference-configuration data at one quadrature point of a 6-node triangle.
struct SectionPointGeometry {
  Eigen::Matrix<double, 6, 2> dN;   ///< ∇₀N_a (P2) [1/mm]
  Eigen::Matrix<double, 6, 1> N;    ///< P2 values (the hoop term u_r/R needs them)
  Eigen::Matrix<double, 3, 2> dNp;  ///< ∇₀N^p_c (P1) [1/mm]
  Eigen::Vector3d Np;               ///< P1 values
  /// 1/R at the point [1/mm] (axisymmetric; 0 for plane strain: no hoop term).
  double inverse_radius = 0.0;
  /// Quadrature weight × det(∂X/∂η) × (2πR for axisymmetric, 1 mm for plane strain) [mm³].
  double weight = 0.0;
};

/// The quadrature-point data of one triangle with reference nodes X (6 × 2, mm) on the
/// six-point rule of degree 4. Throws std::domain_error if the isoparametric map is not
/// invertible at a point, or (axisymmetric) a point lies at R ≤ 0.
void section_point_geometry(const Eigen::Matrix<double, 6, 2>& X, SectionModel model,
                            std::vector<SectionPointGeometry>& out);

}  // namespace biphasic
