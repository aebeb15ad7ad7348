// LineProbe node selection and sampling, interpolate_on_line, LineCsvWriter round trip.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/io/line_probe.hpp"
#include "cube_mesh.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;

constexpr double kEdge = 2.0;  // cube edge length [mm]
constexpr double kTol = 1e-9;  // [mm]

/// Index of the node at x (exact match), or -1.
Index node_at(const Mesh& mesh, const Point& x) {
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (mesh.nodes[n] == x) return static_cast<Index>(n);
  }
  return -1;
}

std::vector<double> vertex_field(const Mesh& mesh, double (*f)(const Point&)) {
  std::vector<double> p;
  for (Index v = 0; v < mesh.num_vertices; ++v) p.push_back(f(mesh.nodes[v]));
  return p;
}

std::string error_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(LineProbe, PicksAxisEdgeNodesInOrder) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const LineProbe probe(mesh, {0, 0, 0}, {kEdge, 0, 0}, kTol);
  ASSERT_EQ(probe.size(), 3u);
  EXPECT_EQ(probe.node(0), 0);
  EXPECT_EQ(probe.node(1), node_at(mesh, {1, 0, 0}));
  EXPECT_EQ(probe.node(2), 1);
  EXPECT_EQ(probe.s(), (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_TRUE(probe.is_vertex(0));
  EXPECT_FALSE(probe.is_vertex(1));
  EXPECT_TRUE(probe.is_vertex(2));
  EXPECT_EQ(probe.position(1), (Point{1, 0, 0}));
}

TEST(LineProbe, OrdersFromTheStartPoint) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const LineProbe probe(mesh, {kEdge, 0, 0}, {0, 0, 0}, kTol);
  ASSERT_EQ(probe.size(), 3u);
  EXPECT_EQ(probe.node(0), 1);
  EXPECT_EQ(probe.node(2), 0);
  EXPECT_EQ(probe.s(), (std::vector<double>{0.0, 1.0, 2.0}));
}

TEST(LineProbe, PicksCubeDiagonal) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const LineProbe probe(mesh, {0, 0, 0}, {kEdge, kEdge, kEdge}, kTol);
  ASSERT_EQ(probe.size(), 3u);
  EXPECT_EQ(probe.node(0), 0);
  EXPECT_EQ(probe.node(1), node_at(mesh, {1, 1, 1}));
  EXPECT_EQ(probe.node(2), 7);
  EXPECT_DOUBLE_EQ(probe.s()[0], 0.0);
  EXPECT_DOUBLE_EQ(probe.s()[1], std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(probe.s()[2], 2.0 * std::sqrt(3.0));
}

TEST(LineProbe, LinearPressureIsExactOnEdgeNodes) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const auto p = vertex_field(mesh, [](const Point& x) { return 0.25 + 0.5 * x[2]; });
  const LineProbe probe(mesh, {0, kEdge, 0}, {0, kEdge, kEdge}, kTol);
  ASSERT_EQ(probe.size(), 3u);
  EXPECT_FALSE(probe.is_vertex(1));
  EXPECT_EQ(probe.pressure(p), (std::vector<double>{0.25, 0.75, 1.25}));
}

TEST(LineProbe, EdgeNodeTakesItsOwnEdgeNotTheProbeLine) {
  // The z = 0 face is split along (0,0,0)-(2,2,0); the probe runs along the other diagonal,
  // whose midpoint is that edge's node. Its pressure is the mean of vertices 0 and 3.
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const LineProbe probe(mesh, {kEdge, 0, 0}, {0, kEdge, 0}, kTol);
  ASSERT_EQ(probe.size(), 3u);
  EXPECT_EQ(probe.node(0), 1);
  EXPECT_EQ(probe.node(1), node_at(mesh, {1, 1, 0}));
  EXPECT_EQ(probe.node(2), 2);
  std::vector<double> p(8, 0.0);
  p[0] = 4.0;
  p[1] = 100.0;
  p[2] = 300.0;
  p[3] = 6.0;
  EXPECT_EQ(probe.pressure(p), (std::vector<double>{100.0, 5.0, 300.0}));
}

TEST(LineProbe, DisplacementOfProbeNodes) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  std::vector<double> u(3 * mesh.nodes.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i) + 0.5;
  const LineProbe probe(mesh, {0, 0, 0}, {kEdge, 0, 0}, kTol);
  const auto mid = static_cast<double>(node_at(mesh, {1, 0, 0}));
  EXPECT_EQ(probe.displacement(u, 1),
            (std::array<double, 3>{3 * mid + 0.5, 3 * mid + 1.5, 3 * mid + 2.5}));
  EXPECT_EQ(probe.displacement(u, 2), (std::array<double, 3>{3.5, 4.5, 5.5}));
  EXPECT_NE(error_of([&] { probe.displacement(std::vector<double>(80), 0); }).find("81"),
            std::string::npos);
  EXPECT_THROW(probe.displacement(u, 3), std::runtime_error);
  EXPECT_NE(error_of([&] { probe.pressure(std::vector<double>(27)); }).find("expected 8"),
            std::string::npos);
}

TEST(LineProbe, ToleranceDecidesWhatLiesOnTheLine) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const Point a{0, 1e-6, 0};
  const Point b{kEdge, 1e-6, 0};
  EXPECT_EQ(LineProbe(mesh, a, b, 1e-5).size(), 3u);
  EXPECT_THROW(LineProbe(mesh, a, b, 1e-7), std::runtime_error);
}

TEST(LineProbe, ThrowsWithClearMessageWhenTooFewVertices) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  // Half an edge: one vertex and one edge node.
  const std::string half = error_of([&] { LineProbe(mesh, {0, 0, 0}, {1, 0, 0}, 0.001); });
  EXPECT_NE(half.find("(0, 0, 0)"), std::string::npos) << half;
  EXPECT_NE(half.find("(1, 0, 0)"), std::string::npos) << half;
  EXPECT_NE(half.find("0.001"), std::string::npos) << half;
  EXPECT_NE(half.find("1 mesh vertices"), std::string::npos) << half;
  // Through the cube centre parallel to x: three edge nodes, no vertex.
  const std::string centre = error_of([&] { LineProbe(mesh, {0, 1, 1}, {kEdge, 1, 1}, kTol); });
  EXPECT_NE(centre.find("0 mesh vertices"), std::string::npos) << centre;
  EXPECT_THROW(LineProbe(mesh, {1, 1, 1}, {1, 1, 1}, kTol), std::runtime_error);
  EXPECT_THROW(LineProbe(mesh, {0, 0, 0}, {kEdge, 0, 0}, -1.0), std::runtime_error);
}

// The mesh-node sampling is kept only where the line runs along the mesh from end to end.
TEST(LineProbe, RunsAlongTheMeshOnlyFromEndToEndThroughElements) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  // The cube's diagonal is an edge of all six elements; a face diagonal crosses two faces'
  // triangles from node to node (vertex 1, the edge node of (0,0,0)-(2,2,0), vertex 2).
  EXPECT_TRUE(runs_along_mesh(LineProbe(mesh, {0, 0, 0}, {kEdge, kEdge, kEdge}, kTol), mesh));
  EXPECT_TRUE(runs_along_mesh(LineProbe(mesh, {kEdge, 0, 0}, {0, kEdge, 0}, kTol), mesh));
  // Past the body at either end: the end point is not a node.
  EXPECT_FALSE(runs_along_mesh(LineProbe(mesh, {0, 0, 0}, {2 * kEdge, 0, 0}, kTol), mesh));
  EXPECT_FALSE(runs_along_mesh(LineProbe(mesh, {-0.5, 0, 0}, {kEdge, 0, 0}, kTol), mesh));
  // Given samples are not mesh nodes.
  const LineProbe given({0, 0, 0}, {1, 0, 0},
                        {ProbeSample{0.0, {0, 0, 0}, {{0, 1.0}}, {{0, 1.0}}},
                         ProbeSample{1.0, {1, 0, 0}, {{1, 1.0}}, {{1, 1.0}}}},
                        mesh.num_nodes(), mesh.num_vertices);
  EXPECT_FALSE(given.at_mesh_nodes());
  EXPECT_EQ(given.node(0), -1);
  EXPECT_FALSE(runs_along_mesh(given, mesh));
}

TEST(LineProbe, GivenSamplesAreWeightedSums) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const Index mid = node_at(mesh, {1, 0, 0});
  const LineProbe probe(
      {0, 0, 0}, {kEdge, 0, 0},
      {ProbeSample{
           0.5, {0.5, 0, 0}, {{0, 0.375}, {mid, 0.75}, {1, -0.125}}, {{0, 0.75}, {1, 0.25}}},
       ProbeSample{2.0, {kEdge, 0, 0}, {{1, 1.0}}, {{1, 1.0}}}},
      mesh.num_nodes(), mesh.num_vertices);
  std::vector<double> u(3 * mesh.nodes.size(), 0.0);
  u[0] = 8.0;                                  // node 0, x
  u[3 * static_cast<std::size_t>(mid)] = 4.0;  // edge node, x
  u[3] = -16.0;                                // node 1, x
  std::vector<double> p(8, 0.0);
  p[0] = 4.0;
  p[1] = 8.0;
  EXPECT_EQ(probe.displacement(u, 0)[0], 0.375 * 8.0 + 0.75 * 4.0 + 0.125 * 16.0);
  EXPECT_EQ(probe.pressure(p), (std::vector<double>{5.0, 8.0}));
  // Out-of-range weights and decreasing s are refused.
  auto make = [&](Index node, double s1) {
    return LineProbe({0, 0, 0}, {1, 0, 0},
                     {ProbeSample{0.0, {0, 0, 0}, {{node, 1.0}}, {{0, 1.0}}},
                      ProbeSample{s1, {1, 0, 0}, {{1, 1.0}}, {{1, 1.0}}}},
                     mesh.num_nodes(), mesh.num_vertices);
  };
  EXPECT_THROW(make(27, 1.0), std::runtime_error);
  EXPECT_THROW(make(0, -1.0), std::runtime_error);
  EXPECT_NO_THROW(make(26, 1.0));
}

TEST(InterpolateOnLine, PiecewiseLinearAndClamped) {
  const std::vector<double> s{0.0, 1.0, 3.0};
  const std::vector<double> f{2.0, 4.0, 0.0};
  EXPECT_EQ(interpolate_on_line(s, f, -1.0), 2.0);
  EXPECT_EQ(interpolate_on_line(s, f, 0.0), 2.0);
  EXPECT_EQ(interpolate_on_line(s, f, 0.5), 3.0);
  EXPECT_EQ(interpolate_on_line(s, f, 1.0), 4.0);
  EXPECT_EQ(interpolate_on_line(s, f, 2.0), 2.0);
  EXPECT_EQ(interpolate_on_line(s, f, 2.5), 1.0);
  EXPECT_EQ(interpolate_on_line(s, f, 3.0), 0.0);
  EXPECT_EQ(interpolate_on_line(s, f, 7.0), 0.0);
  EXPECT_EQ(interpolate_on_line({1.0}, {9.0}, 0.0), 9.0);
  EXPECT_EQ(interpolate_on_line({0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 5.0, 6.0}, 1.5), 5.5);
}

TEST(InterpolateOnLine, RejectsBadInput) {
  EXPECT_THROW(interpolate_on_line({}, {}, 0.0), std::runtime_error);
  EXPECT_THROW(interpolate_on_line({0.0, 1.0}, {1.0}, 0.0), std::runtime_error);
  EXPECT_THROW(interpolate_on_line({1.0, 0.0}, {1.0, 2.0}, 0.5), std::runtime_error);
}

/// Splits a CSV line at commas.
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

TEST(LineCsvWriter, RowsParseBackToTheValuesWritten) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const LineProbe probe(mesh, {0, 0, 0}, {kEdge, kEdge, kEdge}, kTol);
  const fs::path path = fs::path(::testing::TempDir()) /
                        ("biphasic_output_csv_" + std::to_string(getpid())) / "sub" / "line.csv";
  fs::remove_all(path.parent_path().parent_path());

  const std::vector<double> times{0.0, 1.0 / 3.0};
  std::vector<std::vector<double>> us;
  std::vector<std::vector<double>> ps;
  for (double t : times) {
    std::vector<double> u(3 * mesh.nodes.size());
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = (t + 0.1) * std::sqrt(static_cast<double>(i));
    std::vector<double> p(8);
    for (std::size_t v = 0; v < p.size(); ++v) p[v] = std::exp(-t * static_cast<double>(v)) / 7.0;
    us.push_back(u);
    ps.push_back(p);
  }

  LineCsvWriter writer(path.string());
  for (std::size_t k = 0; k < times.size(); ++k) writer.write(times[k], probe, us[k], ps[k]);
  EXPECT_THROW(writer.write(0.0, probe, us[0], std::vector<double>(3)), std::runtime_error);

  // Read while the writer is still open: every write must already be on disk.
  std::ifstream in(path);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "t,s,x,y,z,ux,uy,uz,p");
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto p = probe.pressure(ps[k]);
    for (std::size_t i = 0; i < probe.size(); ++i) {
      ASSERT_TRUE(std::getline(in, line)) << "missing row " << i << " of output " << k;
      const auto cells = split(line);
      ASSERT_EQ(cells.size(), 9u) << line;
      std::vector<double> v;
      for (const auto& c : cells) v.push_back(std::strtod(c.c_str(), nullptr));
      const auto u = probe.displacement(us[k], i);
      const auto& x = probe.position(i);
      const std::vector<double> expected{times[k], probe.s()[i], x[0], x[1], x[2],
                                         u[0],     u[1],         u[2], p[i]};
      EXPECT_EQ(v, expected) << line;
    }
  }
  EXPECT_FALSE(std::getline(in, line)) << "unexpected row: " << line;
  fs::remove_all(path.parent_path().parent_path());
}

TEST(LineCsvWriter, FailsWithPathWhenFileCannotBeOpened) {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("biphasic_output_csv_blocked_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "line.csv");  // a folder where the file should go
  const std::string msg = error_of([&] { LineCsvWriter((dir / "line.csv").string()); });
  EXPECT_NE(msg.find("line.csv"), std::string::npos) << msg;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace biphasic
