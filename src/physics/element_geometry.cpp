#include "biphasic/physics/element_geometry.hpp"

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

namespace biphasic {

void element_point_geometry(const Eigen::Matrix<double, 10, 3>& X, const QuadratureRule& rule,
                            std::vector<PointGeometry>& out) {
  out.resize(rule.points.size());
  const Eigen::Matrix<double, 4, 3> dLdxi = p1_gradients();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const auto& qp = rule.points[q];
    const Eigen::Matrix<double, 10, 3> dNdxi = p2_gradients(qp.xi);
    const Mat3 J0 = X.transpose() * dNdxi;  // ∂X_i/∂ξ_j
    const double det = J0.determinant();
    if (!(det > 0.0)) {
      throw std::domain_error("isoparametric map with det(dX/dxi) = " + std::to_string(det));
    }
    const Mat3 J0inv = J0.inverse();
    out[q].dN = dNdxi * J0inv;
    out[q].dNp = dLdxi * J0inv;
    out[q].Np = p1_values(qp.xi);
    out[q].weight = qp.weight * det;
  }
}

}  // namespace biphasic
