// make_p2_from_linear, orientation and invariant checks on hand-built meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "p2_geometry.hpp"

namespace {

using biphasic::Index;
using biphasic::Mesh;
using biphasic::Point;
using Corners4 = std::array<Index, 4>;
using Corners3 = std::array<Index, 3>;
using NamedFaces = std::vector<std::pair<std::string, std::vector<Corners3>>>;

// Unit cube corners, index i + 2j + 4k for the corner (i, j, k).
std::vector<Point> cube_vertices() {
  std::vector<Point> v;
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) v.push_back({double(i), double(j), double(k)});
    }
  }
  return v;
}

// The six tets of the cube along the diagonal (0,0,0)–(1,1,1): for each axis permutation
// (p, q, r) the path 0 → e_p → e_p + e_q → (1,1,1). Half of them come out inverted.
std::vector<Corners4> cube_tets() {
  const std::array<Index, 3> unit{1, 2, 4};
  std::array<int, 3> perm{0, 1, 2};
  std::vector<Corners4> tets;
  do {
    const Index a = unit[perm[0]];
    const Index b = a + unit[perm[1]];
    tets.push_back({0, a, b, 7});
  } while (std::next_permutation(perm.begin(), perm.end()));
  return tets;
}

// z = 0 and x = 0 faces, split along the diagonals through (0,0,0) that the tets use.
NamedFaces cube_faces() {
  return {{"bottom", {{0, 1, 3}, {0, 2, 3}}}, {"left", {{0, 2, 6}, {0, 4, 6}}}};
}

Point midpoint(const Point& a, const Point& b) {
  return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
}

TEST(MeshBasics, FindBoundaryAndNames) {
  Mesh mesh;
  mesh.boundaries = {{"top", {}}, {"bottom", {}}};
  ASSERT_NE(mesh.find_boundary("bottom"), nullptr);
  EXPECT_EQ(mesh.find_boundary("bottom"), &mesh.boundaries[1]);
  EXPECT_EQ(mesh.find_boundary("lateral"), nullptr);
  EXPECT_EQ(mesh.boundary_names(), (std::vector<std::string>{"top", "bottom"}));
}

TEST(MeshBasics, SignedVolumeOfUnitCornerTet) {
  const Point o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_DOUBLE_EQ(biphasic::tet_signed_volume(o, x, y, z), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(biphasic::tet_signed_volume(o, y, x, z), -1.0 / 6.0);
}

TEST(MeshP2FromLinear, CubeOfSixTets) {
  const std::vector<Point> vertices = cube_vertices();
  const Mesh mesh = biphasic::make_p2_from_linear(vertices, cube_tets(), cube_faces());

  // 8 corners + 12 cube edges + 6 face diagonals + 1 space diagonal.
  EXPECT_EQ(mesh.num_vertices, 8);
  EXPECT_EQ(mesh.num_nodes(), 27);
  ASSERT_EQ(mesh.tets.size(), 6u);
  for (Index v = 0; v < 8; ++v) EXPECT_EQ(mesh.nodes[v], vertices[v]) << "vertex " << v;

  // Every edge node is the midpoint of its edge; tets sharing an edge share its node.
  std::map<std::pair<Index, Index>, Index> edge_node;
  std::set<Index> edge_nodes;
  double volume = 0.0;
  for (const auto& tet : mesh.tets) {
    EXPECT_GT(biphasic::tet_signed_volume(mesh.nodes[tet[0]], mesh.nodes[tet[1]],
                                          mesh.nodes[tet[2]], mesh.nodes[tet[3]]),
              0.0);
    volume += p2test::tet_volume(mesh, tet);
    for (int e = 0; e < 6; ++e) {
      const Index a = tet[biphasic::kTetEdges[e][0]], b = tet[biphasic::kTetEdges[e][1]];
      const Index n = tet[4 + e];
      EXPECT_GE(n, 8);
      EXPECT_EQ(mesh.nodes[n], midpoint(mesh.nodes[a], mesh.nodes[b]));
      const auto [it, inserted] = edge_node.emplace(std::minmax(a, b), n);
      EXPECT_EQ(it->second, n);
      edge_nodes.insert(n);
    }
  }
  EXPECT_EQ(edge_node.size(), 19u);
  EXPECT_EQ(edge_nodes.size(), 19u);
  EXPECT_NEAR(volume, 1.0, 1e-14);

  // Boundary faces reuse the tets' edge nodes and point out of the cube.
  ASSERT_EQ(mesh.boundary_names(), (std::vector<std::string>{"bottom", "left"}));
  const std::map<std::string, Point> outward{{"bottom", {0, 0, -1}}, {"left", {-1, 0, 0}}};
  for (const auto& boundary : mesh.boundaries) {
    ASSERT_EQ(boundary.faces.size(), 2u);
    double area = 0.0;
    for (const auto& face : boundary.faces) {
      for (int e = 0; e < 3; ++e) {
        const Index a = face[biphasic::kTriEdges[e][0]], b = face[biphasic::kTriEdges[e][1]];
        ASSERT_TRUE(edge_node.count(std::minmax(a, b)));
        EXPECT_EQ(face[3 + e], edge_node.at(std::minmax(a, b)));
      }
      EXPECT_EQ(p2test::corner_normal(mesh, face), outward.at(boundary.name));
      area += p2test::tri_area(mesh, face);
    }
    EXPECT_NEAR(area, 1.0, 1e-14) << boundary.name;
  }
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));
}

TEST(MeshP2FromLinear, InvertedTetIsReoriented) {
  // Corners 1 and 2 exchanged: negative volume in the given order.
  const std::vector<Point> vertices{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  const Mesh mesh = biphasic::make_p2_from_linear(vertices, {{0, 1, 2, 3}}, {});
  ASSERT_EQ(mesh.tets.size(), 1u);
  const auto& tet = mesh.tets[0];
  EXPECT_NEAR(biphasic::tet_signed_volume(mesh, 0), 1.0 / 6.0, 1e-15);
  EXPECT_EQ((std::array<Index, 4>{tet[0], tet[1], tet[2], tet[3]}),
            (std::array<Index, 4>{0, 2, 1, 3}));
  for (int e = 0; e < 6; ++e) {
    const Point expected = midpoint(mesh.nodes[tet[biphasic::kTetEdges[e][0]]],
                                    mesh.nodes[tet[biphasic::kTetEdges[e][1]]]);
    EXPECT_EQ(mesh.nodes[tet[4 + e]], expected) << "local edge node " << 4 + e;
  }
}

TEST(MeshP2FromLinear, UnusedVerticesAreDropped) {
  const std::vector<Point> vertices{{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Mesh mesh =
      biphasic::make_p2_from_linear(vertices, {{1, 2, 3, 4}}, {{"base", {{1, 3, 2}}}});
  EXPECT_EQ(mesh.num_vertices, 4);
  EXPECT_EQ(mesh.num_nodes(), 10);
  EXPECT_EQ(mesh.nodes[0], (Point{0, 0, 0}));
  EXPECT_EQ((std::array<Index, 3>{mesh.boundaries[0].faces[0][0], mesh.boundaries[0].faces[0][1],
                                  mesh.boundaries[0].faces[0][2]}),
            (std::array<Index, 3>{0, 2, 1}));
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));
}

TEST(MeshP2FromLinear, FaceEdgeThatIsNoTetEdgeIsAnError) {
  // (1,0,0)–(0,1,0) is a diagonal the six tets do not use.
  const NamedFaces faces{{"bottom", {{0, 1, 3}, {1, 2, 3}}}};
  try {
    biphasic::make_p2_from_linear(cube_vertices(), cube_tets(), faces);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("boundary 'bottom' face 1"), std::string::npos) << message;
    EXPECT_NE(message.find("(1, 2)"), std::string::npos) << message;
  }
}

TEST(MeshP2FromLinear, IndexOutOfRangeIsAnError) {
  const std::vector<Point> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_THROW(biphasic::make_p2_from_linear(vertices, {{0, 1, 2, 4}}, {}), std::runtime_error);
  EXPECT_THROW(biphasic::make_p2_from_linear(vertices, {{0, 1, 2, 3}}, {{"b", {{0, 1, 7}}}}),
               std::runtime_error);
}

TEST(MeshP2FromLinear, DegenerateTetIsAnErrorNamingItAndItsVolume) {
  const std::vector<Point> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  try {
    biphasic::make_p2_from_linear(vertices, {{0, 1, 2, 3}, {0, 1, 2, 4}}, {});
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("tetrahedron 1"), std::string::npos) << message;
    EXPECT_NE(message.find("volume 0"), std::string::npos) << message;
  }
}

TEST(MeshCheck, DetectsBrokenInvariants) {
  const Mesh good = biphasic::make_p2_from_linear(cube_vertices(), cube_tets(), cube_faces());
  ASSERT_NO_THROW(biphasic::check_mesh(good));

  Mesh inverted = good;  // corners 1, 2 exchanged without fixing the edge nodes
  std::swap(inverted.tets[0][1], inverted.tets[0][2]);
  EXPECT_THROW(biphasic::check_mesh(inverted), std::runtime_error);

  Mesh wrong_edge_node = good;  // two edge nodes of a tet exchanged (both edges shared)
  std::swap(wrong_edge_node.tets[2][4], wrong_edge_node.tets[2][7]);
  EXPECT_THROW(biphasic::check_mesh(wrong_edge_node), std::runtime_error);

  Mesh wrong_face = good;  // a face whose edge node is not the tets' one
  std::swap(wrong_face.boundaries[0].faces[0][3], wrong_face.boundaries[0].faces[0][4]);
  EXPECT_THROW(biphasic::check_mesh(wrong_face), std::runtime_error);

  Mesh edge_as_corner = good;  // an edge node counted as a vertex
  edge_as_corner.num_vertices = 9;
  EXPECT_THROW(biphasic::check_mesh(edge_as_corner), std::runtime_error);
}

TEST(MeshOrientTets, FixesQuadraticTetAndKeepsEdgeNodesOnTheirEdges) {
  // A 10-node tet given with corners 1 and 2 exchanged and its edge nodes in the matching
  // (inverted) local order; every edge node is displaced off its midpoint by (0.1, 0.1, 0.1).
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  mesh.num_vertices = 4;
  biphasic::Tet10 tet{0, 1, 2, 3};
  for (int e = 0; e < 6; ++e) {
    Point m =
        midpoint(mesh.nodes[biphasic::kTetEdges[e][0]], mesh.nodes[biphasic::kTetEdges[e][1]]);
    for (double& c : m) c += 0.1;
    tet[4 + e] = mesh.num_nodes();
    mesh.nodes.push_back(m);
  }
  mesh.tets = {tet};
  biphasic::orient_tets(mesh);
  const auto& t = mesh.tets[0];
  EXPECT_GT(biphasic::tet_signed_volume(mesh, 0), 0.0);
  for (int e = 0; e < 6; ++e) {
    Point m = midpoint(mesh.nodes[t[biphasic::kTetEdges[e][0]]],
                       mesh.nodes[t[biphasic::kTetEdges[e][1]]]);
    for (double& c : m) c += 0.1;
    EXPECT_EQ(mesh.nodes[t[4 + e]], m) << "local edge node " << 4 + e;
  }
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));
}

}  // namespace
