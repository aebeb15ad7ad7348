// P2/P1 reference functions: nodal interpolation, partition of unity, gradients.
#include <gtest/gtest.h>

#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/mesh/mesh.hpp"

namespace biphasic {
namespace {

std::array<std::array<double, 3>, 10> reference_nodes() {
  const std::array<double, 3> v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::array<std::array<double, 3>, 10> x{};
  for (int a = 0; a < 4; ++a) x[a] = v[a];
  for (int e = 0; e < 6; ++e)
    for (int c = 0; c < 3; ++c) x[4 + e][c] = 0.5 * (v[kTetEdges[e][0]][c] + v[kTetEdges[e][1]][c]);
  return x;
}

TEST(ShapeFunctions, P2IsNodal) {
  const auto x = reference_nodes();
  for (int b = 0; b < 10; ++b) {
    const auto N = p2_values(x[b]);
    for (int a = 0; a < 10; ++a) EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15);
  }
}

TEST(ShapeFunctions, GradientsMatchDifferences) {
  const std::array<double, 3> xi{0.21, 0.17, 0.33};
  const auto G = p2_gradients(xi);
  for (int j = 0; j < 3; ++j) {
    auto p = xi, m = xi;
    p[j] += 1e-6;
    m[j] -= 1e-6;
    const Eigen::Matrix<double, 10, 1> fd = (p2_values(p) - p2_values(m)) / 2e-6;
    EXPECT_LT((fd - G.col(j)).norm(), 1e-9);
  }
  EXPECT_LT(G.colwise().sum().norm(), 1e-14);  // Σ ∇N_a = 0
  EXPECT_NEAR(p1_values(xi).sum(), 1.0, 1e-15);
}

TEST(ShapeFunctions, Tri6IsNodalAndGradientsConsistent) {
  const std::array<double, 2> x[6] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (int b = 0; b < 6; ++b) {
    const auto N = tri6_values(x[b]);
    for (int a = 0; a < 6; ++a) EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15);
  }
  const std::array<double, 2> eta{0.3, 0.2};
  const auto G = tri6_gradients(eta);
  for (int j = 0; j < 2; ++j) {
    auto p = eta, m = eta;
    p[j] += 1e-6;
    m[j] -= 1e-6;
    EXPECT_LT(((tri6_values(p) - tri6_values(m)) / 2e-6 - G.col(j)).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace biphasic
