// The two backward-Euler volume rates: incremental J̇ = J F⁻ᵀ:∇₀(u − uₙ)/Δt and conservative
// J̇ = (J − Jₙ)/Δt. The conservative mass rows telescope to the volume change.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "biphasic/fe/quadrature.hpp"
#include "biphasic/fe/shape_functions.hpp"
#include "element_fixture.hpp"

namespace biphasic {
namespace {

/// ∫Ω₀ J dX = ∫ dx of the element whose nodes sit at x = X + u [mm³], from the isoparametric
/// map of the deformed nodes alone (4-point rule, as the kernel).
double deformed_volume(const Eigen::Matrix<double, 10, 3>& X, const ElementVector& y) {
  Eigen::Matrix<double, 10, 3> x = X;
  for (int a = 0; a < 10; ++a) x.row(a) += y.segment<3>(3 * a).transpose();
  double volume = 0.0;
  for (const auto& q : tet_quadrature(4).points)
    volume += q.weight * (x.transpose() * p2_gradients(q.xi)).determinant();
  return volume;
}

/// Σₙ Δtₙ Σ_c R_p,c over a sequence of backward-Euler steps of one element [mm³].
double summed_mass_rows(const std::vector<PointGeometry>& geo, ElementParameters p,
                        const std::vector<ElementVector>& states, const std::vector<double>& dt,
                        bool conservative) {
  double sum = 0.0;
  for (std::size_t n = 1; n < states.size(); ++n) {
    p.volume_rate_dt = conservative ? dt[n - 1] : 0.0;
    const ElementVector ydot = (states[n] - states[n - 1]) / dt[n - 1];
    ElementOutput out;
    biphasic_element(geo, p, states[n], ydot, false, out);
    sum += dt[n - 1] * out.residual.tail<4>().sum();
  }
  return sum;
}

// Σ_c N^p_c = 1 removes the Darcy term from the sum of the mass rows, which is then ∫ J̇ dX;
// with J̇ = (J − Jₙ)/Δt the steps telescope to ∫(J_end − J_0) dX.
TEST(VolumeRate, ConservativeMassRowsTelescopeToTheVolumeChange) {
  const Eigen::Matrix<double, 10, 3> X = test::distorted_tet();
  std::vector<PointGeometry> geo;
  element_point_geometry(X, tet_quadrature(4), geo);
  ElementParameters p;
  p.material = {0.2, 0.5};
  p.permeability = 1e-2;
  p.gls_c = 2.5;  // the GLS term lives in the momentum rows: no effect on the balance
  std::vector<ElementVector> states(1);
  ElementVector rate;
  test::random_state(21, 0.06, states[0], rate);
  const std::vector<double> dt{0.3, 1.1, 2.0, 0.05, 0.7, 1.6};
  for (std::size_t n = 0; n < dt.size(); ++n) {
    ElementVector increment;
    test::random_state(30 + static_cast<unsigned>(n), 0.03, increment, rate);
    states.push_back(states.back() + increment);  // pressures change too
  }
  const double expected = deformed_volume(X, states.back()) - deformed_volume(X, states.front());
  ASSERT_GT(std::abs(expected), 1e-3);  // a real volume change [mm³]

  const double conservative = summed_mass_rows(geo, p, states, dt, true);
  EXPECT_LT(std::abs(conservative - expected), 1e-12 * std::abs(expected))
      << conservative << " vs " << expected;
  // The incremental form misses the second-order part of each step's volume change.
  const double incremental = summed_mass_rows(geo, p, states, dt, false);
  EXPECT_GT(std::abs(incremental - expected), 1e-4 * std::abs(expected))
      << incremental << " vs " << expected;
}

}  // namespace
}  // namespace biphasic
