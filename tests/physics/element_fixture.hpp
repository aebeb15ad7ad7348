// A distorted P2 tetrahedron and a finitely deformed state for element-level tests.
#pragma once

#include <random>
#include <vector>

#include "biphasic/fe/quadrature.hpp"
#include "biphasic/physics/biphasic_element.hpp"
#include "biphasic/physics/element_geometry.hpp"

namespace biphasic::test {

/// Reference nodes of a distorted straight-sided P2 tetrahedron with slightly curved edges [mm].
inline Eigen::Matrix<double, 10, 3> distorted_tet() {
  Eigen::Matrix<double, 4, 3> V;
  V << 0.1, -0.2, 0.05, 1.3, 0.1, -0.1, 0.2, 1.1, 0.15, 0.3, 0.25, 0.9;
  Eigen::Matrix<double, 10, 3> X;
  X.topRows<4>() = V;
  const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  for (int e = 0; e < 6; ++e) X.row(4 + e) = 0.5 * (V.row(edges[e][0]) + V.row(edges[e][1]));
  X(5, 2) += 0.03;  // curve one edge
  X(8, 0) -= 0.02;
  return X;
}

/// Reference geometry of distorted_tet() at the points of the 4-point rule.
inline std::vector<PointGeometry> distorted_tet_geometry() {
  std::vector<PointGeometry> geo;
  element_point_geometry(distorted_tet(), tet_quadrature(4), geo);
  return geo;
}

/// A random state with strains of order `amplitude`, pressures of order 0.1 MPa.
inline void random_state(unsigned seed, double amplitude, ElementVector& y, ElementVector& ydot) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (int i = 0; i < 30; ++i) y(i) = amplitude * d(gen);
  for (int i = 30; i < 34; ++i) y(i) = 0.1 * d(gen);
  for (int i = 0; i < 34; ++i) ydot(i) = 0.01 * d(gen);
}

}  // namespace biphasic::test
