// Probes on section meshes: node probes along the mesh (the nodes on the axis, in order),
// interpolated probes that reproduce a quadratic displacement and a linear pressure exactly,
// point location in curved triangles, refusals naming the case-file key, and the probe CSV of
// a section problem with its drained ends.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "biphasic/app/probes.hpp"
#include "biphasic/fe/section_locator.hpp"
#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/field_writer.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {
namespace {

SectionMesh graded_rectangle() {
  SectionRectangleSpec spec;
  spec.width = 2.0;
  spec.height = 1.5;
  spec.nr = 4;
  spec.nz = 5;
  spec.grading_curves = {"top", "axis"};
  spec.grading_ratio = 2.5;
  return generate_section_rectangle(spec);
}

/// A quadratic in-plane displacement [mm] with every second-order term.
std::array<double, 2> g(double x, double y) {
  return {0.1 + 0.3 * x - 0.2 * y + 0.05 * x * x + 0.07 * x * y - 0.03 * y * y,
          -0.2 + 0.1 * y + 0.04 * x * y - 0.06 * y * y + 0.02 * x * x};
}
/// A linear pressure [MPa].
double h(double x, double y) { return 0.3 - 0.25 * x + 0.5 * y; }

Config probe_config() {
  Config cfg;
  cfg.case_file = "case.toml";
  cfg.output.line = false;
  return cfg;
}

TEST(SectionProbes, NodeProbeAlongTheAxisSamplesTheAxisNodesInOrder) {
  const SectionMesh mesh = graded_rectangle();
  Config cfg = probe_config();
  cfg.output.line = true;
  cfg.output.line_start = {0.0, 0.0, 0.0};
  cfg.output.line_end = {0.0, 1.5, 0.0};  // (r, z, 0): the axis r = 0
  const std::vector<Probe> probes = build_section_probes(cfg, mesh);
  ASSERT_EQ(probes.size(), 1u);
  const LineProbe& s = probes[0].samples;
  EXPECT_TRUE(probes[0].measured);
  ASSERT_TRUE(s.at_mesh_nodes());
  EXPECT_TRUE(runs_along_mesh(s, mesh));
  std::vector<Index> axis;
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.nodes[n][0] == 0.0) axis.push_back(n);
  std::sort(axis.begin(), axis.end(),
            [&](Index l, Index r) { return mesh.nodes[l][1] < mesh.nodes[r][1]; });
  ASSERT_EQ(s.size(), axis.size());
  EXPECT_EQ(axis.size(), 2u * 5u + 1u);
  for (std::size_t i = 0; i < axis.size(); ++i) {
    EXPECT_EQ(s.node(i), axis[i]) << "sample " << i;
    EXPECT_EQ(s.position(i), (Point{0.0, mesh.nodes[axis[i]][1], 0.0}));
    EXPECT_NEAR(s.s()[i], mesh.nodes[axis[i]][1], 1e-15);
  }
  const std::vector<std::string> lines = check_section_probes(cfg, mesh);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("11 mesh nodes"), std::string::npos) << lines[0];
}

TEST(SectionProbes, InterpolatedProbeReproducesQuadraticUAndLinearP) {
  const SectionMesh mesh = graded_rectangle();
  Config cfg = probe_config();
  cfg.output.probes.push_back({"diagonal", {0.13, 0.07, 0.0}, {1.91, 1.37, 0.0}, 37});
  cfg.output.probes.push_back({"edge", {2.0, 0.0, 0.0}, {2.0, 1.5, 0.0}, 9});  // on the boundary
  const std::vector<Probe> probes = build_section_probes(cfg, mesh);
  ASSERT_EQ(probes.size(), 2u);
  std::vector<double> u2, p;
  for (const Point2& x : mesh.nodes) {
    const auto v = g(x[0], x[1]);
    u2.insert(u2.end(), v.begin(), v.end());
  }
  for (Index v = 0; v < mesh.num_vertices; ++v) p.push_back(h(mesh.nodes[v][0], mesh.nodes[v][1]));
  const std::vector<double> u = displacement_in_3d(u2);
  for (const Probe& probe : probes) {
    const LineProbe& s = probe.samples;
    EXPECT_FALSE(s.at_mesh_nodes());
    const std::vector<double> pressure = s.pressure(p);
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Point& x = s.position(i);
      EXPECT_EQ(x[2], 0.0);
      const auto expected = g(x[0], x[1]);
      const auto got = s.displacement(u, i);
      EXPECT_NEAR(got[0], expected[0], 1e-13) << probe.name << " sample " << i;
      EXPECT_NEAR(got[1], expected[1], 1e-13) << probe.name << " sample " << i;
      EXPECT_EQ(got[2], 0.0);
      EXPECT_NEAR(pressure[i], h(x[0], x[1]), 1e-13) << probe.name << " sample " << i;
      EXPECT_EQ(s.sample(i).u_weights.size(), 6u);
      EXPECT_EQ(s.sample(i).p_weights.size(), 3u);
    }
  }
  EXPECT_EQ(probes[0].samples.size(), 37u);
}

TEST(SectionProbes, PointsOffTheMeshLinesFallBackToInterpolation) {
  const SectionMesh mesh = graded_rectangle();
  Config cfg = probe_config();
  cfg.output.probes.push_back({"slant", {0.0, 0.0, 0.0}, {2.0, 1.5, 0.0}, 0});
  const std::vector<Probe> probes = build_section_probes(cfg, mesh);
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_FALSE(probes[0].samples.at_mesh_nodes());
  EXPECT_EQ(probes[0].samples.size(), static_cast<std::size_t>(kDefaultProbePoints));
}

TEST(SectionProbes, RefusesPointsOffThePlaneOrOutsideNamingTheKey) {
  const SectionMesh mesh = graded_rectangle();
  {
    Config cfg = probe_config();
    cfg.output.probes.push_back({"lifted", {0.5, 0.0, 0.0}, {0.5, 1.0, 0.25}, 5});
    try {
      build_section_probes(cfg, mesh);
      FAIL() << "a probe with z != 0 was accepted";
    } catch (const CaseError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("case.toml: probe[0] \"lifted\""), std::string::npos) << what;
      EXPECT_NE(what.find("probe[0].end"), std::string::npos) << what;
      EXPECT_EQ(what.find("probe[0].start"), std::string::npos) << what;
      EXPECT_NE(what.find("z = 0.25"), std::string::npos) << what;
    }
  }
  {
    Config cfg = probe_config();
    cfg.output.line = true;
    cfg.output.line_start = {0.0, 0.0, 1.0};
    cfg.output.line_end = {0.0, 1.5, 0.0};
    try {
      check_section_probes(cfg, mesh);
      FAIL() << "a probe line with z != 0 was accepted";
    } catch (const CaseError& e) {
      EXPECT_NE(std::string(e.what()).find("output.line_start"), std::string::npos) << e.what();
    }
  }
  {
    Config cfg = probe_config();
    cfg.output.probes.push_back({"out", {0.5, 0.5, 0.0}, {3.0, 0.5, 0.0}, 11});
    try {
      build_section_probes(cfg, mesh);
      FAIL() << "a probe leaving the section was accepted";
    } catch (const CaseError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("case.toml: probe[0] \"out\""), std::string::npos) << what;
      EXPECT_NE(what.find("outside"), std::string::npos) << what;
    }
  }
}

TEST(SectionLocator, InvertsACurvedTriangle) {
  // Corners (0,0), (2,0), (0,2); the edge node of (1,2) pushed outward.
  std::array<Point2, 6> X{Point2{0, 0}, {2, 0}, {0, 2}, {1, 0}, {1.3, 1.3}, {0, 1}};
  for (const std::array<double, 2>& eta :
       {std::array<double, 2>{0.2, 0.3}, {0.45, 0.5}, {0.1, 0.85}, {1.0 / 3, 1.0 / 3}}) {
    const Eigen::Matrix<double, 6, 1> N = tri6_values(eta);
    Point2 x{0.0, 0.0};
    for (int a = 0; a < 6; ++a)
      for (int d = 0; d < 2; ++d) x[d] += N(a) * X[a][d];
    const SectionPointLocation loc = locate_in_triangle(X, x);
    EXPECT_NEAR(loc.eta[0], eta[0], 1e-12);
    EXPECT_NEAR(loc.eta[1], eta[1], 1e-12);
    EXPECT_EQ(loc.distance_outside, 0.0);
  }
  // 0.1 mm below the edge y = 0: an estimate from the curved map's gradients, exact once the
  // triangle is straight.
  EXPECT_NEAR(locate_in_triangle(X, {0.5, -0.1}).distance_outside, 0.1, 5e-3);
  X[4] = {1.0, 1.0};
  EXPECT_NEAR(locate_in_triangle(X, {0.5, -0.1}).distance_outside, 0.1, 1e-14);
}

TEST(SectionProbes, RecorderWritesTheExpandedDisplacementAndFindsTheDrainedEnd) {
  const SectionMesh mesh = graded_rectangle();
  Config cfg = probe_config();
  cfg.material = MaterialConfig::neo_hookean(0.2, 0.5, 1e-3);
  cfg.bcs.push_back({BcType::Pressure, "top", 0, 0.0, {}, ""});
  const SectionProblem problem(mesh, SectionModel::Axisymmetric, cfg);
  cfg.output.line = true;
  cfg.output.line_start = {0.0, 0.0, 0.0};
  cfg.output.line_end = {0.0, 1.5, 0.0};
  std::vector<Probe> probes = build_section_probes(cfg, mesh);
  EXPECT_EQ(drained_ends(probes[0].samples, problem), DrainedEnds::End);
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("biphasic_section_probes_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  {
    ProbeRecorder recorder(std::move(probes), problem, dir.string());
    std::vector<double> u2(static_cast<std::size_t>(problem.num_u()), 0.0);
    for (Index n = 0; n < mesh.num_nodes(); ++n) u2[2 * n + 1] = -0.1 * mesh.nodes[n][1];
    std::vector<double> p(static_cast<std::size_t>(mesh.num_vertices), 0.0);
    for (Index v = 0; v < mesh.num_vertices; ++v) p[v] = 1.5 - mesh.nodes[v][1];
    const auto measures = recorder.write(0.5, displacement_in_3d(u2), p);
    ASSERT_TRUE(measures.has_value());
    EXPECT_NEAR(measures->p_mid, 0.75, 1e-14);
  }
  std::ifstream in(dir / "line.csv");
  std::string header, first, last, line;
  std::getline(in, header);
  std::getline(in, first);
  while (std::getline(in, line)) last = line;
  EXPECT_EQ(header, "t,s,x,y,z,ux,uy,uz,p");
  EXPECT_EQ(first, "0.5,0,0,0,0,0,-0,0,1.5");
  EXPECT_EQ(last, "0.5,1.5,0,1.5,0,0,-0.15000000000000002,0,0");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace biphasic
