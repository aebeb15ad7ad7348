// Reference shape functions of the Taylor–Hood P2/P1 tetrahedron and the P2 triangle.
// Barycentric coordinates L₀ = 1 − ξ₁ − ξ₂ − ξ₃, L₁ = ξ₁, L₂ = ξ₂, L₃ = ξ₃.
#pragma once

#include <Eigen/Core>
#include <array>

namespace biphasic {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// P2 values at ξ in the local order of mesh.hpp: vertices Lᵢ(2Lᵢ − 1), edges 4 Lᵢ Lⱼ.
Eigen::Matrix<double, 10, 1> p2_values(const std::array<double, 3>& xi);
/// P2 gradients ∂N_a/∂ξ_j (row a).
Eigen::Matrix<double, 10, 3> p2_gradients(const std::array<double, 3>& xi);
/// P1 values (the barycentric coordinates).
Eigen::Vector4d p1_values(const std::array<double, 3>& xi);
/// P1 gradients ∂L_a/∂ξ_j (constant).
Eigen::Matrix<double, 4, 3> p1_gradients();

/// 6-node triangle on {η ≥ 0, η₁ + η₂ ≤ 1}: values and gradients ∂N/∂η (local order of mesh.hpp).
Eigen::Matrix<double, 6, 1> tri6_values(const std::array<double, 2>& eta);
Eigen::Matrix<double, 6, 2> tri6_gradients(const std::array<double, 2>& eta);
/// Linear triangle values (1 − η₁ − η₂, η₁, η₂).
Eigen::Vector3d tri3_values(const std::array<double, 2>& eta);

struct TriangleQuadraturePoint {
  std::array<double, 2> eta;
  double weight;  ///< weights sum to 1/2
};
/// Six-point rule on the reference triangle, exact for degree 4.
const std::array<TriangleQuadraturePoint, 6>& triangle_quadrature();

}  // namespace biphasic
