#include "biphasic/physics/section_geometry.hpp"

#include <Eigen/Dense>
#include <numbers>
#include <stdexcept>
#include <string>

namespace biphasic {

std::string to_string(SectionModel model) {
  return model == SectionModel::Axisymmetric ? "axisymmetric" : "plane_strain";
}

void section_point_geometry(const Eigen::Matrix<double, 6, 2>& X, SectionModel model,
                            std::vector<SectionPointGeometry>& out) {
  const auto& rule = triangle_quadrature();
  out.resize(rule.size());
  Eigen::Matrix<double, 3, 2> dLdeta;
  dLdeta << -1, -1, 1, 0, 0, 1;
  for (std::size_t q = 0; q < rule.size(); ++q) {
    const auto& qp = rule[q];
    const Eigen::Matrix<double, 6, 2> dNdeta = tri6_gradients(qp.eta);
    const Eigen::Matrix2d J0 = X.transpose() * dNdeta;  // ∂X_i/∂η_j
    const double det = J0.determinant();
    if (!(det > 0.0))
      throw std::domain_error("isoparametric map with det(dX/deta) = " + std::to_string(det));
    const Eigen::Matrix2d J0inv = J0.inverse();
    SectionPointGeometry& g = out[q];
    g.dN = dNdeta * J0inv;
    g.dNp = dLdeta * J0inv;
    g.N = tri6_values(qp.eta);
    g.Np = tri3_values(qp.eta);
    g.weight = qp.weight * det;
    g.inverse_radius = 0.0;
    if (model == SectionModel::Axisymmetric) {
      const double R = g.N.dot(X.col(0));
      if (!(R > 0.0))
        throw std::domain_error("axisymmetric quadrature point at R = " + std::to_string(R) +
                                " mm: the section must lie in r >= 0");
      g.inverse_radius = 1.0 / R;
      g.weight *= 2.0 * std::numbers::pi * R;
    }
  }
}

}  // namespace biphasic
