// read_gmsh: formats 2.2 and 4.1, linear and 10-node tetrahedra, hand-made fixtures with
// known node positions, and error reporting.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/mixed_order_msh.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "p2_geometry.hpp"

namespace {

namespace fs = std::filesystem;
using biphasic::Index;
using biphasic::Mesh;
using biphasic::Point;
using biphasic::mixed_order_msh::write_binary_v22;
using biphasic::mixed_order_msh::write_mixed_binary_v22;
using biphasic::mixed_order_msh::write_mixed_binary_v41;

std::string fixture(const std::string& name) {
  return std::string(BIPHASIC_SOURCE_DIR) + "/tests/mesh/data/" + name;
}

// A scratch directory private to the running test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("biphasic_mesh_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

std::string error_of(const std::string& path) {
  try {
    biphasic::read_gmsh(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

double distance(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// Same counts, names, connectivity of corners, and positions of all ten nodes of every tet
// and six nodes of every face (edge-node numbering may differ between linear and quadratic
// input).
void expect_same_mesh(const Mesh& a, const Mesh& b, double tol, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(a.num_vertices, b.num_vertices);
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  ASSERT_EQ(a.tets.size(), b.tets.size());
  ASSERT_EQ(a.boundary_names(), b.boundary_names());
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    ASSERT_EQ(a.boundaries[i].faces.size(), b.boundaries[i].faces.size()) << a.boundaries[i].name;
  }
  double worst = 0.0;
  for (Index v = 0; v < a.num_vertices; ++v) {
    worst = std::max(worst, distance(a.nodes[v], b.nodes[v]));
  }
  for (std::size_t t = 0; t < a.tets.size(); ++t) {
    for (int k = 0; k < 4; ++k) ASSERT_EQ(a.tets[t][k], b.tets[t][k]) << "tet " << t;
    for (int k = 0; k < 10; ++k) {
      worst = std::max(worst, distance(a.nodes[a.tets[t][k]], b.nodes[b.tets[t][k]]));
    }
  }
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    for (std::size_t f = 0; f < a.boundaries[i].faces.size(); ++f) {
      const auto& fa = a.boundaries[i].faces[f];
      const auto& fb = b.boundaries[i].faces[f];
      for (int k = 0; k < 3; ++k) ASSERT_EQ(fa[k], fb[k]);
      for (int k = 0; k < 6; ++k) worst = std::max(worst, distance(a.nodes[fa[k]], b.nodes[fb[k]]));
    }
  }
  EXPECT_LE(worst, tol);
}

TEST(MeshReadGmsh, MissingFileNamesThePath) {
  const std::string path = "/nonexistent/dir/no_such_mesh.msh";
  const std::string message = error_of(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

TEST(MeshReadGmsh, FileWithoutTetrahedraIsAnError) {
  const std::string path = fixture("no_tets_v22.msh");
  const std::string message = error_of(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("no tetrahedra"), std::string::npos) << message;
}

// One volume holding a 10-node and a 4-node tet (2.2), and a 4-node before a 10-node (4.1).
TEST(MeshReadGmsh, MixedElementOrdersAreAnError) {
  for (const char* name : {"mixed_orders_v22.msh", "mixed_orders_v41.msh"}) {
    const std::string path = fixture(name);
    const std::string message = error_of(path);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("mixed element orders"), std::string::npos) << message;
  }
}

// Binary files used to skip the scan for mixed orders and corrupted the heap inside gmsh.
TEST(MeshReadGmsh, MixedElementOrdersInBinaryFilesAreAnError) {
  ScratchDir dir;
  write_mixed_binary_v41(dir.file("mixed_v41_binary.msh"));
  write_mixed_binary_v22(dir.file("mixed_v22_binary.msh"));
  for (const char* name : {"mixed_v41_binary.msh", "mixed_v22_binary.msh"}) {
    const std::string path = dir.file(name);
    const std::string message = error_of(path);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("mixed element orders: both 4-node and 10-node tetrahedra"),
              std::string::npos)
        << message;
  }
}

// gmsh 4.8's 2.x reader reports an element naming an undefined node and then dereferences it
// (a segmentation fault found by fuzzing): the reader must refuse such files first, in ASCII
// and in binary.
TEST(MeshReadGmsh, ElementNamingAnUndefinedNodeIsAnError) {
  ScratchDir dir;
  const std::string binary = dir.file("missing_node_v22_binary.msh");
  // type 4, one element, 2 tags; element 2: nodes 1 3 2 4
  write_binary_v22(binary, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 1, {4, 1, 2, 2, 3, 1, 3, 2, 4});
  for (const std::string& path : {fixture("missing_node_v22.msh"), binary}) {
    const std::string message = error_of(path);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("element 2 names node 4, which no $Nodes section before it defines"),
              std::string::npos)
        << message;
  }
}

// gmsh's 2.x reader goes on past a section it cannot read; the scan must too, or a garbled
// $Elements section ahead of the real ones hides an undefined node from it (a segmentation
// fault found by fuzzing).
TEST(MeshReadGmsh, UndefinedNodeAfterAGarbledSectionIsAnError) {
  ScratchDir dir;
  const std::string path = dir.file("garbled_then_missing_node_v22.msh");
  std::ofstream(path) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\nnot a count\n"
                         "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n"
                         "2 4 2 2 3 1 3 2 4\n$EndElements\n";
  const std::string message = error_of(path);
  EXPECT_NE(message.find("element 2 names node 4, which no $Nodes section before it defines"),
            std::string::npos)
      << message;
}

// gmsh 4.8 crashes converting unexpected partition numbers of a 2.x file (found by fuzzing):
// elements with partition tags are refused, in ASCII and in binary.
TEST(MeshReadGmsh, PartitionedFormat2FileIsAnError) {
  ScratchDir dir;
  const std::string ascii = dir.file("partitioned_v22.msh");
  std::ofstream(ascii) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"
                          "3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n"
                          "7 4 4 1 1 1 -3 1 3 2 4\n$EndElements\n";
  const std::string binary = dir.file("partitioned_v22_binary.msh");
  // type 4, one element, 4 tags; element 7: tags 1 1 1 99999, nodes 1 3 2 4
  write_binary_v22(binary, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 1,
                   {4, 1, 4, 7, 1, 1, 1, 99999, 1, 3, 2, 4});
  for (const std::string& path : {ascii, binary}) {
    const std::string message = error_of(path);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("element 7 has 4 tags, which place it in mesh partitions"),
              std::string::npos)
        << message;
  }
}

// gmsh 4.8's 4.x reader crashes on a physical name of a dimension outside 0-3 (a segmentation
// fault found by fuzzing): the reader must refuse it first, naming the entry, in ASCII and in
// binary files (whose $PhysicalNames section is text) and in format 2.2 as well.
TEST(MeshReadGmsh, PhysicalNameOfAnImpossibleDimensionIsAnError) {
  ScratchDir dir;
  struct Variant {
    const char* source;
    const char* entry;
    const char* replacement;
    const char* expected;
  };
  const Variant variants[] = {
      {"two_tet10_v41.msh", "3 2 \"solid\"", "6 2 \"solid\"",
       "$PhysicalNames entry 2 (6 2 \"solid\") has dimension 6"},
      {"two_tet10_v41.msh", "2 1 \"base\"", "-1 1 \"base\"",
       "$PhysicalNames entry 1 (-1 1 \"base\") has dimension -1"},
      {"two_tet10_v22.msh", "3 2 \"solid\"", "4 2 \"solid\"",
       "$PhysicalNames entry 2 (4 2 \"solid\") has dimension 4"},
      {"full_cylinder_tet10_v41_binary.msh", "2 2 \"top\"", "5 2 \"top\"",
       "$PhysicalNames entry 4 (5 2 \"top\") has dimension 5"},
  };
  int k = 0;
  for (const Variant& v : variants) {
    std::string text;
    {
      std::ifstream in(fixture(v.source), std::ios::binary);
      text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const auto at = text.find(v.entry);
    ASSERT_NE(at, std::string::npos) << v.source;
    text.replace(at, std::string(v.entry).size(), v.replacement);
    const std::string path = dir.file("physical_dim_" + std::to_string(k++) + ".msh");
    std::ofstream(path, std::ios::binary) << text;
    const std::string message = error_of(path);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(v.expected), std::string::npos) << message;
    EXPECT_NE(message.find("a physical group has dimension 0, 1, 2 or 3"), std::string::npos)
        << message;
  }
  // The unmodified files are still read.
  for (const char* name : {"two_tet10_v41.msh", "two_tet10_v22.msh"}) {
    EXPECT_NO_THROW(biphasic::read_gmsh(fixture(name))) << name;
  }
}

// A binary file as gmsh writes it is read (the scan skips its element blocks correctly, so a
// sound binary file is not refused).
TEST(MeshReadGmsh, BinaryFilesWrittenByGmshAreRead) {
  ScratchDir dir;
  for (const char* name : {"two_tet10_v22.msh", "two_tet10_v41.msh"}) {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(fixture(name));
    gmsh::option::setNumber("Mesh.Binary", 1);
    // A physical volume, so that the tets are written (unless the file has one: a second one
    // over the same tets would put them in two regions, which the reader refuses).
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, 3);
    if (groups.empty()) {
      gmsh::vectorpair volumes;
      gmsh::model::getEntities(volumes, 3);
      std::vector<int> tags;
      for (const auto& [dim, tag] : volumes) tags.push_back(tag);
      gmsh::model::addPhysicalGroup(3, tags);
    }
    gmsh::option::setNumber("Mesh.MshFileVersion", name[11] == '2' ? 2.2 : 4.1);
    const std::string binary = dir.file(std::string("binary_") + name);
    gmsh::write(binary);
    gmsh::finalize();
    Mesh mesh;
    EXPECT_NO_THROW(mesh = biphasic::read_gmsh(binary)) << name;
    EXPECT_FALSE(mesh.tets.empty()) << name;
    EXPECT_EQ(mesh.region_names, std::vector<std::string>{"solid"}) << name;
  }
}

// A tet in two physical volumes of different names is refused, naming its element tag.
TEST(MeshReadGmsh, TetInTwoPhysicalVolumesIsAnError) {
  ScratchDir dir;
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(fixture("two_tet10_v41.msh"));
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  std::vector<int> tags;
  for (const auto& [dim, tag] : volumes) tags.push_back(tag);
  const int group = gmsh::model::addPhysicalGroup(3, tags);
  gmsh::model::setPhysicalName(3, group, "bone");
  const std::string path = dir.file("two_volumes.msh");
  gmsh::write(path);
  gmsh::finalize();
  const std::string error = error_of(path);
  EXPECT_NE(error.find("is in two physical volumes"), std::string::npos) << error;
  EXPECT_NE(error.find("'bone'"), std::string::npos) << error;
  EXPECT_NE(error.find("element tag"), std::string::npos) << error;
}

TEST(MeshReadGmsh, BoundaryNodeOutsideTheTetsIsAnError) {
  const std::string path = fixture("stray_face_v22.msh");
  const std::string message = error_of(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("'base'"), std::string::npos) << message;
  EXPECT_NE(message.find("node tag 5"), std::string::npos) << message;
}

TEST(MeshReadGmsh, GarbageFileIsAnError) {
  ScratchDir dir;
  const std::string path = dir.file("garbage.msh");
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\nthree\n", f);
    std::fclose(f);
  }
  const std::string message = error_of(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST(MeshReadGmsh, InvertedLinearTetIsReorientedAndUnusedNodeDropped) {
  const Mesh mesh = biphasic::read_gmsh(fixture("inverted_tet4_v22.msh"));
  EXPECT_EQ(mesh.num_vertices, 4);
  EXPECT_EQ(mesh.num_nodes(), 10);  // node (7, 7, 7) belongs to no tet
  ASSERT_EQ(mesh.tets.size(), 1u);
  EXPECT_NEAR(biphasic::tet_signed_volume(mesh, 0), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(p2test::tet_volume(mesh, mesh.tets[0]), 1.0 / 6.0, 1e-15);
  ASSERT_EQ(mesh.boundary_names(), std::vector<std::string>{"base"});
  ASSERT_EQ(mesh.boundaries[0].faces.size(), 1u);
  const Point n = p2test::corner_normal(mesh, mesh.boundaries[0].faces[0]);
  EXPECT_EQ(n, (Point{0, 0, -1}));
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));
}

// Fixtures (same mesh in formats 2.2 and 4.1): two 10-node tets whose edge nodes sit at
// midpoint + (1, 1, 1)/16; the second is written inverted and translated by x + 2. Its base
// face is in an unnamed physical group 7.
void expect_two_tet10_fixture(const Mesh& mesh) {
  EXPECT_EQ(mesh.num_vertices, 8);
  EXPECT_EQ(mesh.num_nodes(), 20);
  ASSERT_EQ(mesh.tets.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    const auto& tet = mesh.tets[t];
    EXPECT_NEAR(biphasic::tet_signed_volume(mesh, static_cast<Index>(t)), 1.0 / 6.0, 1e-15);
    for (int e = 0; e < 6; ++e) {
      const Point& a = mesh.nodes[tet[biphasic::kTetEdges[e][0]]];
      const Point& b = mesh.nodes[tet[biphasic::kTetEdges[e][1]]];
      const Point expected{0.5 * (a[0] + b[0]) + 0.0625, 0.5 * (a[1] + b[1]) + 0.0625,
                           0.5 * (a[2] + b[2]) + 0.0625};
      EXPECT_EQ(mesh.nodes[tet[4 + e]], expected) << "tet " << t << " local node " << 4 + e;
    }
  }
  ASSERT_EQ(mesh.boundary_names(), (std::vector<std::string>{"base", "7"}));
  for (const auto& boundary : mesh.boundaries) {
    ASSERT_EQ(boundary.faces.size(), 1u);
    EXPECT_EQ(p2test::corner_normal(mesh, boundary.faces[0]), (Point{0, 0, -1})) << boundary.name;
  }
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));  // faces share the tets' edge nodes
}

TEST(MeshReadGmsh, TenNodeTetsKeepTheirEdgeNodesInOurLocalOrder) {
  const Mesh v22 = biphasic::read_gmsh(fixture("two_tet10_v22.msh"));
  const Mesh v41 = biphasic::read_gmsh(fixture("two_tet10_v41.msh"));
  {
    SCOPED_TRACE("format 2.2");
    expect_two_tet10_fixture(v22);
  }
  {
    SCOPED_TRACE("format 4.1");
    expect_two_tet10_fixture(v41);
  }
  EXPECT_EQ(v22.nodes, v41.nodes);
  EXPECT_EQ(v22.tets, v41.tets);
}

// Writes a 2 × 1 × 1 box meshed by gmsh as linear and 10-node tets in formats 2.2 and 4.1.
// Physical groups: "xmin" (x = 0), unnamed 5 (x = 2), volume "solid". Needs a running gmsh.
void write_box_files(const ScratchDir& dir) {
  gmsh::model::add("box");
  gmsh::model::occ::addBox(0, 0, 0, 2, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    if (x1 - x0 < 1e-6 && std::abs(x0) < 1e-6) {
      gmsh::model::addPhysicalGroup(2, {tag}, 1);
      gmsh::model::setPhysicalName(2, 1, "xmin");
    }
    if (x1 - x0 < 1e-6 && std::abs(x0 - 2) < 1e-6) gmsh::model::addPhysicalGroup(2, {tag}, 5);
  }
  gmsh::model::addPhysicalGroup(3, {1}, 1);
  gmsh::model::setPhysicalName(3, 1, "solid");
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.4);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.4);
  gmsh::model::mesh::generate(3);
  for (const double version : {2.2, 4.1}) {
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::write(dir.file(version < 3 ? "box_tet4_v22.msh" : "box_tet4_v41.msh"));
  }
  gmsh::model::mesh::setOrder(2);
  for (const double version : {2.2, 4.1}) {
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::write(dir.file(version < 3 ? "box_tet10_v22.msh" : "box_tet10_v41.msh"));
  }
}

TEST(MeshReadGmsh, FormatsAndOrdersGiveTheSameBoxMesh) {
  ScratchDir dir;
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  write_box_files(dir);

  // Read while the outer session is alive: it must survive untouched.
  const Mesh reference = biphasic::read_gmsh(dir.file("box_tet10_v41.msh"));
  const Mesh tet10_v22 = biphasic::read_gmsh(dir.file("box_tet10_v22.msh"));
  std::string current;
  gmsh::model::getCurrent(current);
  EXPECT_EQ(current, "box");
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  EXPECT_EQ(volumes.size(), 1u);
  gmsh::finalize();

  // And with no session running.
  const Mesh tet4_v22 = biphasic::read_gmsh(dir.file("box_tet4_v22.msh"));
  const Mesh tet4_v41 = biphasic::read_gmsh(dir.file("box_tet4_v41.msh"));

  ASSERT_EQ(reference.boundary_names(), (std::vector<std::string>{"xmin", "5"}));
  EXPECT_GT(reference.tets.size(), 50u);
  double volume = 0.0;
  for (const auto& tet : reference.tets) volume += p2test::tet_volume(reference, tet);
  EXPECT_NEAR(volume, 2.0, 1e-12);
  for (const auto& boundary : reference.boundaries) {
    double area = 0.0;
    for (const auto& face : boundary.faces) area += p2test::tri_area(reference, face);
    EXPECT_NEAR(area, 1.0, 1e-12) << boundary.name;
  }
  EXPECT_NO_THROW(biphasic::check_mesh(reference));

  // gmsh writes coordinates with 16 significant digits.
  expect_same_mesh(reference, tet10_v22, 1e-14, "10-node, format 2.2");
  expect_same_mesh(reference, tet4_v22, 1e-14, "4-node, format 2.2");
  expect_same_mesh(reference, tet4_v41, 1e-14, "4-node, format 4.1");
}

TEST(MeshReadGmsh, WrittenQuarterCylinderReadsBackWithCurvedEdgeNodes) {
  ScratchDir dir;
  biphasic::QuarterCylinderSpec spec;
  spec.lc = 3.0;
  spec.write_msh = dir.file("cylinder_v41.msh");
  const Mesh generated = biphasic::generate_quarter_cylinder(spec);
  const Mesh read_v41 = biphasic::read_gmsh(spec.write_msh);

  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(spec.write_msh);
  gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
  gmsh::write(dir.file("cylinder_v22.msh"));
  gmsh::finalize();
  const Mesh read_v22 = biphasic::read_gmsh(dir.file("cylinder_v22.msh"));

  expect_same_mesh(generated, read_v41, 1e-13 * spec.radius, "format 4.1");
  expect_same_mesh(generated, read_v22, 1e-13 * spec.radius, "format 2.2");
  EXPECT_EQ(generated.num_nodes(), read_v41.num_nodes());

  // Edge nodes of the lateral faces stay on the cylinder, away from their chord midpoints.
  const auto* lateral = read_v22.find_boundary("lateral");
  ASSERT_NE(lateral, nullptr);
  double smallest_sag = 1e300;
  for (const auto& face : lateral->faces) {
    for (int e = 0; e < 3; ++e) {
      const Point& p = read_v22.nodes[face[3 + e]];
      EXPECT_NEAR(std::hypot(p[0], p[1]), spec.radius, 1e-9 * spec.radius);
      const Point& a = read_v22.nodes[face[biphasic::kTriEdges[e][0]]];
      const Point& b = read_v22.nodes[face[biphasic::kTriEdges[e][1]]];
      const Point mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
      const double sag = spec.radius - std::hypot(mid[0], mid[1]);
      if (std::abs(a[2] - b[2]) < 1e-9) smallest_sag = std::min(smallest_sag, sag);
    }
  }
  EXPECT_GT(smallest_sag, 0.0);  // horizontal chords cut inside the circle
}

TEST(MeshReadGmsh, PhysicalVolumesBecomeRegions) {
  const Mesh mesh = biphasic::read_gmsh(fixture("two_regions_tet4_v22.msh"));
  ASSERT_EQ(mesh.tets.size(), 2u);
  ASSERT_EQ(mesh.region_names.size(), 2u);
  ASSERT_EQ(mesh.tet_region.size(), 2u);
  // The tet with node tag 1 (the origin) is the first tet of the file: "cartilage".
  for (std::size_t t = 0; t < 2; ++t) {
    bool has_origin = false;
    for (int c = 0; c < 4; ++c) {
      const Point& x = mesh.nodes[static_cast<std::size_t>(mesh.tets[t][c])];
      has_origin = has_origin || (x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0);
    }
    EXPECT_EQ(mesh.region_names[static_cast<std::size_t>(mesh.region_of(static_cast<Index>(t)))],
              has_origin ? "cartilage" : "9");
  }
  EXPECT_GE(mesh.find_region("cartilage"), 0);
  EXPECT_GE(mesh.find_region("9"), 0);
  EXPECT_EQ(mesh.find_region("bone"), -1);
  EXPECT_NE(mesh.find_boundary("base"), nullptr);
}

TEST(MeshReadGmsh, OnePhysicalVolumeIsOneRegion) {
  const Mesh mesh = biphasic::read_gmsh(fixture("inverted_tet4_v22.msh"));
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"solid"});
  EXPECT_EQ(mesh.tet_region, std::vector<int>{0});
}

}  // namespace
