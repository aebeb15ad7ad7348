// Point location and probe interpolation at arbitrary points: a quadratic displacement and a
// linear pressure are reproduced exactly (to round-off) against the analytic functions, on
// straight P2 meshes and on curved ones (where the straight-sided barycentric coordinates are
// wrong and the isoparametric map must be inverted), and points outside the body are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/app/probes.hpp"
#include "biphasic/fe/point_locator.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace biphasic {
namespace {

/// A quadratic displacement field g(X) [mm] with all second-order terms.
std::array<double, 3> g(const Point& X) {
  const double x = X[0], y = X[1], z = X[2];
  return {0.1 + 0.3 * x - 0.2 * y + 0.05 * x * x + 0.07 * y * z - 0.03 * z * z,
          -0.2 + 0.1 * z + 0.04 * x * y - 0.06 * y * y + 0.02 * x * z,
          0.05 * x - 0.4 * z + 0.03 * x * x - 0.05 * x * y + 0.08 * z * z};
}
/// A linear pressure field h(X) [MPa].
double h(const Point& X) { return 0.3 - 0.25 * X[0] + 0.5 * X[1] + 0.125 * X[2]; }

/// Nodal values of g (node-major, 3 per node) and vertex values of h at the points `at(X)`
/// assigns to the mesh's nodes (their pre-images under a map, or the nodes themselves).
template <class PreImage>
void nodal_fields(const Mesh& mesh, const PreImage& at, std::vector<double>& u,
                  std::vector<double>& p) {
  u.clear();
  p.clear();
  for (const Point& X : mesh.nodes) {
    const auto v = g(at(X));
    u.insert(u.end(), v.begin(), v.end());
  }
  for (Index v = 0; v < mesh.num_vertices; ++v) p.push_back(h(at(mesh.nodes[v])));
}

/// Samples a–b with n points and compares u, p at each sample with g, h at pre_image(x).
template <class PreImage>
void expect_exact_on_line(const Mesh& mesh, const PointLocator& locator, const Point& a,
                          const Point& b, int n, const PreImage& pre_image, double tol) {
  std::vector<double> u, p;
  nodal_fields(mesh, pre_image, u, p);
  const LineProbe probe = interpolating_probe(mesh, locator, a, b, n, 1e-9);
  ASSERT_EQ(probe.size(), static_cast<std::size_t>(n));
  const std::vector<double> pressure = probe.pressure(p);
  for (std::size_t i = 0; i < probe.size(); ++i) {
    const Point& x = probe.position(i);
    const Point X = pre_image(x);
    const auto expected = g(X);
    const auto got = probe.displacement(u, i);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(got[d], expected[d], tol) << "u" << d << " at sample " << i;
    EXPECT_NEAR(pressure[i], h(X), tol) << "p at sample " << i;
  }
}

Point identity(const Point& x) { return x; }

TEST(LocateInElement, StraightTetGivesBarycentricCoordinatesAndDistance) {
  // Corners (0,0,0), (2,0,0), (0,3,0), (0,0,4); edge nodes at the midpoints.
  std::array<Point, 10> X{Point{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 4}};
  for (std::size_t e = 0; e < kTetEdges.size(); ++e)
    for (int d = 0; d < 3; ++d) X[4 + e][d] = 0.5 * (X[kTetEdges[e][0]][d] + X[kTetEdges[e][1]][d]);
  const PointLocation in = locate_in_element(X, {0.5, 0.75, 1.0});
  EXPECT_NEAR(in.xi[0], 0.25, 1e-15);
  EXPECT_NEAR(in.xi[1], 0.25, 1e-15);
  EXPECT_NEAR(in.xi[2], 0.25, 1e-15);
  EXPECT_EQ(in.distance_outside, 0.0);
  // 0.1 mm below the face z = 0.
  EXPECT_NEAR(locate_in_element(X, {0.5, 0.5, -0.1}).distance_outside, 0.1, 1e-14);
}

TEST(PointLocator, QuadraticUAndLinearPExactOnAStraightMesh) {
  const Mesh mesh = test::box_mesh({3, 2, 2}, {2.0, 1.5, 1.0});
  const PointLocator locator(mesh);
  // Through the inside at odd angles, along a face, and corner to corner (through vertices,
  // edges and faces of many elements, where round-off puts points slightly outside some).
  expect_exact_on_line(mesh, locator, {0.13, 0.21, 0.37}, {1.91, 1.37, 0.62}, 37, identity, 1e-13);
  expect_exact_on_line(mesh, locator, {0.0, 0.1, 0.05}, {2.0, 1.45, 0.9}, 23, identity, 1e-13);
  expect_exact_on_line(mesh, locator, {2.0, 0.0, 0.0}, {0.0, 1.5, 1.0}, 41, identity, 1e-13);
  expect_exact_on_line(mesh, locator, {0.3, 0.0, 0.2}, {1.7, 0.0, 0.9}, 19, identity, 1e-13);
}

// A curved P2 mesh: the box mesh with every node moved by the quadratic map
// Φ(X, Y, Z) = (X, Y + c X², Z + c Y²). Each element is then exactly Φ of its straight tet
// (P2 reproduces the quadratic Φ), so a field g(Φ⁻¹(x)) with g quadratic is quadratic in the
// reference coordinates and reproduced exactly — at the right reference coordinates only.
constexpr double kBend = 0.15;
Point bend(const Point& X) {
  return {X[0], X[1] + kBend * X[0] * X[0], X[2] + kBend * X[1] * X[1]};
}
Point unbend(const Point& x) {
  const double Y = x[1] - kBend * x[0] * x[0];
  return {x[0], Y, x[2] - kBend * Y * Y};
}

TEST(PointLocator, QuadraticUAndLinearPExactOnACurvedMesh) {
  Mesh mesh = test::box_mesh({3, 2, 2}, {2.0, 1.5, 1.0});
  for (Point& x : mesh.nodes) x = bend(x);
  const PointLocator locator(mesh);
  // Lines between images of interior points (their pre-images stay inside the box).
  expect_exact_on_line(mesh, locator, bend({0.2, 0.3, 0.3}), bend({1.8, 1.1, 0.7}), 31, unbend,
                       1e-12);
  expect_exact_on_line(mesh, locator, bend({1.9, 0.2, 0.15}), bend({0.3, 1.3, 0.85}), 29, unbend,
                       1e-12);
  // On the curved image of the face X = 2 (x = 2 stays planar, the element faces bow in y, z).
  expect_exact_on_line(mesh, locator, bend({2.0, 0.2, 0.1}), bend({2.0, 1.2, 0.1}), 2, unbend,
                       1e-12);
  // The straight-sided coordinates would be off by far more: the sample points' pre-images
  // differ from what the straight elements give by about kBend h² / 4.
}

// The generated quarter cylinder: its lateral face is curved (edge nodes on the circle). A
// displacement linear in x is in the span of the isoparametric P2 functions, so it is exact at
// any point, including points next to the curved face where straight-sided coordinates are off.
TEST(PointLocator, LinearFieldExactNearTheCurvedFaceOfTheCylinder) {
  QuarterCylinderSpec spec;
  spec.radius = 3.0;
  spec.height = 2.0;
  spec.lc = 1.0;
  const Mesh mesh = generate_quarter_cylinder(spec);
  // The mesh is curved: some edge node lies off its edge's midpoint.
  double bow = 0.0;
  for (const Tet10& tet : mesh.tets)
    for (std::size_t e = 0; e < kTetEdges.size(); ++e)
      for (int d = 0; d < 3; ++d)
        bow = std::max(
            bow, std::abs(mesh.nodes[tet[4 + e]][d] - 0.5 * (mesh.nodes[tet[kTetEdges[e][0]]][d] +
                                                             mesh.nodes[tet[kTetEdges[e][1]]][d])));
  ASSERT_GT(bow, 1e-3);
  const PointLocator locator(mesh);
  std::vector<double> u;
  for (const Point& x : mesh.nodes) {
    u.push_back(0.1 + 0.2 * x[0] - 0.3 * x[1] + 0.4 * x[2]);
    u.push_back(x[0] * 0.5);
    u.push_back(-x[2]);
  }
  // A chord just inside the arc r = 3 at z = 1, and a radial line out to r = 2.97.
  const double r = 2.97;
  for (const auto& [a, b] : std::vector<std::pair<Point, Point>>{
           {{r, 0.001, 1.0}, {0.001, r, 1.0}},
           {{0.01, 0.01, 0.5}, {r * std::cos(0.6), r * std::sin(0.6), 1.7}}}) {
    const LineProbe probe = interpolating_probe(mesh, locator, a, b, 57, 1e-9);
    for (std::size_t i = 0; i < probe.size(); ++i) {
      const Point& x = probe.position(i);
      const auto got = probe.displacement(u, i);
      EXPECT_NEAR(got[0], 0.1 + 0.2 * x[0] - 0.3 * x[1] + 0.4 * x[2], 1e-12) << i;
      EXPECT_NEAR(got[1], 0.5 * x[0], 1e-12) << i;
      EXPECT_NEAR(got[2], -x[2], 1e-12) << i;
    }
  }
  // Points on the exact circle lie within the mesh's curved face up to its P2 approximation
  // of the circle; beyond that they are outside.
  EXPECT_FALSE(locator.locate({3.1, 0.5, 1.0}, 1e-6).has_value());
  EXPECT_TRUE(locator.locate({2.9, 0.5, 1.0}, 1e-6).has_value());
}

TEST(PointLocator, PointsOutsideAreRefusedWithTheirPosition) {
  const Mesh mesh = test::box_mesh({2, 2, 2}, {1.0, 1.0, 1.0});
  const PointLocator locator(mesh);
  EXPECT_FALSE(locator.locate({1.5, 0.5, 0.5}, 1e-9).has_value());
  EXPECT_FALSE(locator.locate({0.5, 0.5, -1e-6}, 1e-9).has_value());
  // Within the round-off allowance the point counts as on the face.
  const auto on_face = locator.locate({0.5, 0.5, -1e-12}, 1e-9);
  ASSERT_TRUE(on_face.has_value());
  EXPECT_GE(on_face->xi[0], 0.0);
  EXPECT_GE(on_face->xi[1], 0.0);
  EXPECT_GE(on_face->xi[2], 0.0);
  try {
    interpolating_probe(mesh, locator, {0.5, 0.5, 0.5}, {0.5, 0.5, 1.5}, 11, 1e-9);
    FAIL() << "a line leaving the body was accepted";
  } catch (const std::out_of_range& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("point 7 of 11 at (0.5, 0.5, 1.1) mm"), std::string::npos) << what;
    EXPECT_NE(what.find("5 of the points"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace biphasic
