#include "biphasic/study/field_error.hpp"

#include <cmath>

#include "biphasic/physics/element_geometry.hpp"

namespace biphasic {

FieldErrors l2_errors(const BiphasicProblem& problem, const double* y, const VectorField& u,
                      const ScalarField& p, double t, int quadrature_points) {
  const Mesh& mesh = problem.mesh();
  const SparsityPattern& pattern = problem.pattern();
  const QuadratureRule rule = tet_quadrature(quadrature_points);
  std::vector<Eigen::Matrix<double, 10, 1>> N;
  for (const QuadraturePoint& qp : rule.points) N.push_back(p2_values(qp.xi));
  std::vector<PointGeometry> geometry;
  double eu = 0.0, ep = 0.0, nu = 0.0, np = 0.0;
  for (const Tet10& tet : mesh.tets) {
    Eigen::Matrix<double, 10, 3> X, U;
    Eigen::Vector4d P;
    for (int a = 0; a < 10; ++a)
      for (int c = 0; c < 3; ++c) {
        X(a, c) = mesh.nodes[tet[a]][c];
        U(a, c) = y[pattern.u_dof(tet[a], c)];
      }
    for (int c = 0; c < 4; ++c) P(c) = y[pattern.p_dof(tet[c])];
    element_point_geometry(X, rule, geometry);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const Vec3 Xq = X.transpose() * N[q];
      const Vec3 uq = u(Xq, t);
      const double pq = p(Xq, t);
      const double w = geometry[q].weight;
      eu += w * (U.transpose() * N[q] - uq).squaredNorm();
      ep += w * std::pow(geometry[q].Np.dot(P) - pq, 2);
      nu += w * uq.squaredNorm();
      np += w * pq * pq;
    }
  }
  return {std::sqrt(eu), std::sqrt(ep), std::sqrt(nu), std::sqrt(np)};
}

}  // namespace biphasic
