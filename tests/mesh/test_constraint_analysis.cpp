// Rigid modes left free by fixed displacement components, connected parts, coincident nodes,
// and the physical points and curves of .msh files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "biphasic/mesh/coincident_nodes.hpp"
#include "biphasic/mesh/constraint_analysis.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace {

using namespace biphasic;

Mesh column() {
  ColumnSpec spec;
  spec.width = 2.0;
  spec.depth = 1.0;
  spec.height = 3.0;
  spec.nx = 2;
  spec.ny = 1;
  spec.nz = 3;
  return generate_column(spec);
}

/// Every node of boundary `name`, fixed in `component`.
std::vector<FixedComponent> fix(const Mesh& mesh, const std::string& name, int component) {
  std::vector<FixedComponent> out;
  std::vector<Index> nodes;
  for (const Tri6& f : mesh.find_boundary(name)->faces)
    nodes.insert(nodes.end(), f.begin(), f.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  for (Index n : nodes) out.push_back({n, component});
  return out;
}

std::vector<FixedComponent> operator+(std::vector<FixedComponent> a,
                                      const std::vector<FixedComponent>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<std::string> descriptions(const PartFreedom& part) {
  std::vector<std::string> out;
  for (const FreeMode& m : part.free) out.push_back(m.description);
  return out;
}

TEST(ConstraintAnalysis, NothingFixedLeavesAllSixModesFree) {
  const Mesh mesh = column();
  const auto parts = free_rigid_modes(mesh, {});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].free.size(), 6u);
  EXPECT_EQ(parts[0].tets, static_cast<Index>(mesh.tets.size()));
}

TEST(ConstraintAnalysis, FrictionlessPlatensLeaveTheInPlaneMotionsFree) {
  const Mesh mesh = column();
  const auto parts = free_rigid_modes(mesh, fix(mesh, "bottom", 2) + fix(mesh, "top", 2));
  ASSERT_EQ(parts.size(), 1u);
  const auto d = descriptions(parts[0]);
  ASSERT_EQ(d.size(), 3u) << ::testing::PrintToString(d);
  EXPECT_EQ(d[0], "translation x");
  EXPECT_EQ(d[1], "translation y");
  // With x and y free as well, the axis may be any vertical line.
  EXPECT_EQ(d[2], "rotation about z");
}

TEST(ConstraintAnalysis, RollersOnThreeFacesHoldEverything) {
  const Mesh mesh = column();
  const auto parts =
      free_rigid_modes(mesh, fix(mesh, "bottom", 2) + fix(mesh, "x0", 0) + fix(mesh, "y0", 1));
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_TRUE(parts[0].free.empty()) << ::testing::PrintToString(descriptions(parts[0]));
}

TEST(ConstraintAnalysis, APinnedNodeLeavesRotationsAboutItself) {
  const Mesh mesh = column();
  // The corner vertex at (2, 1, 3) mm, fixed in all three components.
  Index pin = -1;
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.nodes[n] == Point{2.0, 1.0, 3.0}) pin = n;
  ASSERT_GE(pin, 0);
  const auto parts = free_rigid_modes(mesh, {{pin, 0}, {pin, 1}, {pin, 2}});
  const auto d = descriptions(parts.at(0));
  ASSERT_EQ(d.size(), 3u) << ::testing::PrintToString(d);
  // Each axis passes through the pin; named by its point nearest the centroid (1, 0.5, 1.5).
  EXPECT_EQ(d[0], "rotation about x through (1, 1, 3) mm");
  EXPECT_EQ(d[1], "rotation about y through (2, 0.5, 3) mm");
  EXPECT_EQ(d[2], "rotation about z through (2, 1, 1.5) mm");
}

TEST(ConstraintAnalysis, AnUnconnectedPartIsAnalysedOnItsOwn) {
  Mesh mesh = column();
  // A second copy of the column, 10 mm away in x, sharing no node with the first.
  const Mesh other = column();
  const Index offset = mesh.num_nodes();
  Mesh both;
  for (const Point& x : mesh.nodes) both.nodes.push_back(x);
  for (Point x : other.nodes) {
    x[0] += 10.0;
    both.nodes.push_back(x);
  }
  both.num_vertices = both.num_nodes();  // (the corner-first invariant is not needed here)
  both.tets = mesh.tets;
  for (Tet10 t : other.tets) {
    for (Index& n : t) n += offset;
    both.tets.push_back(t);
  }
  both.boundaries = mesh.boundaries;
  const MeshParts parts = connected_parts(both);
  EXPECT_EQ(parts.count, 2);
  const auto freedom =
      free_rigid_modes(both, fix(both, "bottom", 2) + fix(both, "x0", 0) + fix(both, "y0", 1));
  ASSERT_EQ(freedom.size(), 2u);
  EXPECT_TRUE(freedom[0].free.empty());
  EXPECT_EQ(freedom[1].free.size(), 6u);
  EXPECT_NEAR(freedom[1].centroid[0], 11.0, 1e-12);
}

TEST(CoincidentNodes, SoundMeshHasNoneAndADuplicatedNodeIsFound) {
  Mesh mesh = column();
  const double tolerance = coincidence_tolerance(mesh);
  EXPECT_GT(tolerance, 0.0);
  EXPECT_TRUE(coincident_nodes(mesh, tolerance).empty());
  // Cut the mesh at vertex 0: a copy of it takes its place in the first tetrahedron using it.
  const Index copy = mesh.num_nodes();
  mesh.nodes.push_back(mesh.nodes[0]);
  for (Tet10& t : mesh.tets) {
    auto it = std::find(t.begin(), t.end(), Index{0});
    if (it != t.end()) {
      *it = copy;
      break;
    }
  }
  const auto pairs = coincident_nodes(mesh, tolerance);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], std::make_pair(Index{0}, copy));
}

std::string fixture(const std::string& name) {
  return std::string(BIPHASIC_SOURCE_DIR) + "/tests/mesh/data/" + name;
}

TEST(MeshNodeSets, PhysicalPointsAndCurvesBecomeNodeSetsWithTheirEdgeNodes) {
  for (const char* file : {"full_cylinder_tet4_v22.msh", "full_cylinder_tet10_v41.msh"}) {
    const Mesh mesh = read_gmsh(fixture(file));
    ASSERT_EQ(mesh.file_tags.size(), mesh.nodes.size()) << file;
    const NodeSet* axis = mesh.find_node_set("axis");
    const NodeSet* rim = mesh.find_node_set("rim");
    ASSERT_NE(axis, nullptr) << file;
    ASSERT_NE(rim, nullptr) << file;
    EXPECT_EQ(axis->dimension, 1);
    EXPECT_EQ(rim->dimension, 0);
    ASSERT_EQ(rim->nodes.size(), 1u);
    EXPECT_NEAR(mesh.nodes[rim->nodes[0]][0], 2.0, 1e-12);
    EXPECT_NEAR(mesh.nodes[rim->nodes[0]][1], 0.0, 1e-12);
    // The axis from z = 0 to 1.5 mm: segment ends and midpoints alternate, 2k + 1 nodes.
    std::vector<double> z;
    for (Index n : axis->nodes) {
      EXPECT_NEAR(mesh.nodes[n][0], 0.0, 1e-12) << file;
      EXPECT_NEAR(mesh.nodes[n][1], 0.0, 1e-12) << file;
      z.push_back(mesh.nodes[n][2]);
    }
    std::sort(z.begin(), z.end());
    ASSERT_GE(z.size(), 3u);
    EXPECT_EQ(z.size() % 2, 1u) << file;
    EXPECT_NEAR(z.front(), 0.0, 1e-12);
    EXPECT_NEAR(z.back(), 1.5, 1e-12);
    for (std::size_t k = 1; k + 1 < z.size(); k += 2)
      EXPECT_NEAR(z[k], 0.5 * (z[k - 1] + z[k + 1]), 1e-9) << file << " midpoint " << k;
    // Not a boundary: conditions find it by name among the node sets.
    EXPECT_EQ(mesh.find_boundary("axis"), nullptr);
  }
}

}  // namespace

namespace {

TEST(MeshNodeSets, GeneratedMeshesHaveNoFileTagsOrNodeSets) {
  biphasic::QuarterCylinderSpec spec;
  spec.lc = 4.0;
  const biphasic::Mesh mesh = biphasic::generate_quarter_cylinder(spec);
  // Nothing the mesh cache would lose: messages name nodes by index and position only.
  EXPECT_TRUE(mesh.file_tags.empty());
  EXPECT_TRUE(mesh.node_sets.empty());
  EXPECT_EQ(mesh.describe_node(0).find("file tag"), std::string::npos);
}

}  // namespace

namespace {

// A name shared by two sets would let a boundary condition silently pick one of them.
TEST(MeshNodeSets, ANameSharedBySetsOfTwoKindsIsRefused) {
  using biphasic::Mesh;
  using biphasic::NodeSet;
  const Mesh sound = column();
  auto message_for = [&](const std::vector<NodeSet>& sets) -> std::string {
    Mesh mesh = sound;
    mesh.node_sets = sets;
    try {
      biphasic::check_mesh(mesh);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(message_for({{"pin", 0, {0}}, {"edge", 1, {0, 1}}}), "accepted");
  EXPECT_NE(message_for({{"pin", 0, {0}}, {"pin", 1, {0, 1}}})
                .find("'pin' is given to a physical point and a physical curve"),
            std::string::npos);
  EXPECT_NE(message_for({{"top", 1, {0}}}).find("'top' is given to a physical surface"),
            std::string::npos);
  EXPECT_NE(message_for({{"pin", 0, {sound.num_nodes()}}}).find("is not a node index"),
            std::string::npos);
}

}  // namespace
