// FieldWriter: HDF5 content read back with the C API, XDMF index consistency, crash safety.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "../common/h5_reader.hpp"
#include "../common/run_binary.hpp"
#include "biphasic/io/field_writer.hpp"
#include "cube_mesh.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;
using e2e::read_text;
using test::H5Reader;

constexpr double kEdge = 2.0;  // cube edge length [mm]

/// A fresh, empty folder for one test (unique per process), removed again at scope exit.
struct TempDir {
  explicit TempDir(const std::string& name)
      : path(fs::path(::testing::TempDir()) /
             ("biphasic_output_" + name + "_" + std::to_string(getpid()))) {
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

/// What an XDMF file says: its time values, and for every DataItem whether the referenced
/// dataset exists in the HDF5 file (resolved relative to the XDMF folder) with the stated shape.
struct XdmfCheck {
  std::vector<double> times;
  int data_items = 0;
  int bad_references = 0;
  int tet10_topologies = 0;
  bool closed = false;
};

XdmfCheck check_xdmf(const fs::path& xdmf) {
  XdmfCheck check;
  const std::string text = read_text(xdmf);
  check.closed = text.find("</Xdmf>") != std::string::npos;

  static const std::regex time_re(R"re(<Time Value="([^"]*)"\s*/>)re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), time_re);
       it != std::sregex_iterator(); ++it) {
    check.times.push_back(std::strtod((*it)[1].str().c_str(), nullptr));
  }
  static const std::regex topo_re(R"re(TopologyType="Tetrahedron_10")re");
  check.tet10_topologies =
      static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), topo_re), {}));

  static const std::regex item_re(
      R"re(<DataItem Dimensions="([^"]*)"[^>]*Format="HDF">([^:<]*):([^<]*)</DataItem>)re");
  std::map<std::string, std::unique_ptr<H5Reader>> files;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), item_re);
       it != std::sregex_iterator(); ++it) {
    ++check.data_items;
    const std::string file = (*it)[2].str();
    const std::string path = (*it)[3].str();
    if (fs::path(file).is_absolute()) {
      ++check.bad_references;
      continue;
    }
    auto& reader = files[file];
    if (!reader) reader = std::make_unique<H5Reader>(xdmf.parent_path() / file);
    if (!reader->exists(path)) {
      ++check.bad_references;
      continue;
    }
    std::ostringstream dims;
    const auto d = reader->dims(path);
    for (std::size_t k = 0; k < d.size(); ++k) dims << (k ? " " : "") << d[k];
    if (dims.str() != (*it)[1].str()) ++check.bad_references;
  }
  return check;
}

/// Node-major displacement with distinct, non-round values [mm].
std::vector<double> make_u(const Mesh& mesh, double scale) {
  std::vector<double> u(3 * mesh.nodes.size());
  for (std::size_t i = 0; i < u.size(); ++i)
    u[i] = scale * (0.1 * static_cast<double>(i) + 1.0 / 3.0);
  return u;
}

/// Vertex pressures that are not linear in the coordinates [MPa].
std::vector<double> make_p(const Mesh& mesh, double scale) {
  std::vector<double> p(static_cast<std::size_t>(mesh.num_vertices));
  for (std::size_t v = 0; v < p.size(); ++v)
    p[v] = scale * (0.7 + 0.3 * static_cast<double>(v * v));
  return p;
}

/// Expected pressure on every node: vertex values, and for an edge node the mean of the two
/// vertices whose midpoint it is (found geometrically, independent of the tetrahedra).
std::vector<double> expected_nodal_pressure(const Mesh& mesh, const std::vector<double>& p) {
  std::vector<double> out(p);
  const auto nv = static_cast<std::size_t>(mesh.num_vertices);
  for (std::size_t n = nv; n < mesh.nodes.size(); ++n) {
    int found = 0;
    for (std::size_t a = 0; a < nv; ++a) {
      for (std::size_t b = a + 1; b < nv; ++b) {
        const auto& xa = mesh.nodes[a];
        const auto& xb = mesh.nodes[b];
        const auto& x = mesh.nodes[n];
        bool mid = true;
        for (int c = 0; c < 3; ++c) mid = mid && 0.5 * (xa[c] + xb[c]) == x[c];
        // Both diagonals of a face share a midpoint; only mesh edges count.
        bool is_edge = false;
        for (const Tet10& tet : mesh.tets) {
          for (const auto& e : kTetEdges) {
            const auto p0 = static_cast<std::size_t>(tet[e[0]]);
            const auto p1 = static_cast<std::size_t>(tet[e[1]]);
            is_edge = is_edge || (p0 == a && p1 == b) || (p0 == b && p1 == a);
          }
        }
        if (mid && is_edge) {
          out.push_back(0.5 * (p[a] + p[b]));
          ++found;
        }
      }
    }
    if (found != 1) throw std::runtime_error("test mesh: edge node without a unique edge");
  }
  return out;
}

TEST(CubeMesh, HasTwentySevenNodesAndPositiveTets) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  EXPECT_EQ(mesh.num_nodes(), 27);
  EXPECT_EQ(mesh.tets.size(), 6u);
  double volume = 0.0;
  for (const Tet10& t : mesh.tets) {
    const auto& x0 = mesh.nodes[static_cast<std::size_t>(t[0])];
    std::array<std::array<double, 3>, 3> d{};
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c)
        d[k][c] = mesh.nodes[static_cast<std::size_t>(t[k + 1])][c] - x0[c];
    }
    const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
                       d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                       d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
    EXPECT_GT(det, 0.0);
    volume += det / 6.0;
  }
  EXPECT_DOUBLE_EQ(volume, kEdge * kEdge * kEdge);
}

TEST(EdgeNodeVertices, MapsEveryEdgeNodeToItsEdge) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const auto edges = edge_node_vertices(mesh);
  ASSERT_EQ(edges.size(), 19u);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto& x = mesh.nodes[8 + k];
    const auto& xa = mesh.nodes[static_cast<std::size_t>(edges[k][0])];
    const auto& xb = mesh.nodes[static_cast<std::size_t>(edges[k][1])];
    EXPECT_LT(edges[k][0], edges[k][1]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(0.5 * (xa[c] + xb[c]), x[c]);
  }
}

TEST(EdgeNodeVertices, RejectsInconsistentMeshes) {
  Mesh shared = test::make_cube_mesh(kEdge);
  std::swap(shared.tets[0][4], shared.tets[0][5]);  // one edge node now on two edges
  EXPECT_THROW(edge_node_vertices(shared), std::runtime_error);

  Mesh orphan = test::make_cube_mesh(kEdge);
  orphan.nodes.push_back({9.0, 9.0, 9.0});  // an edge node no tetrahedron uses
  try {
    edge_node_vertices(orphan);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("edge node 27"), std::string::npos) << e.what();
  }

  Mesh corner = test::make_cube_mesh(kEdge);
  corner.tets[2][1] = 20;  // an edge node in a corner slot
  EXPECT_THROW(edge_node_vertices(corner), std::runtime_error);
}

TEST(FieldWriter, WritesMeshFieldsAndTimesExactly) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("exact");
  const fs::path& dir = dir_tmp.path;
  const std::vector<double> times{0.1, 0.35};
  const std::vector<std::vector<double>> us{make_u(mesh, 1.0), make_u(mesh, -2.5)};
  const std::vector<std::vector<double>> ps{make_p(mesh, 1.0), make_p(mesh, 0.01)};
  {
    FieldWriter writer(dir.string(), "run", mesh);
    EXPECT_TRUE(fs::exists(dir / "run.h5"));
    EXPECT_FALSE(fs::exists(dir / "run.xdmf"));
    for (std::size_t i = 0; i < times.size(); ++i) {
      writer.write(times[i], us[i], ps[i]);
      EXPECT_EQ(writer.num_outputs(), i + 1);

      ASSERT_TRUE(fs::exists(dir / "run.xdmf")) << "after output " << i;
      EXPECT_FALSE(fs::exists(dir / "run.xdmf.tmp"));
      const XdmfCheck check = check_xdmf(dir / "run.xdmf");
      EXPECT_TRUE(check.closed);
      EXPECT_EQ(check.times, std::vector<double>(times.begin(), times.begin() + i + 1));
      EXPECT_EQ(check.tet10_topologies, static_cast<int>(i + 1));
      EXPECT_EQ(check.data_items, 4 * static_cast<int>(i + 1));
      EXPECT_EQ(check.bad_references, 0);
    }
  }

  const H5Reader h5(dir / "run.h5");
  const auto nn = static_cast<hsize_t>(mesh.num_nodes());
  EXPECT_EQ(h5.dims("/mesh/coordinates"), (std::vector<hsize_t>{nn, 3}));
  const auto xyz = h5.read<double>("/mesh/coordinates", H5T_NATIVE_DOUBLE);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(xyz[3 * n + c], mesh.nodes[n][c]);
  }
  EXPECT_EQ(h5.dims("/mesh/topology"), (std::vector<hsize_t>{6, 10}));
  const auto topo = h5.read<std::int64_t>("/mesh/topology", H5T_NATIVE_INT64);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    for (std::size_t k = 0; k < 10; ++k) EXPECT_EQ(topo[10 * e + k], mesh.tets[e][k]);
  }
  EXPECT_EQ(h5.read<std::int64_t>("/mesh/vertex_count", H5T_NATIVE_INT64),
            std::vector<std::int64_t>{8});
  EXPECT_EQ(h5.read<double>("/fields/times", H5T_NATIVE_DOUBLE), times);

  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string step = std::to_string(i);
    EXPECT_EQ(h5.dims("/fields/displacement/" + step), (std::vector<hsize_t>{nn, 3}));
    EXPECT_EQ(h5.read<double>("/fields/displacement/" + step, H5T_NATIVE_DOUBLE), us[i]);
    EXPECT_EQ(h5.read<double>("/fields/pressure_vertices/" + step, H5T_NATIVE_DOUBLE), ps[i]);
    const auto p = h5.read<double>("/fields/pressure/" + step, H5T_NATIVE_DOUBLE);
    EXPECT_EQ(p, expected_nodal_pressure(mesh, ps[i]));
    for (const char* group : {"displacement", "pressure", "pressure_vertices"}) {
      EXPECT_EQ(h5.time_attribute("/fields/" + std::string(group) + "/" + step), times[i]);
    }
  }
}

TEST(FieldWriter, EdgeNodePressureOfLinearFieldIsExact) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("linear");
  const fs::path& dir = dir_tmp.path;
  const auto field = [](const Point& x) { return 0.25 - 0.5 * x[0] + 0.75 * x[1] + 1.5 * x[2]; };
  std::vector<double> p;
  for (Index v = 0; v < mesh.num_vertices; ++v) p.push_back(field(mesh.nodes[v]));
  {
    FieldWriter writer(dir.string(), "lin", mesh);
    writer.write(0.0, std::vector<double>(81, 0.0), p);
  }
  const H5Reader h5(dir / "lin.h5");
  const auto nodal = h5.read<double>("/fields/pressure/0", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(nodal.size(), 27u);
  for (std::size_t n = 0; n < 27; ++n) EXPECT_EQ(nodal[n], field(mesh.nodes[n])) << "node " << n;
}

TEST(FieldWriter, RejectsWrongSizesWithClearMessage) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("sizes");
  const fs::path& dir = dir_tmp.path;
  FieldWriter writer(dir.string(), "bad", mesh);
  try {
    writer.write(0.0, std::vector<double>(27, 0.0), make_p(mesh, 1.0));
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("27 entries"), std::string::npos) << msg;
    EXPECT_NE(msg.find("81"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bad.h5"), std::string::npos) << msg;
  }
  try {
    writer.write(0.0, make_u(mesh, 1.0), std::vector<double>(27, 0.0));
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("27 entries"), std::string::npos) << msg;
    EXPECT_NE(msg.find("expected 8"), std::string::npos) << msg;
  }
  EXPECT_THROW(writer.write(std::nan(""), make_u(mesh, 1.0), make_p(mesh, 1.0)),
               std::runtime_error);
  EXPECT_EQ(writer.num_outputs(), 0u);
  EXPECT_FALSE(fs::exists(dir / "bad.xdmf"));
  // A rejected call leaves the writer usable.
  writer.write(1.0, make_u(mesh, 1.0), make_p(mesh, 1.0));
  EXPECT_EQ(check_xdmf(dir / "bad.xdmf").times, std::vector<double>{1.0});
}

TEST(FieldWriter, ReplacesStaleIndexAndSurvivesMovingTheFolder) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("move");
  const fs::path& dir = dir_tmp.path;
  {
    FieldWriter first(dir.string(), "case", mesh);
    for (double t : {0.0, 1.0, 2.0}) first.write(t, make_u(mesh, t), make_p(mesh, t));
  }
  {
    FieldWriter second(dir.string(), "case", mesh);
    EXPECT_FALSE(fs::exists(dir / "case.xdmf")) << "index of the earlier run must be removed";
    second.write(5.0, make_u(mesh, 1.0), make_p(mesh, 1.0));
  }
  const TempDir moved_tmp("moved");
  const fs::path& moved = moved_tmp.path;
  fs::rename(dir, moved);
  const XdmfCheck check = check_xdmf(moved / "case.xdmf");
  EXPECT_EQ(check.times, std::vector<double>{5.0});
  EXPECT_EQ(check.data_items, 4);
  EXPECT_EQ(check.bad_references, 0);
  const H5Reader h5(moved / "case.h5");
  EXPECT_FALSE(h5.exists("/fields/displacement/1"));
}

TEST(FieldWriter, KilledRunLeavesReadableFiles) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("killed");
  const fs::path& dir = dir_tmp.path;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // No destructors run: the process dies with the HDF5 file still open.
    try {
      auto* writer = new FieldWriter(dir.string(), "crash", mesh);
      writer->write(0.5, make_u(mesh, 1.0), make_p(mesh, 1.0));
      writer->write(1.5, make_u(mesh, 2.0), make_p(mesh, 2.0));
    } catch (...) {
      _exit(3);
    }
    raise(SIGKILL);
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGKILL);

  const XdmfCheck check = check_xdmf(dir / "crash.xdmf");
  EXPECT_EQ(check.times, (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(check.bad_references, 0);
  EXPECT_EQ(check.data_items, 8);
  const H5Reader h5(dir / "crash.h5");
  EXPECT_EQ(h5.read<double>("/fields/times", H5T_NATIVE_DOUBLE), (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(h5.read<double>("/fields/displacement/1", H5T_NATIVE_DOUBLE), make_u(mesh, 2.0));
}

TEST(FieldWriter, FailsWithPathWhenFolderCannotBeCreated) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("blocked");
  const fs::path& dir = dir_tmp.path;
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  try {
    FieldWriter writer((dir / "file" / "sub").string(), "x", mesh);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("file/sub"), std::string::npos) << e.what();
  }
}

/// Cell values with distinct, non-round entries: `components` per cell of `mesh`.
std::vector<double> make_cells(const Mesh& mesh, int components, double scale) {
  std::vector<double> v(static_cast<std::size_t>(components) * mesh.tets.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = scale * (1.0 / 7.0 + static_cast<double>(i));
  return v;
}

/// A layout of cell fields only: a tensor, a scalar and a vector.
FieldLayout cell_layout() {
  FieldLayout layout;
  layout.displacement = false;
  layout.pressure = false;
  layout.cells = {{"stress", 9, "MPa"}, {"J", 1, "-"}, {"flux", 3, "mm/s"}};
  return layout;
}

TEST(FieldWriter, WritesCellFieldsAsCellAttributes) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("cells");
  const fs::path& dir = dir_tmp.path;
  const std::vector<double> times{0.0, 2.0};
  std::vector<std::vector<std::vector<double>>> values;
  {
    FieldWriter writer(dir.string(), "run", mesh, cell_layout());
    for (std::size_t i = 0; i < times.size(); ++i) {
      const double scale = 1.0 + static_cast<double>(i);
      values.push_back({make_cells(mesh, 9, scale), make_cells(mesh, 1, -scale),
                        make_cells(mesh, 3, 0.5 * scale)});
      // Displacement and pressure are not in the layout: their arguments are not read.
      writer.write(times[i], {}, {}, values.back());
    }
  }
  const XdmfCheck check = check_xdmf(dir / "run.xdmf");
  EXPECT_EQ(check.times, times);
  EXPECT_EQ(check.data_items, 2 * (2 + 3));  // topology, geometry, three cell fields
  EXPECT_EQ(check.bad_references, 0);
  const std::string xdmf = read_text(dir / "run.xdmf");
  for (
      const char* attribute :
      {R"(<Attribute Name="stress" AttributeType="Tensor" Center="Cell">)",
       R"(<Attribute Name="J" AttributeType="Scalar" Center="Cell">)",
       R"(<Attribute Name="flux" AttributeType="Vector" Center="Cell">)",
       R"(<DataItem Dimensions="6 9" NumberType="Float" Precision="8" Format="HDF">run.h5:/fields/stress/1</DataItem>)",
       R"(<DataItem Dimensions="6" NumberType="Float" Precision="8" Format="HDF">run.h5:/fields/J/1</DataItem>)",
       R"(<DataItem Dimensions="6 3" NumberType="Float" Precision="8" Format="HDF">run.h5:/fields/flux/0</DataItem>)"}) {
    EXPECT_NE(xdmf.find(attribute), std::string::npos) << attribute << " missing in\n" << xdmf;
  }
  EXPECT_EQ(xdmf.find("displacement"), std::string::npos);
  EXPECT_EQ(xdmf.find("pressure"), std::string::npos);

  const H5Reader h5(dir / "run.h5");
  EXPECT_FALSE(h5.exists("/fields/displacement"));
  EXPECT_FALSE(h5.exists("/fields/pressure"));
  EXPECT_FALSE(h5.exists("/fields/pressure_vertices"));
  const std::vector<std::pair<std::string, std::vector<hsize_t>>> shapes{
      {"stress", {6, 9}}, {"J", {6}}, {"flux", {6, 3}}};
  const std::vector<std::string> units{"MPa", "-", "mm/s"};
  for (std::size_t i = 0; i < times.size(); ++i) {
    for (std::size_t f = 0; f < shapes.size(); ++f) {
      const std::string path = "/fields/" + shapes[f].first + "/" + std::to_string(i);
      EXPECT_EQ(h5.dims(path), shapes[f].second) << path;
      EXPECT_EQ(h5.read<double>(path, H5T_NATIVE_DOUBLE), values[i][f]) << path;
      EXPECT_EQ(h5.time_attribute(path), times[i]) << path;
      EXPECT_EQ(h5.string_attribute(path, "units"), units[f]) << path;
    }
  }
}

TEST(FieldWriter, RefusesBadCellFields) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("bad_cells");
  const std::string dir = dir_tmp.path.string();
  const auto refused = [&](std::vector<CellFieldSpec> cells, const std::string& expected) {
    FieldLayout layout;
    layout.cells = std::move(cells);
    try {
      FieldWriter writer(dir, "x", mesh, layout);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find(expected) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused({{"pressure", 1, "MPa"}}, "'pressure' clashes"));
  EXPECT_TRUE(refused({{"J", 1, "-"}, {"J", 1, "-"}}, "'J' clashes"));
  EXPECT_TRUE(refused({{"times", 1, "s"}}, "'times' clashes"));
  EXPECT_TRUE(refused({{"a/b", 1, "-"}}, "invalid cell field name 'a/b'"));
  EXPECT_TRUE(refused({{"", 1, "-"}}, "invalid cell field name"));
  EXPECT_TRUE(refused({{"c", 2, "-"}}, "'c' has 2 components"));
  FieldWriter symmetric(dir, "t6", mesh, {false, false, {{"s", 6, "MPa"}}});
  symmetric.write(0.0, {}, {}, {make_cells(mesh, 6, 1.0)});
  EXPECT_NE(read_text(dir_tmp.path / "t6.xdmf").find(R"(Name="s" AttributeType="Tensor6")"),
            std::string::npos);

  FieldWriter writer(dir, "sizes", mesh, cell_layout());
  try {
    writer.write(0.0, {}, {},
                 {make_cells(mesh, 9, 1.0), make_cells(mesh, 3, 1.0), make_cells(mesh, 3, 1.0)});
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("J has 18 entries, expected 1 x 6 cells = 6"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(writer.write(0.0, {}, {}, {make_cells(mesh, 9, 1.0)}), std::runtime_error);
  EXPECT_EQ(writer.num_outputs(), 0u);
}

TEST(FieldWriter, RestartDropsLaterCellFieldsAndAppends) {
  const Mesh mesh = test::make_cube_mesh(kEdge);
  const TempDir dir_tmp("cells_restart");
  const std::string dir = dir_tmp.path.string();
  FieldLayout layout = cell_layout();
  layout.pressure = true;
  const auto cells = [&](double s) {
    return std::vector<std::vector<double>>{make_cells(mesh, 9, s), make_cells(mesh, 1, s),
                                            make_cells(mesh, 3, s)};
  };
  {
    FieldWriter first(dir, "f", mesh, layout);
    for (double t : {0.0, 1.0, 2.0}) first.write(t, {}, make_p(mesh, t), cells(t));
  }
  {
    FieldWriter again(dir, "f", mesh, 1.0, layout);
    EXPECT_EQ(again.times(), (std::vector<double>{0.0, 1.0}));
    const H5Reader h5(dir_tmp.path / "f.h5");
    for (const char* group : {"stress", "J", "flux", "pressure", "pressure_vertices"}) {
      EXPECT_TRUE(h5.exists("/fields/" + std::string(group) + "/1")) << group;
      EXPECT_FALSE(h5.exists("/fields/" + std::string(group) + "/2")) << group;
    }
  }
  {
    FieldWriter again(dir, "f", mesh, 1.0, layout);
    again.write(1.5, {}, make_p(mesh, 1.5), cells(1.5));
  }
  const XdmfCheck check = check_xdmf(dir_tmp.path / "f.xdmf");
  EXPECT_EQ(check.times, (std::vector<double>{0.0, 1.0, 1.5}));
  EXPECT_EQ(check.data_items, 3 * (2 + 4));
  EXPECT_EQ(check.bad_references, 0);
  const H5Reader h5(dir_tmp.path / "f.h5");
  EXPECT_EQ(h5.read<double>("/fields/flux/2", H5T_NATIVE_DOUBLE), make_cells(mesh, 3, 1.5));
}

}  // namespace
}  // namespace biphasic
