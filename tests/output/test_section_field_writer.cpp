// FieldWriter on a section mesh: Triangle_6 cells at z = 0, the displacement with a third
// component 0, the pressure on edge nodes the mean of their edge's vertices, restarts.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "../common/h5_reader.hpp"
#include "biphasic/io/field_writer.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "cube_mesh.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;
using test::H5Reader;

struct TempDir {
  explicit TempDir(const std::string& name)
      : path(fs::path(::testing::TempDir()) /
             ("biphasic_section_output_" + name + "_" + std::to_string(getpid()))) {
    fs::remove_all(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  fs::path path;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

SectionMesh small_section(int nr = 3, int nz = 2) {
  SectionRectangleSpec spec;
  spec.width = 3.0;
  spec.height = 2.0;
  spec.nr = nr;
  spec.nz = nz;
  return generate_section_rectangle(spec);
}

/// u = (0.1 r + 0.01 z², −0.2 z + 0.03 r z), 2 per node, scaled by s.
std::vector<double> make_u2(const SectionMesh& mesh, double s) {
  std::vector<double> u;
  for (const Point2& x : mesh.nodes) {
    u.push_back(s * (0.1 * x[0] + 0.01 * x[1] * x[1]));
    u.push_back(s * (-0.2 * x[1] + 0.03 * x[0] * x[1]));
  }
  return u;
}

/// p = s (1 + 0.5 r − 0.25 z²) on the vertices: the edge nodes' mean differs from p there.
std::vector<double> make_p(const SectionMesh& mesh, double s) {
  std::vector<double> p;
  for (Index v = 0; v < mesh.num_vertices; ++v) {
    const Point2& x = mesh.nodes[v];
    p.push_back(s * (1.0 + 0.5 * x[0] - 0.25 * x[1] * x[1]));
  }
  return p;
}

TEST(SectionFieldWriter, WritesTriangle6AtZeroWithPlanarDisplacement) {
  const SectionMesh mesh = small_section();
  const TempDir dir("fields");
  FieldLayout layout;
  layout.cells.push_back({"J", 1, "-"});
  {
    FieldWriter writer(dir.path.string(), "fields", mesh, layout);
    std::vector<double> J(mesh.triangles.size(), 1.0);
    for (double t : {0.0, 0.5}) writer.write(t, make_u2(mesh, 1.0 + t), make_p(mesh, 1.0 + t), {J});
  }
  const auto nn = static_cast<std::size_t>(mesh.num_nodes());
  const auto ne = mesh.triangles.size();
  const H5Reader h5(dir.path / "fields.h5");
  EXPECT_EQ(h5.dims("/mesh/coordinates"), (std::vector<hsize_t>{nn, 3}));
  EXPECT_EQ(h5.dims("/mesh/topology"), (std::vector<hsize_t>{ne, 6}));
  const auto xyz = h5.read<double>("/mesh/coordinates", H5T_NATIVE_DOUBLE);
  for (std::size_t n = 0; n < nn; ++n) {
    EXPECT_EQ(xyz[3 * n], mesh.nodes[n][0]);
    EXPECT_EQ(xyz[3 * n + 1], mesh.nodes[n][1]);
    EXPECT_EQ(xyz[3 * n + 2], 0.0) << "node " << n;
  }
  const auto topo = h5.read<std::int64_t>("/mesh/topology", H5T_NATIVE_INT64);
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < 6; ++a) EXPECT_EQ(topo[6 * e + a], mesh.triangles[e][a]);
  EXPECT_EQ(h5.read<std::int64_t>("/mesh/vertex_count", H5T_NATIVE_INT64).at(0), mesh.num_vertices);

  for (int step : {0, 1}) {
    const double s = 1.0 + 0.5 * step;
    const std::string i = std::to_string(step);
    const auto u = h5.read<double>("/fields/displacement/" + i, H5T_NATIVE_DOUBLE);
    const std::vector<double> u2 = make_u2(mesh, s);
    ASSERT_EQ(u.size(), 3 * nn);
    for (std::size_t n = 0; n < nn; ++n) {
      EXPECT_EQ(u[3 * n], u2[2 * n]);
      EXPECT_EQ(u[3 * n + 1], u2[2 * n + 1]);
      EXPECT_EQ(u[3 * n + 2], 0.0) << "node " << n;
    }
    const auto p = h5.read<double>("/fields/pressure/" + i, H5T_NATIVE_DOUBLE);
    const std::vector<double> pv = make_p(mesh, s);
    ASSERT_EQ(p.size(), nn);
    // Every triangle's edge node carries the mean of its edge's two corners.
    for (const Tri6& tri : mesh.triangles) {
      for (std::size_t k = 0; k < kTriEdges.size(); ++k) {
        const double mean = 0.5 * (pv[tri[kTriEdges[k][0]]] + pv[tri[kTriEdges[k][1]]]);
        EXPECT_DOUBLE_EQ(p[tri[3 + k]], mean);
      }
      for (int c = 0; c < 3; ++c) EXPECT_EQ(p[tri[c]], pv[tri[c]]);
    }
    EXPECT_EQ(h5.read<double>("/fields/pressure_vertices/" + i, H5T_NATIVE_DOUBLE), pv);
  }

  const std::string xdmf = read_text(dir.path / "fields.xdmf");
  const std::string e = std::to_string(ne);
  EXPECT_NE(xdmf.find("TopologyType=\"Triangle_6\" NumberOfElements=\"" + e + "\""),
            std::string::npos)
      << xdmf;
  EXPECT_NE(xdmf.find("Dimensions=\"" + e + " 6\""), std::string::npos);
  EXPECT_EQ(xdmf.find("Tetrahedron"), std::string::npos);
  EXPECT_NE(xdmf.find("GeometryType=\"XYZ\""), std::string::npos);
  EXPECT_NE(xdmf.find("Dimensions=\"" + std::to_string(nn) + " 3\""), std::string::npos);
}

TEST(SectionFieldWriter, EdgeNodesOfAGeneratedSectionAreTheirEdgesMidpoints) {
  const SectionMesh mesh = small_section();
  const auto edges = edge_node_vertices(mesh);
  ASSERT_EQ(edges.size(), static_cast<std::size_t>(mesh.num_nodes() - mesh.num_vertices));
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Point2& x = mesh.nodes[mesh.num_vertices + k];
    for (int d = 0; d < 2; ++d)
      EXPECT_NEAR(x[d], 0.5 * (mesh.nodes[edges[k][0]][d] + mesh.nodes[edges[k][1]][d]), 1e-14);
  }
}

TEST(SectionFieldWriter, RefusesAThreeComponentDisplacement) {
  const SectionMesh mesh = small_section();
  const TempDir dir("sizes");
  FieldWriter writer(dir.path.string(), "fields", mesh);
  const std::vector<double> u3(3 * static_cast<std::size_t>(mesh.num_nodes()), 0.0);
  try {
    writer.write(0.0, u3, make_p(mesh, 1.0));
    FAIL() << "a 3-per-node displacement was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("expected 2 x"), std::string::npos) << e.what();
  }
}

TEST(SectionFieldWriter, RestartKeepsEarlierOutputsAndAppends) {
  const SectionMesh mesh = small_section();
  const TempDir dir("restart");
  const std::string d = dir.path.string();
  {
    FieldWriter first(d, "fields", mesh);
    for (double t : {0.0, 1.0, 2.0}) first.write(t, make_u2(mesh, t), make_p(mesh, t));
  }
  {
    FieldWriter again(d, "fields", mesh, 1.0);
    EXPECT_EQ(again.times(), (std::vector<double>{0.0, 1.0}));
    const H5Reader h5(dir.path / "fields.h5");
    EXPECT_TRUE(h5.exists("/fields/displacement/1"));
    EXPECT_FALSE(h5.exists("/fields/displacement/2"));
    EXPECT_FALSE(h5.exists("/fields/pressure/2"));
  }
  {
    FieldWriter again(d, "fields", mesh, 1.0);
    again.write(1.5, make_u2(mesh, 1.5), make_p(mesh, 1.5));
    EXPECT_EQ(again.times(), (std::vector<double>{0.0, 1.0, 1.5}));
  }
  const H5Reader h5(dir.path / "fields.h5");
  EXPECT_EQ(h5.read<double>("/fields/times", H5T_NATIVE_DOUBLE),
            (std::vector<double>{0.0, 1.0, 1.5}));
  EXPECT_EQ(h5.time_attribute("/fields/displacement/2"), 1.5);
  const auto u = h5.read<double>("/fields/displacement/2", H5T_NATIVE_DOUBLE);
  EXPECT_EQ(u[3], make_u2(mesh, 1.5)[2]);
  EXPECT_EQ(u[5], 0.0);
  const std::string xdmf = read_text(dir.path / "fields.xdmf");
  EXPECT_NE(xdmf.find("<Time Value=\"1.5\"/>"), std::string::npos);
  EXPECT_EQ(xdmf.find("<Time Value=\"2\"/>"), std::string::npos);
}

TEST(SectionFieldWriter, RestartRefusesTheFilesOfAnotherMesh) {
  const SectionMesh mesh = small_section(3, 2);
  const TempDir dir("other");
  const std::string d = dir.path.string();
  {
    FieldWriter first(d, "fields", mesh);
    first.write(0.0, make_u2(mesh, 0.0), make_p(mesh, 0.0));
  }
  const SectionMesh other = small_section(4, 2);
  try {
    FieldWriter again(d, "fields", other, 0.0);
    FAIL() << "the files of another section were continued";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("another mesh"), std::string::npos) << e.what();
  }
}

TEST(SectionFieldWriter, RestartRefusesTetrahedralFilesWithTheSameNodeCount) {
  const Mesh cube = test::make_cube_mesh(2.0);
  const SectionMesh section = small_section(1, 4);  // 3 × 9 nodes, like the cube's 27
  ASSERT_EQ(section.num_nodes(), cube.num_nodes());
  const TempDir dir("tets");
  const std::string d = dir.path.string();
  {
    FieldWriter first(d, "fields", cube);
    first.write(0.0, std::vector<double>(3 * cube.nodes.size(), 0.0),
                std::vector<double>(static_cast<std::size_t>(cube.num_vertices), 0.0));
  }
  try {
    FieldWriter again(d, "fields", section, 0.0);
    FAIL() << "a tetrahedral file was continued with a section mesh";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("Triangle_6"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace biphasic
