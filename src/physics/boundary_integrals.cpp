#include "biphasic/physics/boundary_integrals.hpp"

#include <Eigen/Geometry>

namespace biphasic {

namespace {
/// Area vector (∂x/∂η₁ × ∂x/∂η₂) at a reference point.
Vec3 area_vector(const Eigen::Matrix<double, 6, 3>& X, const std::array<double, 2>& eta) {
  const Eigen::Matrix<double, 3, 2> T = X.transpose() * tri6_gradients(eta);
  return Vec3(T.col(0)).cross(Vec3(T.col(1)));
}
}  // namespace

Eigen::Matrix<double, 6, 1> face_p2_integrals(const Eigen::Matrix<double, 6, 3>& X) {
  Eigen::Matrix<double, 6, 1> r = Eigen::Matrix<double, 6, 1>::Zero();
  for (const auto& q : triangle_quadrature())
    r += q.weight * area_vector(X, q.eta).norm() * tri6_values(q.eta);
  return r;
}

Eigen::Vector3d face_p1_integrals(const Eigen::Matrix<double, 6, 3>& X) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (const auto& q : triangle_quadrature())
    r += q.weight * area_vector(X, q.eta).norm() * tri3_values(q.eta);
  return r;
}

Eigen::Matrix<double, 6, 3> face_normal_integrals(const Eigen::Matrix<double, 6, 3>& X,
                                                  const Vec3& inward) {
  Eigen::Matrix<double, 6, 3> r = Eigen::Matrix<double, 6, 3>::Zero();
  for (const auto& q : triangle_quadrature()) {
    Vec3 a = area_vector(X, q.eta);
    if (a.dot(inward) > 0.0) a = -a;
    r += q.weight * tri6_values(q.eta) * a.transpose();
  }
  return r;
}

}  // namespace biphasic
