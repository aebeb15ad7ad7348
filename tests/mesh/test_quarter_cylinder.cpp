// Generated quarter cylinder: boundaries, exact areas and volume, node placement, grading,
// determinism, and leaving a running gmsh session untouched.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "p2_geometry.hpp"

namespace {

using biphasic::Index;
using biphasic::Mesh;
using biphasic::Point;
using std::numbers::pi;

constexpr double kR = 18.0;
constexpr double kH = 8.0;

biphasic::QuarterCylinderSpec spec_with_lc(double lc) {
  biphasic::QuarterCylinderSpec spec;
  spec.radius = kR;
  spec.height = kH;
  spec.lc = lc;
  return spec;
}

double radius_of(const Point& p) { return std::hypot(p[0], p[1]); }

// z of the vertices on the axis x = y = 0, ascending.
std::vector<double> axis_vertices(const Mesh& mesh) {
  std::vector<double> z;
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    if (radius_of(mesh.nodes[v]) <= 1e-9 * kR) z.push_back(mesh.nodes[v][2]);
  }
  std::sort(z.begin(), z.end());
  return z;
}

// The lc = 1.3 mesh, generated once per process on first use (a generation error then fails
// the test that asked for it).
class MeshQuarterCylinder : public ::testing::Test {
 protected:
  static const Mesh& mesh() {
    static const Mesh generated = biphasic::generate_quarter_cylinder(spec_with_lc(1.3));
    return generated;
  }
};

TEST_F(MeshQuarterCylinder, HasTheFiveNamedBoundaries) {
  EXPECT_EQ(mesh().boundary_names(),
            (std::vector<std::string>{"bottom", "top", "lateral", "symmetry_x", "symmetry_y"}));
  for (const auto& b : mesh().boundaries) EXPECT_FALSE(b.faces.empty()) << b.name;
}

// Tolerances (relative). The symmetry planes are rectangles with straight sides: their P2 faces
// tile them exactly, up to rounding (1e-12). Curved parts: gmsh puts the edge node of an edge on
// the cylinder at the parametric middle (equal angles), and the P2 curve through three such
// points at angles −θ/2, 0, θ/2 has radius R·(1 − a²t²(1 − t²))^½, a = 1 − cos(θ/2), t ∈ [−1, 1]:
// it lies inside the circle by at most Rθ⁴/512. Integrated over the quarter rim this removes a
// fraction θ⁴/480 of the quarter-disc area. Rim segments are ≤ lc, so θ ≤ lc/R and the bottom
// and top areas are low by at most 5.7e-8 at lc = 1.3 (measured 5.4e-8): tolerance 1e-7, and
// the area must not exceed the exact one. Edges inside the lateral face follow the same
// formula but may be up to ~1.4·lc long: bound 2.2e-7 for the lateral area and the volume
// (measured 1.4e-8 and 2.9e-8): tolerance 2.5e-7. Straight-midpoint edge nodes would be off by
// ~θ²/6 ≈ 9e-4 and fail.
TEST_F(MeshQuarterCylinder, BoundaryAreasMatchTheExactSurfaces) {
  const std::vector<std::pair<std::string, std::pair<double, double>>> expected{
      {"bottom", {pi * kR * kR / 4, 1e-7}},
      {"top", {pi * kR * kR / 4, 1e-7}},
      {"lateral", {pi * kR * kH / 2, 2.5e-7}},
      {"symmetry_x", {kR * kH, 1e-12}},
      {"symmetry_y", {kR * kH, 1e-12}}};
  for (const auto& [name, exact_and_tol] : expected) {
    const auto* boundary = mesh().find_boundary(name);
    ASSERT_NE(boundary, nullptr) << name;
    double area = 0.0;
    for (const auto& face : boundary->faces) area += p2test::tri_area(mesh(), face);
    const auto [exact, rel_tol] = exact_and_tol;
    if (name == "bottom" || name == "top") {
      EXPECT_LE(area, exact) << name;
    }
    EXPECT_NEAR(area, exact, rel_tol * exact)
        << name << " relative error " << (area - exact) / exact;
  }
}

TEST_F(MeshQuarterCylinder, VolumeMatchesTheQuarterCylinder) {
  double volume = 0.0;
  for (const auto& tet : mesh().tets) {
    const double v = p2test::tet_volume(mesh(), tet);
    ASSERT_GT(v, 0.0);
    volume += v;
  }
  const double exact = pi * kR * kR * kH / 4;
  EXPECT_NEAR(volume, exact, 2.5e-7 * exact) << "relative error " << (volume - exact) / exact;
}

TEST_F(MeshQuarterCylinder, LateralNodesIncludingEdgeNodesLieOnTheCylinder) {
  const auto* lateral = mesh().find_boundary("lateral");
  ASSERT_NE(lateral, nullptr);
  double worst = 0.0;
  for (const auto& face : lateral->faces) {
    for (const Index n : face) worst = std::max(worst, std::abs(radius_of(mesh().nodes[n]) - kR));
  }
  EXPECT_LE(worst, 1e-9 * kR);
}

TEST_F(MeshQuarterCylinder, FlatBoundaryNodesLieOnTheirPlanes) {
  const auto coordinate_error = [&](const std::string& name, int axis, double value) {
    double worst = 0.0;
    for (const auto& face : mesh().find_boundary(name)->faces) {
      for (const Index n : face) worst = std::max(worst, std::abs(mesh().nodes[n][axis] - value));
    }
    return worst;
  };
  EXPECT_LE(coordinate_error("bottom", 2, 0.0), 1e-12 * kR);
  EXPECT_LE(coordinate_error("top", 2, kH), 1e-12 * kR);
  EXPECT_LE(coordinate_error("symmetry_x", 0, 0.0), 1e-12 * kR);
  EXPECT_LE(coordinate_error("symmetry_y", 1, 0.0), 1e-12 * kR);
}

TEST_F(MeshQuarterCylinder, VerticesComeFirstAndTetsArePositive) {
  const Mesh& m = mesh();
  ASSERT_GT(m.num_vertices, 0);
  ASSERT_LT(m.num_vertices, m.num_nodes());
  std::vector<int> as_corner(m.nodes.size(), 0), as_edge(m.nodes.size(), 0);
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const auto& tet = m.tets[t];
    for (int k = 0; k < 4; ++k) ++as_corner[tet[k]];
    for (int k = 4; k < 10; ++k) ++as_edge[tet[k]];
    EXPECT_GT(biphasic::tet_signed_volume(m, static_cast<Index>(t)), 0.0) << "tet " << t;
  }
  for (Index n = 0; n < m.num_nodes(); ++n) {
    if (n < m.num_vertices) {
      EXPECT_TRUE(as_corner[n] > 0 && as_edge[n] == 0) << "node " << n;
    } else {
      EXPECT_TRUE(as_corner[n] == 0 && as_edge[n] > 0) << "node " << n;
    }
  }
  EXPECT_NO_THROW(biphasic::check_mesh(m));
}

TEST_F(MeshQuarterCylinder, BoundaryFacesPointOutward) {
  for (const auto& boundary : mesh().boundaries) {
    for (const auto& face : boundary.faces) {
      const Point n = p2test::corner_normal(mesh(), face);
      Point out{};
      if (boundary.name == "bottom") out = {0, 0, -1};
      if (boundary.name == "top") out = {0, 0, 1};
      if (boundary.name == "symmetry_x") out = {-1, 0, 0};
      if (boundary.name == "symmetry_y") out = {0, -1, 0};
      if (boundary.name == "lateral") {
        const Point& p = mesh().nodes[face[0]];
        out = {p[0] / kR, p[1] / kR, 0};
      }
      ASSERT_GT(n[0] * out[0] + n[1] * out[1] + n[2] * out[2], 0.9) << boundary.name;
    }
  }
}

TEST_F(MeshQuarterCylinder, AxisCarriesVerticesFromBottomToTop) {
  const std::vector<double> z = axis_vertices(mesh());
  ASSERT_GE(z.size(), 2u);
  EXPECT_EQ(z.front(), 0.0);
  EXPECT_EQ(z.back(), kH);
  // The axis is a geometric edge meshed with size lc = 1.3: ceil(8 / 1.3) = 7 segments.
  EXPECT_EQ(z.size(), 8u);
}

TEST(MeshQuarterCylinderGrading, RefinesTowardTheGradedFaces) {
  const Mesh uniform = biphasic::generate_quarter_cylinder(spec_with_lc(2.0));
  auto spec = spec_with_lc(2.0);
  spec.grading_faces = {"top", "bottom"};
  spec.grading_ratio = 3.0;
  spec.grading_distance = 2.0;
  const Mesh graded = biphasic::generate_quarter_cylinder(spec);

  const std::vector<double> zu = axis_vertices(uniform);
  const std::vector<double> zg = axis_vertices(graded);
  EXPECT_GT(zg.size(), zu.size());
  ASSERT_GE(zg.size(), 4u);
  // First and last axis segments are close to lc / ratio, well below lc.
  EXPECT_LT(zg[1] - zg[0], 0.5 * spec.lc);
  EXPECT_LT(zg[zg.size() - 1] - zg[zg.size() - 2], 0.5 * spec.lc);
  // Away from the graded faces the size returns to about lc.
  double longest = 0.0;
  for (std::size_t i = 1; i < zg.size(); ++i) longest = std::max(longest, zg[i] - zg[i - 1]);
  EXPECT_GT(longest, 0.5 * spec.lc);
  EXPECT_NO_THROW(biphasic::check_mesh(graded));
}

// A swept mesh: every vertex lies on one of the layer planes column_layer_z gives, every layer
// is used, the volume is the quarter cylinder's, and the boundaries are the usual five.
TEST(MeshQuarterCylinderSwept, VerticesLieOnTheGradedLayers) {
  auto spec = spec_with_lc(3.0);
  spec.layers = 9;
  spec.layer_grading_faces = {"bottom", "top"};
  spec.layer_grading_ratio = 8.0;
  const Mesh mesh = biphasic::generate_quarter_cylinder(spec);
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));
  EXPECT_EQ(mesh.boundary_names(),
            (std::vector<std::string>{"bottom", "top", "lateral", "symmetry_x", "symmetry_y"}));
  biphasic::ColumnSpec column;
  column.height = kH;
  column.nz = 9;
  column.grading_faces = {"bottom", "top"};
  column.grading_ratio = 8.0;
  const std::vector<double> planes = biphasic::column_layer_z(column);
  std::vector<int> used(planes.size(), 0);
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    const double z = mesh.nodes[v][2];
    const auto near = std::min_element(planes.begin(), planes.end(), [z](double a, double b) {
      return std::abs(a - z) < std::abs(b - z);
    });
    ASSERT_LT(std::abs(*near - z), 1e-9 * kH) << "vertex " << v << " at z = " << z;
    ++used[static_cast<std::size_t>(near - planes.begin())];
  }
  for (std::size_t k = 0; k < used.size(); ++k) EXPECT_GT(used[k], 0) << "plane " << k;
  // Thinnest layer 8 times thinner than the thickest, at the faces.
  EXPECT_NEAR((planes[5] - planes[4]) / (planes[1] - planes[0]), 8.0, 1e-9);
  double volume = 0.0;
  for (const auto& tet : mesh.tets) volume += p2test::tet_volume(mesh, tet);
  const double exact = pi * kR * kR * kH / 4;
  EXPECT_NEAR(volume, exact, 1e-5 * exact);
}

TEST(MeshQuarterCylinderSpec, InvalidSpecsAreErrors) {
  auto unknown = spec_with_lc(4.0);
  unknown.grading_faces = {"top", "side"};
  unknown.grading_ratio = 2.0;
  try {
    biphasic::generate_quarter_cylinder(unknown);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'side'"), std::string::npos) << message;
    for (const char* valid : {"bottom", "top", "lateral", "symmetry_x", "symmetry_y"}) {
      EXPECT_NE(message.find(valid), std::string::npos) << message;
    }
  }
  auto ratio = spec_with_lc(4.0);
  ratio.grading_faces = {"top"};
  ratio.grading_ratio = 0.5;
  EXPECT_THROW(biphasic::generate_quarter_cylinder(ratio), std::runtime_error);
  EXPECT_THROW(biphasic::generate_quarter_cylinder(spec_with_lc(0.0)), std::runtime_error);
  auto radius = spec_with_lc(4.0);
  radius.radius = -1.0;
  EXPECT_THROW(biphasic::generate_quarter_cylinder(radius), std::runtime_error);
  auto both = spec_with_lc(4.0);
  both.layers = 4;
  both.grading_faces = {"top"};
  both.grading_ratio = 2.0;
  EXPECT_THROW(biphasic::generate_quarter_cylinder(both), std::runtime_error);
  auto unswept = spec_with_lc(4.0);
  unswept.layer_grading_faces = {"top"};
  EXPECT_THROW(biphasic::generate_quarter_cylinder(unswept), std::runtime_error);
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.nodes != b.nodes || a.num_vertices != b.num_vertices || a.tets != b.tets) return false;
  if (a.boundaries.size() != b.boundaries.size()) return false;
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    if (a.boundaries[i].name != b.boundaries[i].name) return false;
    if (a.boundaries[i].faces != b.boundaries[i].faces) return false;
  }
  return true;
}

// Mirrors the library's probe: an uninitialized gmsh leaves the value alone or throws.
bool gmsh_running() {
  double value = std::numeric_limits<double>::quiet_NaN();
  try {
    gmsh::option::getNumber("General.Terminal", value);
  } catch (...) {
    return false;
  }
  return !std::isnan(value);
}

TEST(MeshGmshSession, RepeatedCallsAreDeterministicAndLeaveGmshFinalized) {
  const Mesh first = biphasic::generate_quarter_cylinder(spec_with_lc(3.0));
  EXPECT_FALSE(gmsh_running());
  const Mesh second = biphasic::generate_quarter_cylinder(spec_with_lc(3.0));
  EXPECT_FALSE(gmsh_running());
  EXPECT_TRUE(same_mesh(first, second));
}

TEST(MeshGmshSession, LeavesAnOuterSessionAsItFoundIt) {
  const Mesh standalone = biphasic::generate_quarter_cylinder(spec_with_lc(3.0));

  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("outer");
  gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 123.0);
  gmsh::option::setNumber("Mesh.Algorithm3D", 4);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  std::vector<std::string> models_before;
  gmsh::model::list(models_before);
  gmsh::option::setNumber("General.Terminal", 1);

  const Mesh inside = biphasic::generate_quarter_cylinder(spec_with_lc(3.0));

  EXPECT_TRUE(gmsh_running());
  std::string current;
  gmsh::model::getCurrent(current);
  EXPECT_EQ(current, "outer");
  std::vector<std::string> models_after;
  gmsh::model::list(models_after);
  EXPECT_EQ(models_after, models_before);
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  EXPECT_EQ(volumes.size(), 1u);
  double value = 0.0;
  gmsh::option::getNumber("Mesh.MeshSizeMax", value);
  EXPECT_EQ(value, 123.0);
  gmsh::option::getNumber("Mesh.Algorithm3D", value);
  EXPECT_EQ(value, 4.0);
  gmsh::option::getNumber("Mesh.ElementOrder", value);
  EXPECT_EQ(value, 2.0);
  gmsh::option::getNumber("General.Terminal", value);
  EXPECT_EQ(value, 1.0);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::finalize();

  EXPECT_TRUE(same_mesh(standalone, inside));
}

}  // namespace
