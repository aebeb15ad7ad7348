// The semidiscrete GLS term under backward Euler is the paper's τ_GLS = h²/(4kΔt) term on
// the step's displacement increment: R_GLS = τ_GLS ∫Ω (divₓ f)(divₓ Δu) dv.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "../common/box_mesh.hpp"
#include "biphasic/fe/quadrature.hpp"
#include "biphasic/fe/tet_geometry.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "element_fixture.hpp"

namespace biphasic {
namespace {

/// τ ∫Ω (divₓ N_a e_i)(divₓ Δu) dv computed on the current configuration x = X + u.
Eigen::Matrix<double, 30, 1> paper_gls_residual(const Eigen::Matrix<double, 10, 3>& X,
                                                const Eigen::Matrix<double, 10, 3>& u,
                                                const Eigen::Matrix<double, 10, 3>& du,
                                                double tau) {
  Eigen::Matrix<double, 30, 1> r = Eigen::Matrix<double, 30, 1>::Zero();
  const Eigen::Matrix<double, 10, 3> x = X + u;
  for (const auto& q : tet_quadrature(4).points) {
    const Eigen::Matrix<double, 10, 3> dNdxi = p2_gradients(q.xi);
    const Mat3 jac = x.transpose() * dNdxi;  // ∂x/∂ξ
    const Eigen::Matrix<double, 10, 3> dNdx = dNdxi * jac.inverse();
    const double div_du = (dNdx.cwiseProduct(du)).sum();
    const double dv = q.weight * jac.determinant();
    for (int a = 0; a < 10; ++a)
      for (int i = 0; i < 3; ++i) r(3 * a + i) += tau * dNdx(a, i) * div_du * dv;
  }
  return r;
}

Eigen::Matrix<double, 10, 3> as_nodes(const ElementVector& y) {
  Eigen::Matrix<double, 10, 3> m;
  for (int a = 0; a < 10; ++a) m.row(a) = y.segment<3>(3 * a).transpose();
  return m;
}

TEST(Gls, BackwardEulerResidualIsPaperTermOnIncrement) {
  const Eigen::Matrix<double, 10, 3> X = test::distorted_tet();
  std::vector<PointGeometry> geo;
  element_point_geometry(X, tet_quadrature(4), geo);
  const TetCorners c{X.row(0).transpose(), X.row(1).transpose(), X.row(2).transpose(),
                     X.row(3).transpose()};
  const double h = tet_circumradius(c), k = 1e-3, dt = 6.4;
  ElementParameters with, without;
  with.permeability = without.permeability = k;
  with.gls_c = h * h / (4 * k);
  ElementVector y, y_old, ignored;
  test::random_state(3, 0.06, y, ignored);
  test::random_state(4, 0.06, y_old, ignored);
  y_old.tail<4>() = y.tail<4>();
  const ElementVector ydot = (y - y_old) / dt;
  ElementOutput a, b;
  biphasic_element(geo, with, y, ydot, true, a);
  biphasic_element(geo, without, y, ydot, true, b);
  const Eigen::Matrix<double, 30, 1> expected =
      paper_gls_residual(X, as_nodes(y), as_nodes(y - y_old), h * h / (4 * k * dt));
  const Eigen::Matrix<double, 30, 1> gls = (a.residual - b.residual).head<30>();
  EXPECT_LT((gls - expected).norm(), 1e-12 * expected.norm());
  EXPECT_GT(expected.norm(), 1e-6);  // the comparison is not between zeros
  // The mass rows are untouched.
  EXPECT_LT((a.residual - b.residual).tail<4>().norm(), 1e-15);
}

TEST(Gls, StiffnessFromRestIsPaperMatrix) {
  // K_GLS = τ ∫ (div N)ᵀ (div N) dv at u = uₙ = 0 (the paper's eq. K_GLS).
  const Eigen::Matrix<double, 10, 3> X = test::distorted_tet();
  std::vector<PointGeometry> geo;
  element_point_geometry(X, tet_quadrature(4), geo);
  const double ce = 0.37, dt = 3.2, tau = ce / dt;
  ElementParameters with, without;
  with.gls_c = ce;
  const ElementVector zero = ElementVector::Zero();
  ElementOutput a, b;
  biphasic_element(geo, with, zero, zero, true, a);
  biphasic_element(geo, without, zero, zero, true, b);
  const ElementMatrix K = (a.dfdy + a.dfdydot / dt) - (b.dfdy + b.dfdydot / dt);
  Eigen::Matrix<double, 30, 30> expected = Eigen::Matrix<double, 30, 30>::Zero();
  for (const auto& q : tet_quadrature(4).points) {
    const Eigen::Matrix<double, 10, 3> dNdxi = p2_gradients(q.xi);
    const Mat3 jac = X.transpose() * dNdxi;
    const Eigen::Matrix<double, 10, 3> dNdx = dNdxi * jac.inverse();
    Eigen::Matrix<double, 30, 1> divN;
    for (int a2 = 0; a2 < 10; ++a2)
      for (int i = 0; i < 3; ++i) divN(3 * a2 + i) = dNdx(a2, i);
    expected += tau * q.weight * jac.determinant() * divN * divN.transpose();
  }
  EXPECT_LT((K.topLeftCorner<30, 30>() - expected).norm(), 1e-12 * expected.norm());
}

TEST(Gls, CoefficientUsesCircumradiusAndPermeability) {
  const Mesh mesh = test::box_mesh({2, 1, 1}, {2.0, 1.0, 1.0});
  Config cfg;
  cfg.material.set("permeability", 5e-3);
  cfg.stabilisation.type = "gls";
  BiphasicProblem problem(mesh, cfg);
  for (Index e = 0; e < static_cast<Index>(mesh.tets.size()); ++e) {
    TetCorners c;
    for (int a = 0; a < 4; ++a)
      c[a] = Vec3(mesh.nodes[mesh.tets[e][a]][0], mesh.nodes[mesh.tets[e][a]][1],
                  mesh.nodes[mesh.tets[e][a]][2]);
    // Kuhn tetrahedra of a unit cube: circumsphere = the cube's, radius √3/2.
    EXPECT_NEAR(tet_circumradius(c), std::sqrt(3.0) / 2, 1e-12);
    EXPECT_NEAR(problem.gls_coefficient(e), 0.75 / (4 * 5e-3), 1e-9);
  }
}

}  // namespace
}  // namespace biphasic
