// Finite-difference checks of the element Jacobians dR/dy and dR/dẏ, block by block.
#include <gtest/gtest.h>

#include <string>

#include "biphasic/fe/quadrature.hpp"
#include "biphasic/physics/element_geometry.hpp"
#include "element_fixture.hpp"

namespace biphasic {
namespace {

struct Block {
  const char* name;
  int r0, nr, c0, nc;
};
const Block kBlocks[] = {
    {"u-u", 0, 30, 0, 30}, {"u-p", 0, 30, 30, 4}, {"p-u", 30, 4, 0, 30}, {"p-p", 30, 4, 30, 4}};

/// Central-difference Jacobian of the residual with respect to y (wrt_rate = false) or ẏ.
ElementMatrix central_difference(const std::vector<PointGeometry>& geo, const ElementParameters& p,
                                 const ElementVector& y, const ElementVector& ydot, bool wrt_rate,
                                 double eps) {
  ElementMatrix D;
  ElementOutput plus, minus;
  for (int j = 0; j < kElementDofs; ++j) {
    ElementVector yp = y, ym = y, vp = ydot, vm = ydot;
    (wrt_rate ? vp : yp)(j) += eps;
    (wrt_rate ? vm : ym)(j) -= eps;
    biphasic_element(geo, p, yp, vp, false, plus);
    biphasic_element(geo, p, ym, vm, false, minus);
    D.col(j) = (plus.residual - minus.residual) / (2.0 * eps);
  }
  return D;
}

/// GLS coefficient c_e, flux-perturbation β, the Δt of the conservative volume rate
/// J̇ = (J − Jₙ)/Δt (0: the incremental J̇ = J F⁻ᵀ:∇₀u̇), and the offsets of the need-following
/// coefficients (ElementCoefficients).
struct Stabilisations {
  double gls_c = 0.0;
  double flux_beta = 0.0;
  double volume_rate_dt = 0.0;
  const char* name = "";
  double gls_offset = 0.0;
  double flux_offset = 0.0;
  friend void PrintTo(const Stabilisations& s, std::ostream* os) { *os << s.name; }
};
class ElementJacobian : public ::testing::TestWithParam<Stabilisations> {};

// For each block: the central-difference error falls as ε² (ratio ≈ 4 per halving), or is
// already at round-off because the residual is linear in those unknowns.
TEST_P(ElementJacobian, MatchesCentralDifferencesBlockByBlock) {
  std::vector<PointGeometry> geo;
  element_point_geometry(test::distorted_tet(), tet_quadrature(4), geo);
  ElementParameters p;
  p.material = {0.2, 0.5};
  p.permeability = 1e-2;
  p.gls_c = GetParam().gls_c;
  p.flux_beta = GetParam().flux_beta;
  p.gls_offset = GetParam().gls_offset;
  p.flux_offset = GetParam().flux_offset;
  p.volume_rate_dt = GetParam().volume_rate_dt;
  ElementVector y, ydot;
  test::random_state(7, 0.08, y, ydot);
  ElementOutput exact;
  biphasic_element(geo, p, y, ydot, true, exact);

  for (bool wrt_rate : {false, true}) {
    const ElementMatrix& A = wrt_rate ? exact.dfdydot : exact.dfdy;
    const double eps = 1e-3;
    const ElementMatrix E1 = central_difference(geo, p, y, ydot, wrt_rate, eps) - A;
    const ElementMatrix E2 = central_difference(geo, p, y, ydot, wrt_rate, eps / 2) - A;
    for (const Block& b : kBlocks) {
      const double scale = std::max(1e-12, A.block(b.r0, b.c0, b.nr, b.nc).norm());
      const double e1 = E1.block(b.r0, b.c0, b.nr, b.nc).norm() / scale;
      const double e2 = E2.block(b.r0, b.c0, b.nr, b.nc).norm() / scale;
      const std::string what = std::string(wrt_rate ? "dR/dydot " : "dR/dy ") + b.name;
      EXPECT_LT(e2, 1e-5) << what;
      if (e1 > 1e-9) {
        EXPECT_NEAR(e1 / e2, 4.0, 0.4) << what << " e1=" << e1 << " e2=" << e2;
      }
    }
  }
}

// Combined matrix of backward Euler: d/dy F(y, (y − yₙ)/Δt) = dF/dy + (1/Δt) dF/dẏ.
TEST_P(ElementJacobian, BackwardEulerCombinationMatchesDifferences) {
  std::vector<PointGeometry> geo;
  element_point_geometry(test::distorted_tet(), tet_quadrature(4), geo);
  ElementParameters p;
  p.permeability = 1e-3;
  p.gls_c = GetParam().gls_c;
  p.flux_beta = GetParam().flux_beta;
  p.gls_offset = GetParam().gls_offset;
  p.flux_offset = GetParam().flux_offset;
  ElementVector y, ydot, y_old;
  test::random_state(11, 0.05, y, ydot);
  test::random_state(12, 0.05, y_old, ydot);
  const double dt = 0.7;
  if (GetParam().volume_rate_dt > 0.0) p.volume_rate_dt = dt;  // as the integrator sets it
  auto residual = [&](const ElementVector& yy) {
    ElementOutput o;
    biphasic_element(geo, p, yy, (yy - y_old) / dt, false, o);
    return ElementVector(o.residual);
  };
  ElementOutput exact;
  biphasic_element(geo, p, y, (y - y_old) / dt, true, exact);
  const ElementMatrix A = exact.dfdy + exact.dfdydot / dt;
  ElementMatrix D;
  const double eps = 1e-4;
  for (int j = 0; j < kElementDofs; ++j) {
    ElementVector yp = y, ym = y;
    yp(j) += eps;
    ym(j) -= eps;
    D.col(j) = (residual(yp) - residual(ym)) / (2 * eps);
  }
  EXPECT_LT((D - A).norm() / A.norm(), 1e-7);
}

// The conservative cases use Δt = 5 s: uₙ = u − Δt u̇ is then a second, distinct deformed state
// (|Δt u̇| up to 0.05 against displacements of 0.08), so Jₙ bₙ and J b differ.
INSTANTIATE_TEST_SUITE_P(
    Stabilisations, ElementJacobian,
    ::testing::Values(Stabilisations{0.0, 0.0, 0.0, "plain"}, Stabilisations{2.5, 0.0, 0.0, "gls"},
                      Stabilisations{0.0, 0.35, 0.0, "flux_perturbation"},
                      Stabilisations{0.0, 0.0, 5.0, "plain_conservative"},
                      Stabilisations{2.5, 0.0, 5.0, "gls_conservative"},
                      // need-following: c_e = 2.5 − 1, β = 0.35 − 10 k
                      Stabilisations{2.5, 0.0, 0.0, "gls_minimal", 1.0},
                      Stabilisations{2.5, 0.0, 5.0, "gls_minimal_conservative", 1.0},
                      Stabilisations{0.0, 0.35, 0.0, "flux_perturbation_minimal", 0.0, 10.0}),
    [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace biphasic

namespace biphasic {
namespace {

/// The element with the GLS term at the centroid alone (stabilisation.gls_quadrature =
/// "one_point") and with its full 4-point rule.
struct OnePointGlsElement {
  std::vector<PointGeometry> geo;
  PointGeometry centroid;
  ElementParameters p;
  explicit OnePointGlsElement(const Eigen::Matrix<double, 10, 3>& X, double gls_offset = 0.0) {
    element_point_geometry(X, tet_quadrature(4), geo);
    std::vector<PointGeometry> one;
    element_point_geometry(X, tet_quadrature(1), one);
    centroid = one.front();
    p.material = {0.2, 0.5};
    p.permeability = 1e-2;
    p.gls_c = 2.5;
    p.gls_offset = gls_offset;
  }
  ElementOutput evaluate(const ElementVector& y, const ElementVector& ydot, bool jacobian,
                         bool one_point) const {
    ElementOutput out;
    biphasic_element(geo, p.material, ConstantPermeability{p.permeability}, p, y, ydot, jacobian,
                     out, one_point ? &centroid : nullptr);
    return out;
  }
};

// dR/dy and dR/dẏ of the one-point GLS element against central differences (ε and ε/2), with
// the incremental and the conservative volume rate and with a need-following offset.
TEST(OnePointGls, JacobianMatchesCentralDifferences) {
  for (const double offset : {0.0, 1.0})
    for (const double rate_dt : {0.0, 5.0}) {
      OnePointGlsElement element(test::distorted_tet(), offset);
      element.p.volume_rate_dt = rate_dt;
      ElementVector y, ydot;
      test::random_state(7, 0.08, y, ydot);
      const ElementOutput exact = element.evaluate(y, ydot, true, true);
      for (bool wrt_rate : {false, true}) {
        auto difference = [&](double eps) {
          ElementMatrix D;
          for (int j = 0; j < kElementDofs; ++j) {
            ElementVector yp = y, ym = y, vp = ydot, vm = ydot;
            (wrt_rate ? vp : yp)(j) += eps;
            (wrt_rate ? vm : ym)(j) -= eps;
            D.col(j) = (element.evaluate(yp, vp, false, true).residual -
                        element.evaluate(ym, vm, false, true).residual) /
                       (2.0 * eps);
          }
          return D;
        };
        const ElementMatrix& A = wrt_rate ? exact.dfdydot : exact.dfdy;
        const double e1 = (difference(1e-3) - A).norm() / A.norm();
        const double e2 = (difference(5e-4) - A).norm() / A.norm();
        EXPECT_LT(e2, 1e-6) << "offset " << offset << ", rate dt " << rate_dt << ", "
                            << (wrt_rate ? "dR/dydot" : "dR/dy");
        if (e1 > 1e-9) {
          EXPECT_NEAR(e1 / e2, 4.0, 0.4) << "offset " << offset << ", rate dt " << rate_dt;
        }
      }
    }
}

// Under an affine motion of a straight-sided element F, J and J̇ are constant and ∇₀N of the P2
// functions is linear in X: the GLS rows' integrand c_e J̇ (F⁻ᵀ : ∇₀f) is linear, and the
// one-point rule integrates it exactly (its Jacobian, a product of two such gradients, is not).
// On a general state the two rules differ, and the other rows are untouched by the choice.
TEST(OnePointGls, ExactForAnAffineMotionOfAStraightElement) {
  Eigen::Matrix<double, 10, 3> X;
  const Eigen::Matrix<double, 4, 3> corners =
      (Eigen::Matrix<double, 4, 3>() << 0, 0, 0, 1.1, 0.1, 0, 0.2, 0.9, 0.1, 0.1, 0.3, 1.2)
          .finished();
  const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  X.topRows<4>() = corners;
  for (int m = 0; m < 6; ++m)
    X.row(4 + m) = 0.5 * (corners.row(edges[m][0]) + corners.row(edges[m][1]));
  OnePointGlsElement element(X);
  // u = G X (affine), u̇ = Ġ X, p quadratic-free (P1, any values).
  Mat3 G, Gdot;
  G << -0.02, 0.01, 0.0, 0.005, -0.03, 0.01, 0.0, 0.02, -0.05;
  Gdot << -0.002, 0.0, 0.001, 0.0, -0.001, 0.0, 0.001, 0.0, -0.004;
  ElementVector y = ElementVector::Zero(), ydot = ElementVector::Zero();
  for (int a = 0; a < 10; ++a) {
    y.segment<3>(3 * a) = G * X.row(a).transpose();
    ydot.segment<3>(3 * a) = Gdot * X.row(a).transpose();
  }
  y.tail<4>() << 0.01, 0.02, -0.01, 0.005;
  const ElementOutput full = element.evaluate(y, ydot, false, false);
  const ElementOutput one = element.evaluate(y, ydot, false, true);
  ASSERT_GT(full.residual.head<30>().norm(), 0.0);
  EXPECT_LT((one.residual - full.residual).norm(), 1e-13 * full.residual.norm());
  // A non-affine state: the GLS rows differ, the mass rows do not.
  ElementVector y2, ydot2;
  test::random_state(7, 0.08, y2, ydot2);
  const ElementOutput full2 = element.evaluate(y2, ydot2, false, false);
  const ElementOutput one2 = element.evaluate(y2, ydot2, false, true);
  EXPECT_GT((one2.residual.head<30>() - full2.residual.head<30>()).norm(),
            1e-6 * full2.residual.head<30>().norm());
  EXPECT_EQ(one2.residual.tail<4>(), full2.residual.tail<4>());
}

}  // namespace
}  // namespace biphasic
