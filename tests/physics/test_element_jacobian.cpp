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

/// GLS coefficient c_e, flux-perturbation β, and the Δt of the conservative volume rate
/// J̇ = (J − Jₙ)/Δt (0: the incremental J̇ = J F⁻ᵀ:∇₀u̇).
struct Stabilisations {
  double gls_c = 0.0;
  double flux_beta = 0.0;
  double volume_rate_dt = 0.0;
  const char* name = "";
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
INSTANTIATE_TEST_SUITE_P(Stabilisations, ElementJacobian,
                         ::testing::Values(Stabilisations{0.0, 0.0, 0.0, "plain"},
                                           Stabilisations{2.5, 0.0, 0.0, "gls"},
                                           Stabilisations{0.0, 0.35, 0.0, "flux_perturbation"},
                                           Stabilisations{0.0, 0.0, 5.0, "plain_conservative"},
                                           Stabilisations{2.5, 0.0, 5.0, "gls_conservative"}),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace biphasic
