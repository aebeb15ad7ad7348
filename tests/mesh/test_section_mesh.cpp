// SectionMesh: the rectangle generator (counts, areas, curve lengths and normals, grading, spec
// checks), the invariant checks, and read_gmsh_section on hand-written .msh 2.2 files.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/mesh/section_mesh.hpp"

namespace {

namespace fs = std::filesystem;
using biphasic::check_section_mesh;
using biphasic::generate_section_rectangle;
using biphasic::Index;
using biphasic::Point2;
using biphasic::SectionMesh;
using biphasic::SectionRectangleSpec;

// The message of the std::runtime_error `body` throws, or "" if it throws none.
std::string error_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_CONTAINS(message, part)               \
  EXPECT_NE((message).find(part), std::string::npos) \
      << "'" << (message) << "' lacks '" << (part) << "'"

double area_of(const SectionMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += biphasic::triangle_signed_area(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]);
  return area;
}

double length(const Point2& a, const Point2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

double curve_length(const SectionMesh& mesh, const std::string& name) {
  const auto* b = mesh.find_boundary(name);
  double sum = 0.0;
  for (const auto& s : b->segments) sum += length(mesh.nodes[s[0]], mesh.nodes[s[1]]);
  return sum;
}

// True if some triangle has the vertex pair {a, b} as an edge.
bool has_edge(const SectionMesh& mesh, Index a, Index b) {
  for (const auto& t : mesh.triangles)
    for (const auto& [p, q] : biphasic::kTriEdges)
      if ((t[p] == a && t[q] == b) || (t[p] == b && t[q] == a)) return true;
  return false;
}

// Cell sizes along r (at z = 0) or z (at r = 0) of a generated rectangle with nr cells in r.
std::vector<double> cell_sizes(const SectionMesh& mesh, int nr, int nz, bool along_z) {
  std::vector<double> sizes;
  const int n = along_z ? nz : nr;
  for (int k = 0; k < n; ++k) {
    const Index a = along_z ? static_cast<Index>(k) * (nr + 1) : k;
    const Index b = along_z ? static_cast<Index>(k + 1) * (nr + 1) : k + 1;
    sizes.push_back(length(mesh.nodes[a], mesh.nodes[b]));
  }
  return sizes;
}

SectionRectangleSpec small_spec() {
  SectionRectangleSpec spec;
  spec.width = 3.0;
  spec.height = 2.0;
  spec.nr = 3;
  spec.nz = 2;
  return spec;
}

TEST(SectionMesh, RectangleCountsAndNumbering) {
  for (const auto& [nr, nz] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{18, 8}}) {
    SectionRectangleSpec spec;
    spec.nr = nr;
    spec.nz = nz;
    const SectionMesh mesh = generate_section_rectangle(spec);
    SCOPED_TRACE(std::to_string(nr) + " x " + std::to_string(nz));
    EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(2 * nr * nz));
    EXPECT_EQ(mesh.num_vertices, (nr + 1) * (nz + 1));
    // Edges: nr(nz+1) along r, (nr+1)nz along z, nr·nz diagonals; with the vertices that is
    // (2nr+1)(2nz+1) nodes.
    EXPECT_EQ(mesh.num_nodes(), (2 * nr + 1) * (2 * nz + 1));
    EXPECT_EQ(mesh.boundary_names(),
              (std::vector<std::string>{"axis", "lateral", "bottom", "top"}));
    EXPECT_EQ(mesh.find_boundary("axis")->segments.size(), static_cast<std::size_t>(nz));
    EXPECT_EQ(mesh.find_boundary("lateral")->segments.size(), static_cast<std::size_t>(nz));
    EXPECT_EQ(mesh.find_boundary("bottom")->segments.size(), static_cast<std::size_t>(nr));
    EXPECT_EQ(mesh.find_boundary("top")->segments.size(), static_cast<std::size_t>(nr));
    EXPECT_TRUE(mesh.node_sets.empty());
    EXPECT_TRUE(mesh.file_tags.empty());
    EXPECT_TRUE(mesh.triangle_region.empty());
    EXPECT_NO_THROW(check_section_mesh(mesh));
    // Vertices numbered r fastest, then z.
    EXPECT_EQ(mesh.nodes[1][0], spec.width / nr);
    EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(nr + 1)][1], spec.height / nz);
    EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(mesh.num_vertices - 1)],
              (Point2{spec.width, spec.height}));
  }
}

TEST(SectionMesh, RectangleDiagonalsAlternate) {
  const SectionMesh mesh = generate_section_rectangle(small_spec());
  const auto at = [](Index i, Index j) { return i + 4 * j; };
  EXPECT_TRUE(has_edge(mesh, at(0, 0), at(1, 1)));  // cell (0, 0): even
  EXPECT_FALSE(has_edge(mesh, at(1, 0), at(0, 1)));
  EXPECT_TRUE(has_edge(mesh, at(2, 0), at(1, 1)));  // cell (1, 0): odd
  EXPECT_FALSE(has_edge(mesh, at(1, 0), at(2, 1)));
  EXPECT_TRUE(has_edge(mesh, at(1, 1), at(0, 2)));  // cell (0, 1): odd
  EXPECT_TRUE(has_edge(mesh, at(1, 1), at(2, 2)));  // cell (1, 1): even
}

TEST(SectionMesh, RectangleAreaLengthsAndMidsideNodes) {
  SectionRectangleSpec spec = small_spec();
  spec.width = 18.0;
  spec.height = 8.0;
  spec.nr = 7;
  spec.nz = 5;
  spec.grading_curves = {"lateral", "top"};
  spec.grading_ratio = 3.0;
  const SectionMesh mesh = generate_section_rectangle(spec);
  EXPECT_NEAR(area_of(mesh), spec.width * spec.height, 1e-12 * spec.width * spec.height);
  for (const auto& t : mesh.triangles)
    EXPECT_GT(biphasic::triangle_signed_area(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]),
              0.0);
  EXPECT_NEAR(curve_length(mesh, "axis"), spec.height, 1e-12);
  EXPECT_NEAR(curve_length(mesh, "lateral"), spec.height, 1e-12);
  EXPECT_NEAR(curve_length(mesh, "bottom"), spec.width, 1e-12);
  EXPECT_NEAR(curve_length(mesh, "top"), spec.width, 1e-12);
  for (const auto& t : mesh.triangles) {
    for (std::size_t e = 0; e < 3; ++e) {
      const Point2& a = mesh.nodes[t[biphasic::kTriEdges[e][0]]];
      const Point2& b = mesh.nodes[t[biphasic::kTriEdges[e][1]]];
      const Point2& m = mesh.nodes[t[3 + e]];
      EXPECT_NEAR(m[0], 0.5 * (a[0] + b[0]), 1e-14);
      EXPECT_NEAR(m[1], 0.5 * (a[1] + b[1]), 1e-14);
    }
  }
}

TEST(SectionMesh, RectangleCurvesHaveOutwardNormals) {
  const SectionMesh mesh = generate_section_rectangle(small_spec());
  const std::vector<std::pair<std::string, Point2>> expected{
      {"axis", {-1.0, 0.0}}, {"lateral", {1.0, 0.0}}, {"bottom", {0.0, -1.0}}, {"top", {0.0, 1.0}}};
  for (const auto& [name, normal] : expected) {
    for (const auto& s : mesh.find_boundary(name)->segments) {
      const Point2& a = mesh.nodes[s[0]];
      const Point2& b = mesh.nodes[s[1]];
      const double l = length(a, b);
      EXPECT_NEAR((b[1] - a[1]) / l, normal[0], 1e-14) << name;
      EXPECT_NEAR(-(b[0] - a[0]) / l, normal[1], 1e-14) << name;
      const Point2& m = mesh.nodes[s[2]];
      EXPECT_NEAR(m[0], 0.5 * (a[0] + b[0]), 1e-14) << name;
      EXPECT_NEAR(m[1], 0.5 * (a[1] + b[1]), 1e-14) << name;
    }
  }
}

TEST(SectionMesh, RectangleGradingRatioIsExact) {
  for (const int nz : {3, 4, 7, 8}) {
    SectionRectangleSpec spec = small_spec();
    spec.nz = nz;
    spec.grading_curves = {"bottom", "top"};
    spec.grading_ratio = 4.0;
    const SectionMesh mesh = generate_section_rectangle(spec);
    const std::vector<double> dz = cell_sizes(mesh, spec.nr, nz, true);
    const auto [lo, hi] = std::minmax_element(dz.begin(), dz.end());
    SCOPED_TRACE("nz = " + std::to_string(nz));
    EXPECT_NEAR(*hi / *lo, 4.0, 1e-12);
    EXPECT_NEAR(dz.front(), *lo, 1e-14);
    EXPECT_NEAR(dz.back(), *lo, 1e-14);
    // r stays uniform.
    for (const double dr : cell_sizes(mesh, spec.nr, nz, false)) EXPECT_NEAR(dr, 1.0, 1e-14);
  }
  SectionRectangleSpec spec = small_spec();
  spec.nr = 6;
  spec.nz = 5;
  spec.grading_curves = {"axis", "top"};
  spec.grading_ratio = 2.5;
  const SectionMesh mesh = generate_section_rectangle(spec);
  const std::vector<double> dr = cell_sizes(mesh, spec.nr, spec.nz, false);
  const std::vector<double> dz = cell_sizes(mesh, spec.nr, spec.nz, true);
  EXPECT_NEAR(dr.back() / dr.front(), 2.5, 1e-12);  // finest at the axis
  EXPECT_NEAR(dz.front() / dz.back(), 2.5, 1e-12);  // finest at the top
  EXPECT_TRUE(std::is_sorted(dr.begin(), dr.end()));
  EXPECT_TRUE(std::is_sorted(dz.rbegin(), dz.rend()));
}

TEST(SectionMesh, RectangleIsDeterministic) {
  SectionRectangleSpec spec = small_spec();
  spec.grading_curves = {"lateral"};
  spec.grading_ratio = 2.0;
  const SectionMesh a = generate_section_rectangle(spec);
  const SectionMesh b = generate_section_rectangle(spec);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.triangles, b.triangles);
  for (std::size_t i = 0; i < a.boundaries.size(); ++i)
    EXPECT_EQ(a.boundaries[i].segments, b.boundaries[i].segments);
}

TEST(SectionMesh, InvalidSpecsNameTheField) {
  struct Case {
    std::function<void(SectionRectangleSpec&)> change;
    std::vector<std::string> parts;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases{
      {[](SectionRectangleSpec& s) { s.width = 0.0; }, {"width", "0"}},
      {[&](SectionRectangleSpec& s) { s.height = nan; }, {"height", "nan"}},
      {[](SectionRectangleSpec& s) { s.nr = 0; }, {"nr must be >= 1", "0"}},
      {[](SectionRectangleSpec& s) { s.nz = -2; }, {"nz must be >= 1", "-2"}},
      {[](SectionRectangleSpec& s) { s.grading_ratio = 0.5; }, {"grading_ratio", "0.5"}},
      {[](SectionRectangleSpec& s) { s.grading_curves = {"side"}; }, {"grading_curves", "'side'"}},
      {[](SectionRectangleSpec& s) {
         s.nz = 2;
         s.grading_ratio = 2.0;
         s.grading_curves = {"bottom", "top"};
       },
       {"nz must be >= 3", "got 2"}},
      {[](SectionRectangleSpec& s) {
         s.nr = 1;
         s.grading_ratio = 2.0;
         s.grading_curves = {"axis"};
       },
       {"nr must be >= 2", "'axis'", "got 1"}},
  };
  for (const Case& c : cases) {
    SectionRectangleSpec spec = small_spec();
    c.change(spec);
    const std::string message = error_of([&] { generate_section_rectangle(spec); });
    EXPECT_CONTAINS(message, "generate_section_rectangle");
    for (const std::string& part : c.parts) EXPECT_CONTAINS(message, part);
  }
  // Curves named with a ratio of 1 need no extra cells.
  SectionRectangleSpec spec = small_spec();
  spec.nz = 1;
  spec.grading_curves = {"bottom", "top"};
  EXPECT_NO_THROW(generate_section_rectangle(spec));
}

TEST(SectionMesh, CheckCatchesIndexOutOfRange) {
  SectionMesh mesh = generate_section_rectangle(small_spec());
  mesh.triangles[2][1] = 1000;
  const std::string message = error_of([&] { check_section_mesh(mesh); });
  EXPECT_CONTAINS(message, "check_section_mesh");
  EXPECT_CONTAINS(message, "triangle 2");
  EXPECT_CONTAINS(message, "corner 1000");
}

TEST(SectionMesh, CheckCatchesClockwiseTriangle) {
  SectionMesh mesh = generate_section_rectangle(small_spec());
  auto& t = mesh.triangles[3];
  std::swap(t[1], t[2]);
  std::swap(t[3], t[5]);
  const std::string message = error_of([&] { check_section_mesh(mesh); });
  EXPECT_CONTAINS(message, "triangle 3");
  EXPECT_CONTAINS(message, "non-positive area");
  // orient_triangles puts it right.
  biphasic::orient_triangles(mesh);
  EXPECT_NO_THROW(check_section_mesh(mesh));
}

TEST(SectionMesh, CheckCatchesSegmentOffTheTriangles) {
  SectionMesh mesh = generate_section_rectangle(small_spec());
  // Vertices 0 and 2 (r = 0 and r = 2 on the bottom) are not joined by an edge.
  mesh.boundaries[2].segments[1] = {0, 2, mesh.boundaries[2].segments[1][2]};
  const std::string message = error_of([&] { check_section_mesh(mesh); });
  EXPECT_CONTAINS(message, "boundary 'bottom' segment 1");
  EXPECT_CONTAINS(message, "not an edge of any triangle");
  const std::string orient = error_of([&] { biphasic::orient_boundary_segments(mesh); });
  EXPECT_CONTAINS(orient, "orient_boundary_segments: boundary 'bottom' segment 1");
}

TEST(SectionMesh, CheckCatchesReversedSegmentAndOrientFixesIt) {
  SectionMesh mesh = generate_section_rectangle(small_spec());
  auto& s = mesh.boundaries[1].segments[0];
  std::swap(s[0], s[1]);
  const std::string message = error_of([&] { check_section_mesh(mesh); });
  EXPECT_CONTAINS(message, "boundary 'lateral' segment 0");
  EXPECT_CONTAINS(message, "body on its right");
  biphasic::orient_boundary_segments(mesh);
  EXPECT_NO_THROW(check_section_mesh(mesh));
}

TEST(SectionMesh, CheckCatchesDuplicatedNames) {
  const SectionMesh good = generate_section_rectangle(small_spec());
  SectionMesh mesh = good;
  mesh.boundaries[3].name = "axis";
  EXPECT_CONTAINS(error_of([&] { check_section_mesh(mesh); }), "two boundaries are named 'axis'");

  mesh = good;
  mesh.node_sets.push_back({"top", 0, {0}});
  EXPECT_CONTAINS(error_of([&] { check_section_mesh(mesh); }), "'top'");

  mesh = good;
  mesh.node_sets.push_back({"pin", 0, {0}});
  mesh.node_sets.push_back({"pin", 0, {1}});
  EXPECT_CONTAINS(error_of([&] { check_section_mesh(mesh); }), "two node sets are named 'pin'");

  mesh = good;
  mesh.region_names = {"cartilage", "cartilage"};
  mesh.triangle_region.assign(mesh.triangles.size(), 0);
  EXPECT_CONTAINS(error_of([&] { check_section_mesh(mesh); }), "two regions are named 'cartilage'");
}

TEST(SectionMesh, OrientRefusesDegenerateTriangle) {
  SectionMesh mesh;
  mesh.nodes = {{0, 0}, {1, 0}, {2, 0}, {0.5, 0}, {1.5, 0}, {1, 0}};
  mesh.num_vertices = 3;
  mesh.triangles = {{0, 1, 2, 3, 4, 5}};
  const std::string message = error_of([&] { biphasic::orient_triangles(mesh); });
  EXPECT_CONTAINS(message, "triangle 0 is degenerate");
  EXPECT_CONTAINS(message, "area 0");
}

TEST(SectionMesh, DescribeNode) {
  SectionMesh mesh = generate_section_rectangle(small_spec());
  EXPECT_EQ(mesh.describe_node(1), "node 1 at (1, 0) mm");
  mesh.file_tags.assign(static_cast<std::size_t>(mesh.num_nodes()), -1);
  mesh.file_tags[1] = 40;
  EXPECT_EQ(mesh.describe_node(1), "node 1 (file tag 40) at (1, 0) mm");
}

// ---- read_gmsh_section ------------------------------------------------------------------

// A scratch directory private to the running test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("biphasic_section_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (path_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

 private:
  fs::path path_;
};

const char* const kHeader = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";

// The unit square of two 3-node triangles (the second clockwise), four named curves (the axis
// written against the body), a named corner point, one physical surface, and an unused node 5.
// `z3` is the z of node 3.
std::string linear_square(const std::string& z3 = "0") {
  return std::string(kHeader) +
         "$PhysicalNames\n6\n0 10 \"pin\"\n1 1 \"bottom\"\n1 2 \"lateral\"\n1 3 \"top\"\n"
         "1 4 \"axis\"\n2 100 \"tissue\"\n$EndPhysicalNames\n"
         "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 " +
         z3 +
         "\n4 0 1 0\n5 7 7 0\n$EndNodes\n"
         "$Elements\n7\n"
         "1 15 2 10 1 1\n"
         "2 1 2 1 1 1 2\n"
         "3 1 2 2 2 2 3\n"
         "4 1 2 3 3 3 4\n"
         "5 1 2 4 4 1 4\n"
         "6 2 2 100 1 1 2 3\n"
         "7 2 2 100 1 1 4 3\n"
         "$EndElements\n";
}

// The same square with 6-node triangles and 3-node lines (the second triangle clockwise), no
// physical surface, and an unnamed physical curve 7 on the left side.
std::string quadratic_square() {
  return std::string(kHeader) +
         "$PhysicalNames\n3\n1 1 \"bottom\"\n1 2 \"lateral\"\n1 3 \"top\"\n$EndPhysicalNames\n"
         "$Nodes\n9\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0 0\n6 1 0.5 0\n7 0.5 1 0\n"
         "8 0 0.5 0\n9 0.5 0.5 0\n$EndNodes\n"
         "$Elements\n6\n"
         "1 8 2 1 1 1 2 5\n"
         "2 8 2 2 2 2 3 6\n"
         "3 8 2 3 3 3 4 7\n"
         "4 8 2 7 4 4 1 8\n"
         "5 9 2 0 1 1 2 3 5 6 9\n"
         "6 9 2 0 1 1 4 3 8 7 9\n"
         "$EndElements\n";
}

void expect_unit_square(const SectionMesh& mesh) {
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.num_vertices, 4);
  EXPECT_EQ(mesh.num_nodes(), 9);
  EXPECT_NEAR(area_of(mesh), 1.0, 1e-14);
  EXPECT_NO_THROW(check_section_mesh(mesh));
  for (const auto& b : mesh.boundaries) EXPECT_EQ(b.segments.size(), 1u) << b.name;
  // Outward normals of the four sides.
  const std::vector<std::pair<std::string, Point2>> sides{
      {"bottom", {0, -1}}, {"lateral", {1, 0}}, {"top", {0, 1}}};
  for (const auto& [name, normal] : sides) {
    const auto* b = mesh.find_boundary(name);
    ASSERT_NE(b, nullptr) << name;
    const auto& s = b->segments[0];
    const Point2& a = mesh.nodes[s[0]];
    const Point2& c = mesh.nodes[s[1]];
    EXPECT_NEAR(c[1] - a[1], normal[0], 1e-14) << name;
    EXPECT_NEAR(-(c[0] - a[0]), normal[1], 1e-14) << name;
    EXPECT_NEAR(mesh.nodes[s[2]][0], 0.5 * (a[0] + c[0]), 1e-14) << name;
    EXPECT_NEAR(mesh.nodes[s[2]][1], 0.5 * (a[1] + c[1]), 1e-14) << name;
  }
}

TEST(SectionMeshReadGmsh, LinearTrianglesWithCurvesPointAndSurface) {
  ScratchDir dir;
  const SectionMesh mesh = biphasic::read_gmsh_section(dir.write("square3.msh", linear_square()));
  expect_unit_square(mesh);
  EXPECT_EQ(mesh.boundary_names(), (std::vector<std::string>{"bottom", "lateral", "top", "axis"}));
  const auto& axis = mesh.find_boundary("axis")->segments[0];
  EXPECT_EQ(mesh.nodes[axis[0]], (Point2{0, 1}));  // reversed: the body on its left
  EXPECT_EQ(mesh.nodes[axis[1]], (Point2{0, 0}));
  // Unused node 5 dropped; corners keep their tags, edge nodes are new.
  ASSERT_EQ(mesh.file_tags.size(), 9u);
  EXPECT_EQ(std::vector<Index>(mesh.file_tags.begin(), mesh.file_tags.begin() + 4),
            (std::vector<Index>{1, 2, 3, 4}));
  for (std::size_t n = 4; n < 9; ++n) EXPECT_EQ(mesh.file_tags[n], -1);
  ASSERT_EQ(mesh.node_sets.size(), 1u);
  EXPECT_EQ(mesh.node_sets[0].name, "pin");
  EXPECT_EQ(mesh.node_sets[0].dimension, 0);
  EXPECT_EQ(mesh.node_sets[0].nodes, std::vector<Index>{0});
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"tissue"});
  EXPECT_EQ(mesh.triangle_region, (std::vector<int>{0, 0}));
}

TEST(SectionMeshReadGmsh, QuadraticTriangles) {
  ScratchDir dir;
  const SectionMesh mesh =
      biphasic::read_gmsh_section(dir.write("square6.msh", quadratic_square()));
  expect_unit_square(mesh);
  EXPECT_EQ(mesh.boundary_names(), (std::vector<std::string>{"bottom", "lateral", "top", "7"}));
  // Every node keeps its tag: corners 1–4, then edge nodes 5–9.
  EXPECT_EQ(mesh.file_tags, (std::vector<Index>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(mesh.nodes[8], (Point2{0.5, 0.5}));  // tag 9: the diagonal's midside node
  EXPECT_TRUE(mesh.triangle_region.empty());
  EXPECT_TRUE(mesh.region_names.empty());
  EXPECT_TRUE(mesh.node_sets.empty());
}

TEST(SectionMeshReadGmsh, NodeOffThePlaneIsRefused) {
  ScratchDir dir;
  const std::string path = dir.write("lifted.msh", linear_square("0.5"));
  const std::string message = error_of([&] { biphasic::read_gmsh_section(path); });
  EXPECT_CONTAINS(message, "read_gmsh_section");
  EXPECT_CONTAINS(message, path);
  EXPECT_CONTAINS(message, "node tag 3");
  EXPECT_CONTAINS(message, "z = 0.5");
}

TEST(SectionMeshReadGmsh, MissingFileAndMixedOrdersNameTheFile) {
  const std::string missing = "/nonexistent/dir/no_such_section.msh";
  const std::string message = error_of([&] { biphasic::read_gmsh_section(missing); });
  EXPECT_CONTAINS(message, missing);
  EXPECT_CONTAINS(message, "does not exist");

  ScratchDir dir;
  std::string mixed = quadratic_square();
  mixed.replace(mixed.find("6 9 2 0 1 1 4 3 8 7 9"), 21, "6 2 2 0 1 1 4 3");
  const std::string path = dir.write("mixed.msh", mixed);
  const std::string mixed_message = error_of([&] { biphasic::read_gmsh_section(path); });
  EXPECT_CONTAINS(mixed_message, path);
  EXPECT_CONTAINS(mixed_message, "mixed element orders");
}

TEST(SectionMeshReadGmsh, CurveOffTheTrianglesNamesTheCurve) {
  ScratchDir dir;
  std::string text = linear_square();
  text.replace(text.find("2 1 2 1 1 1 2"), 13, "2 1 2 1 1 5 2");  // node 5 is no corner
  const std::string path = dir.write("stray.msh", text);
  const std::string message = error_of([&] { biphasic::read_gmsh_section(path); });
  EXPECT_CONTAINS(message, path);
  EXPECT_CONTAINS(message, "physical curve 'bottom'");
  EXPECT_CONTAINS(message, "node tag 5");

  // Nodes 2 and 4 are corners but not the ends of one triangle edge (the diagonal is 1–3).
  text = linear_square();
  text.replace(text.find("2 1 2 1 1 1 2"), 13, "2 1 2 1 1 2 4");
  const std::string across = dir.write("across.msh", text);
  const std::string across_message = error_of([&] { biphasic::read_gmsh_section(across); });
  EXPECT_CONTAINS(across_message, across);
  EXPECT_CONTAINS(across_message,
                  "physical curve 'bottom' line (element tag 2) is not an edge of any triangle");
}

// The .geo of docs/section_meshes.md, meshed by gmsh at order 1 (format 2.2) and 2 (format 4.1).
TEST(SectionMeshReadGmsh, DocumentedGeoFileIsRead) {
  ScratchDir dir;
  const std::string geo =
      std::string(BIPHASIC_SOURCE_DIR) + "/tests/mesh/data/section_rectangle.geo";
  for (const int order : {1, 2}) {
    SCOPED_TRACE("order " + std::to_string(order));
    const std::string msh = dir.file("section_" + std::to_string(order) + ".msh");
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(geo);
    gmsh::model::mesh::generate(2);
    gmsh::model::mesh::setOrder(order);
    gmsh::option::setNumber("Mesh.MshFileVersion", order == 1 ? 2.2 : 4.1);
    gmsh::write(msh);
    gmsh::finalize();

    const SectionMesh mesh = biphasic::read_gmsh_section(msh);
    EXPECT_NEAR(area_of(mesh), 18.0 * 8.0, 1e-9);
    EXPECT_EQ(mesh.boundary_names(),
              (std::vector<std::string>{"axis", "lateral", "bottom", "top"}));
    EXPECT_NEAR(curve_length(mesh, "axis"), 8.0, 1e-12);
    EXPECT_NEAR(curve_length(mesh, "lateral"), 8.0, 1e-12);
    EXPECT_NEAR(curve_length(mesh, "bottom"), 18.0, 1e-12);
    EXPECT_NEAR(curve_length(mesh, "top"), 18.0, 1e-12);
    const std::vector<std::pair<std::string, Point2>> normals{
        {"axis", {-1, 0}}, {"lateral", {1, 0}}, {"bottom", {0, -1}}, {"top", {0, 1}}};
    for (const auto& [name, normal] : normals) {
      for (const auto& s : mesh.find_boundary(name)->segments) {
        const Point2& a = mesh.nodes[s[0]];
        const Point2& b = mesh.nodes[s[1]];
        const double l = length(a, b);
        EXPECT_NEAR((b[1] - a[1]) / l, normal[0], 1e-12) << name;
        EXPECT_NEAR(-(b[0] - a[0]) / l, normal[1], 1e-12) << name;
      }
    }
    EXPECT_EQ(mesh.region_names, std::vector<std::string>{"tissue"});
    EXPECT_EQ(mesh.triangle_region, std::vector<int>(mesh.triangles.size(), 0));
    ASSERT_NE(mesh.find_node_set("pin"), nullptr);
    ASSERT_EQ(mesh.find_node_set("pin")->nodes.size(), 1u);
    EXPECT_EQ(mesh.nodes[mesh.find_node_set("pin")->nodes[0]], (Point2{0, 0}));
    EXPECT_EQ(mesh.file_tags.size(), static_cast<std::size_t>(mesh.num_nodes()));
  }
}

}  // namespace
