#include "biphasic/fe/shape_functions.hpp"

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

namespace {
std::array<double, 4> barycentric(const std::array<double, 3>& xi) {
  return {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
}
}  // namespace

Eigen::Matrix<double, 10, 1> p2_values(const std::array<double, 3>& xi) {
  const auto L = barycentric(xi);
  Eigen::Matrix<double, 10, 1> N;
  for (int a = 0; a < 4; ++a) N(a) = L[a] * (2.0 * L[a] - 1.0);
  for (int e = 0; e < 6; ++e) N(4 + e) = 4.0 * L[kTetEdges[e][0]] * L[kTetEdges[e][1]];
  return N;
}

Eigen::Matrix<double, 4, 3> p1_gradients() {
  Eigen::Matrix<double, 4, 3> G;
  G << -1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return G;
}

Eigen::Matrix<double, 10, 3> p2_gradients(const std::array<double, 3>& xi) {
  const auto L = barycentric(xi);
  const Eigen::Matrix<double, 4, 3> dL = p1_gradients();
  Eigen::Matrix<double, 10, 3> G;
  for (int a = 0; a < 4; ++a) G.row(a) = (4.0 * L[a] - 1.0) * dL.row(a);
  for (int e = 0; e < 6; ++e) {
    const int i = kTetEdges[e][0], j = kTetEdges[e][1];
    G.row(4 + e) = 4.0 * (L[i] * dL.row(j) + L[j] * dL.row(i));
  }
  return G;
}

Eigen::Vector4d p1_values(const std::array<double, 3>& xi) {
  const auto L = barycentric(xi);
  return {L[0], L[1], L[2], L[3]};
}

Eigen::Matrix<double, 6, 1> tri6_values(const std::array<double, 2>& eta) {
  const double L[3] = {1.0 - eta[0] - eta[1], eta[0], eta[1]};
  Eigen::Matrix<double, 6, 1> N;
  for (int a = 0; a < 3; ++a) N(a) = L[a] * (2.0 * L[a] - 1.0);
  for (int e = 0; e < 3; ++e) N(3 + e) = 4.0 * L[kTriEdges[e][0]] * L[kTriEdges[e][1]];
  return N;
}

Eigen::Matrix<double, 6, 2> tri6_gradients(const std::array<double, 2>& eta) {
  const double L[3] = {1.0 - eta[0] - eta[1], eta[0], eta[1]};
  Eigen::Matrix<double, 3, 2> dL;
  dL << -1, -1, 1, 0, 0, 1;
  Eigen::Matrix<double, 6, 2> G;
  for (int a = 0; a < 3; ++a) G.row(a) = (4.0 * L[a] - 1.0) * dL.row(a);
  for (int e = 0; e < 3; ++e) {
    const int i = kTriEdges[e][0], j = kTriEdges[e][1];
    G.row(3 + e) = 4.0 * (L[i] * dL.row(j) + L[j] * dL.row(i));
  }
  return G;
}

Eigen::Vector3d tri3_values(const std::array<double, 2>& eta) {
  return {1.0 - eta[0] - eta[1], eta[0], eta[1]};
}

const std::array<TriangleQuadraturePoint, 6>& triangle_quadrature() {
  // Symmetric degree-4 rule: orbits (a, a, 1 − 2a) with a₁, a₂ below, weights w₁, w₂ (sum 1),
  // scaled by the reference area 1/2.
  static const std::array<TriangleQuadraturePoint, 6> rule = [] {
    const double a1 = 0.445948490915965, w1 = 0.223381589678011;
    const double a2 = 0.091576213509771, w2 = 0.109951743655322;
    std::array<TriangleQuadraturePoint, 6> r{};
    const double as[2] = {a1, a2}, ws[2] = {w1, w2};
    for (int o = 0; o < 2; ++o) {
      const double a = as[o], b = 1.0 - 2.0 * a, w = 0.5 * ws[o];
      r[3 * o + 0] = {{a, a}, w};
      r[3 * o + 1] = {{b, a}, w};
      r[3 * o + 2] = {{a, b}, w};
    }
    return r;
  }();
  return rule;
}

}  // namespace biphasic
