// Test-side geometry of P2 (isoparametric) elements: volumes and areas by quadrature that is
// exact for the polynomial integrands of straight or curved P2 tets, and for planar P2
// triangles. Independent of the library's own volume helpers.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace p2test {

using biphasic::Mesh;
using biphasic::Point;
using biphasic::Tet10;
using biphasic::Tri6;

/// Gauss–Legendre rule with n points on [0, 1].
struct Rule {
  std::vector<double> x, w;
};

inline Rule gauss_legendre(int n) {
  Rule rule;
  for (int i = 1; i <= n; ++i) {
    double t = std::cos(std::numbers::pi * (i - 0.25) / (n + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p_prev = 1.0, p = t;  // Legendre P0, P1 at t
      for (int k = 2; k <= n; ++k) {
        const double p_next = ((2.0 * k - 1.0) * t * p - (k - 1.0) * p_prev) / k;
        p_prev = p;
        p = p_next;
      }
      dp = n * (t * p - p_prev) / (t * t - 1.0);
      const double step = p / dp;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.x.push_back(0.5 * (1.0 + t));
    rule.w.push_back(1.0 / ((1.0 - t * t) * dp * dp));
  }
  return rule;
}

inline double det3(const std::array<Point, 3>& c) {
  // columns c[0], c[1], c[2]
  return c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
         c[1][0] * (c[0][1] * c[2][2] - c[0][2] * c[2][1]) +
         c[2][0] * (c[0][1] * c[1][2] - c[0][2] * c[1][1]);
}

/// Volume [mm³] of a P2 tet: ∫ det J over the reference tet, through the collapsed (Duffy)
/// map of the unit cube with n Gauss points per direction. det J has degree 3, the collapsed
/// integrand degree ≤ 5 per direction, so n = 3 is exact; the default leaves margin.
inline double tet_volume(const Mesh& mesh, const Tet10& tet, int n = 4) {
  static constexpr std::array<std::array<double, 3>, 4> dlambda{
      {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const Rule g = gauss_legendre(n);
  double volume = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const double u = g.x[i], v = g.x[j], w = g.x[k];
        const double xi = u, eta = v * (1 - u), zeta = w * (1 - u) * (1 - v);
        const double weight = g.w[i] * g.w[j] * g.w[k] * (1 - u) * (1 - u) * (1 - v);
        const std::array<double, 4> lambda{1 - xi - eta - zeta, xi, eta, zeta};
        std::array<Point, 3> jac{};  // jac[d] = ∂x/∂ξ_d
        const auto add = [&](biphasic::Index node, const std::array<double, 3>& grad) {
          const Point& x = mesh.nodes[node];
          for (int d = 0; d < 3; ++d) {
            for (int c = 0; c < 3; ++c) jac[d][c] += x[c] * grad[d];
          }
        };
        for (int a = 0; a < 4; ++a) {
          std::array<double, 3> grad{};
          for (int d = 0; d < 3; ++d) grad[d] = (4 * lambda[a] - 1) * dlambda[a][d];
          add(tet[a], grad);
        }
        for (int e = 0; e < 6; ++e) {
          const int a = biphasic::kTetEdges[e][0], b = biphasic::kTetEdges[e][1];
          std::array<double, 3> grad{};
          for (int d = 0; d < 3; ++d) {
            grad[d] = 4 * (lambda[a] * dlambda[b][d] + lambda[b] * dlambda[a][d]);
          }
          add(tet[4 + e], grad);
        }
        volume += weight * det3(jac);
      }
    }
  }
  return volume;
}

/// Area [mm²] of a P2 triangle: ∫ |∂x/∂ξ × ∂x/∂η| over the reference triangle (collapsed
/// Gauss, n per direction). Exact for planar faces (the integrand is then a quadratic);
/// for curved faces the quadrature error is far below the geometric one.
inline double tri_area(const Mesh& mesh, const Tri6& tri, int n = 6) {
  static constexpr std::array<std::array<double, 2>, 3> dlambda{{{-1, -1}, {1, 0}, {0, 1}}};
  const Rule g = gauss_legendre(n);
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double u = g.x[i], v = g.x[j];
      const double xi = u, eta = v * (1 - u);
      const double weight = g.w[i] * g.w[j] * (1 - u);
      const std::array<double, 3> lambda{1 - xi - eta, xi, eta};
      std::array<Point, 2> tangent{};
      const auto add = [&](biphasic::Index node, const std::array<double, 2>& grad) {
        const Point& x = mesh.nodes[node];
        for (int d = 0; d < 2; ++d) {
          for (int c = 0; c < 3; ++c) tangent[d][c] += x[c] * grad[d];
        }
      };
      for (int a = 0; a < 3; ++a) {
        add(tri[a], {(4 * lambda[a] - 1) * dlambda[a][0], (4 * lambda[a] - 1) * dlambda[a][1]});
      }
      for (int e = 0; e < 3; ++e) {
        const int a = biphasic::kTriEdges[e][0], b = biphasic::kTriEdges[e][1];
        add(tri[3 + e], {4 * (lambda[a] * dlambda[b][0] + lambda[b] * dlambda[a][0]),
                         4 * (lambda[a] * dlambda[b][1] + lambda[b] * dlambda[a][1])});
      }
      const Point& t0 = tangent[0];
      const Point& t1 = tangent[1];
      const Point normal{t0[1] * t1[2] - t0[2] * t1[1], t0[2] * t1[0] - t0[0] * t1[2],
                         t0[0] * t1[1] - t0[1] * t1[0]};
      area +=
          weight * std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    }
  }
  return area;
}

/// Unit normal of the straight triangle through the corners of `tri` (right-hand rule).
inline Point corner_normal(const Mesh& mesh, const Tri6& tri) {
  const Point& a = mesh.nodes[tri[0]];
  const Point& b = mesh.nodes[tri[1]];
  const Point& c = mesh.nodes[tri[2]];
  const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Point v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& x : n) x /= len;
  return n;
}

}  // namespace p2test
