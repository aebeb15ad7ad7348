// Verification-benchmark meshes: the structured column (counts, exact volume and areas, layer
// grading, planar boundaries) and the gmsh sphere octant (volume and area converging as lc⁴,
// nodes on the sphere, outward normals, determinism).
#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
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
using std::numbers::pi;

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Point& p) { return std::sqrt(dot(p, p)); }

double volume_of(const Mesh& mesh) {
  double volume = 0.0;
  for (const auto& tet : mesh.tets) {
    const double v = p2test::tet_volume(mesh, tet);
    EXPECT_GT(v, 0.0);
    volume += v;
  }
  return volume;
}

double area_of(const Mesh& mesh, const std::string& name) {
  const auto* boundary = mesh.find_boundary(name);
  if (boundary == nullptr) {
    ADD_FAILURE() << "no boundary '" << name << "'";
    return 0.0;
  }
  double area = 0.0;
  for (const auto& face : boundary->faces) area += p2test::tri_area(mesh, face);
  return area;
}

// Largest |x_axis − value| over all nodes (corners and edge nodes) of the boundary's faces.
double plane_error(const Mesh& mesh, const std::string& name, int axis, double value) {
  double worst = 0.0;
  for (const auto& face : mesh.find_boundary(name)->faces) {
    for (const Index n : face) worst = std::max(worst, std::abs(mesh.nodes[n][axis] - value));
  }
  return worst;
}

// Smallest cosine between a face's corner normal and the outward normal `out(face)`.
template <class Outward>
double worst_alignment(const Mesh& mesh, const std::string& name, Outward out) {
  double worst = 1.0;
  for (const auto& face : mesh.find_boundary(name)->faces) {
    const Point o = out(face);
    worst = std::min(worst, dot(p2test::corner_normal(mesh, face), o) / norm(o));
  }
  return worst;
}

// Each named plane boundary: name, axis, coordinate value, outward direction (±1 along axis).
struct Plane {
  std::string name;
  int axis;
  double value;
  double outward;
};

// Expects `call` to throw a std::runtime_error whose message contains each of `parts`.
void expect_error(const std::function<void()>& call, const std::vector<std::string>& parts) {
  std::string message;
  EXPECT_THROW(
      {
        try {
          call();
        } catch (const std::runtime_error& e) {
          message = e.what();
          throw;
        }
      },
      std::runtime_error);
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << message << "' lacks " << part;
  }
}

// ---- column ------------------------------------------------------------------------------

biphasic::ColumnSpec box_spec() {
  biphasic::ColumnSpec spec;
  spec.width = 2.0;
  spec.depth = 0.5;
  spec.height = 3.0;
  spec.nx = 2;
  spec.ny = 3;
  spec.nz = 4;
  return spec;
}

std::vector<Plane> column_planes(const biphasic::ColumnSpec& s) {
  return {{"bottom", 2, 0.0, -1}, {"top", 2, s.height, 1}, {"x0", 0, 0.0, -1},
          {"x1", 0, s.width, 1},  {"y0", 1, 0.0, -1},      {"y1", 1, s.depth, 1}};
}

TEST(MeshColumn, DefaultsAreAUnitColumnOfTenLayers) {
  const Mesh mesh = biphasic::generate_column({});
  EXPECT_EQ(mesh.tets.size(), 60u);
  EXPECT_EQ(mesh.num_vertices, 2 * 2 * 11);
  EXPECT_NEAR(volume_of(mesh), 1.0, 1e-13);
  const std::vector<double> z = biphasic::column_layer_z({});
  ASSERT_EQ(z.size(), 11u);
  for (int k = 0; k <= 10; ++k) EXPECT_DOUBLE_EQ(z[static_cast<std::size_t>(k)], k / 10.0);
}

// nx = 2^31 − 1 overflowed int arithmetic (undefined behaviour) before allocating; counts are
// now 64-bit and a column beyond 10^8 cells is refused with a message before any allocation.
TEST(MeshColumn, CellCountsBeyondTheLimitAreRefusedWithoutOverflow) {
  const auto message_for = [](int nx, int ny, int nz) -> std::string {
    biphasic::ColumnSpec spec;
    spec.nx = nx;
    spec.ny = ny;
    spec.nz = nz;
    try {
      biphasic::generate_column(spec);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string huge = message_for(std::numeric_limits<int>::max(), 1, 1);
  EXPECT_NE(huge.find("nx * ny * nz = 2147483647 * 1 * 1 cells"), std::string::npos) << huge;
  EXPECT_NE(huge.find("limit of 100000000"), std::string::npos) << huge;
  const std::string cube = message_for(2000, 2000, 2000);  // 8e9 cells: overflows 32 bits
  EXPECT_NE(cube.find("limit of 100000000"), std::string::npos) << cube;
}

TEST(MeshColumn, CountsVolumeAndInvariants) {
  const auto spec = box_spec();
  const Mesh mesh = biphasic::generate_column(spec);
  EXPECT_EQ(mesh.tets.size(), static_cast<std::size_t>(6 * spec.nx * spec.ny * spec.nz));
  EXPECT_EQ(mesh.num_vertices, (spec.nx + 1) * (spec.ny + 1) * (spec.nz + 1));
  // Edges of the Kuhn lattice: 3 axis directions, 3 face diagonals, 1 body diagonal.
  const Index nx = spec.nx, ny = spec.ny, nz = spec.nz;
  const Index edges = nx * (ny + 1) * (nz + 1) + (nx + 1) * ny * (nz + 1) +
                      (nx + 1) * (ny + 1) * nz + nx * ny * (nz + 1) + nx * (ny + 1) * nz +
                      (nx + 1) * ny * nz + nx * ny * nz;
  EXPECT_EQ(mesh.num_nodes(), mesh.num_vertices + edges);
  const double exact = spec.width * spec.depth * spec.height;
  EXPECT_NEAR(volume_of(mesh), exact, 1e-13 * exact);
  EXPECT_NO_THROW(biphasic::check_mesh(mesh));
}

TEST(MeshColumn, BoundariesAreTheSixFacesWithExactAreas) {
  const auto s = box_spec();
  const Mesh mesh = biphasic::generate_column(s);
  EXPECT_EQ(mesh.boundary_names(),
            (std::vector<std::string>{"bottom", "top", "x0", "x1", "y0", "y1"}));
  const std::vector<std::pair<std::string, double>> areas{
      {"bottom", s.width * s.depth}, {"top", s.width * s.depth}, {"x0", s.depth * s.height},
      {"x1", s.depth * s.height},    {"y0", s.width * s.height}, {"y1", s.width * s.height}};
  for (const auto& [name, exact] : areas) {
    EXPECT_NEAR(area_of(mesh, name), exact, 1e-13 * exact) << name;
  }
  EXPECT_EQ(mesh.find_boundary("top")->faces.size(), static_cast<std::size_t>(2 * s.nx * s.ny));
  EXPECT_EQ(mesh.find_boundary("x1")->faces.size(), static_cast<std::size_t>(2 * s.ny * s.nz));
  EXPECT_EQ(mesh.find_boundary("y0")->faces.size(), static_cast<std::size_t>(2 * s.nx * s.nz));
}

TEST(MeshColumn, BoundaryNodesLieExactlyOnTheirPlanesAndFacesPointOutward) {
  auto spec = box_spec();
  spec.grading_faces = {"top"};
  spec.grading_ratio = 5.0;
  const Mesh mesh = biphasic::generate_column(spec);
  for (const Plane& p : column_planes(spec)) {
    EXPECT_EQ(plane_error(mesh, p.name, p.axis, p.value), 0.0) << p.name;
    const double cosine = worst_alignment(mesh, p.name, [&](const biphasic::Tri6&) {
      Point out{0, 0, 0};
      out[static_cast<std::size_t>(p.axis)] = p.outward;
      return out;
    });
    EXPECT_GT(cosine, 1.0 - 1e-12) << p.name;
  }
  for (const auto& face : mesh.find_boundary("top")->faces) {
    for (const Index n : face) ASSERT_EQ(mesh.nodes[n][2], spec.height);
  }
}

TEST(MeshColumn, UniformLayersAreEqual) {
  auto spec = box_spec();
  spec.nz = 7;
  const std::vector<double> z = biphasic::column_layer_z(spec);
  ASSERT_EQ(z.size(), 8u);
  for (std::size_t k = 0; k < z.size(); ++k) {
    EXPECT_NEAR(z[k], spec.height * static_cast<double>(k) / 7.0, 1e-15 * spec.height);
  }
  EXPECT_EQ(z.front(), 0.0);
  EXPECT_EQ(z.back(), spec.height);
}

// Layer thicknesses of column_layer_z.
std::vector<double> thicknesses(const std::vector<double>& z) {
  std::vector<double> h;
  for (std::size_t k = 1; k < z.size(); ++k) h.push_back(z[k] - z[k - 1]);
  return h;
}

TEST(MeshColumn, GradedLayersFormAGeometricProgressionReachingTheRatio) {
  struct Case {
    std::vector<std::string> faces;
    int nz;
    double ratio;
  };
  for (const Case& c : {Case{{"top"}, 10, 8.0}, Case{{"bottom"}, 6, 3.0},
                        Case{{"bottom", "top"}, 9, 4.0}, Case{{"top", "bottom"}, 8, 2.5}}) {
    SCOPED_TRACE(c.faces.size() == 2 ? "both" : c.faces[0]);
    SCOPED_TRACE("nz = " + std::to_string(c.nz));
    auto spec = box_spec();
    spec.nz = c.nz;
    spec.grading_faces = c.faces;
    spec.grading_ratio = c.ratio;
    const std::vector<double> z = biphasic::column_layer_z(spec);
    ASSERT_EQ(z.size(), static_cast<std::size_t>(c.nz + 1));
    EXPECT_EQ(z.front(), 0.0);
    EXPECT_EQ(z.back(), spec.height);
    const std::vector<double> h = thicknesses(z);
    for (const double t : h) ASSERT_GT(t, 0.0);
    const auto [thin, thick] = std::minmax_element(h.begin(), h.end());
    EXPECT_NEAR(*thick / *thin, c.ratio, 1e-12 * c.ratio);

    const bool bottom = std::count(c.faces.begin(), c.faces.end(), "bottom") > 0;
    const bool top = std::count(c.faces.begin(), c.faces.end(), "top") > 0;
    const int n = c.nz;
    const int m = bottom && top ? (n - 1) / 2 : n - 1;
    const double q = std::pow(c.ratio, 1.0 / m);
    for (int k = 0; k < n; ++k) {
      // Thickness grows by q per layer away from the (nearest) graded face.
      const int e = bottom && top ? std::min(k, n - 1 - k) : (bottom ? k : n - 1 - k);
      EXPECT_NEAR(h[static_cast<std::size_t>(k)] / *thin, std::pow(q, e), 1e-12 * c.ratio)
          << "layer " << k;
    }
    if (bottom && !top) {
      EXPECT_EQ(thin - h.begin(), 0);
    }
    if (top && !bottom) {
      EXPECT_EQ(thin - h.begin(), n - 1);
    }
    if (top && bottom) {
      EXPECT_NEAR(h.front(), h.back(), 1e-14 * spec.height);
      EXPECT_NEAR(h.front(), *thin, 1e-14 * spec.height);
    }

    // The mesh vertices sit exactly on these layers.
    const Mesh mesh = biphasic::generate_column(spec);
    std::vector<double> vertex_z;
    for (Index v = 0; v < mesh.num_vertices; ++v) vertex_z.push_back(mesh.nodes[v][2]);
    std::sort(vertex_z.begin(), vertex_z.end());
    vertex_z.erase(std::unique(vertex_z.begin(), vertex_z.end()), vertex_z.end());
    EXPECT_EQ(vertex_z, z);
    const double exact = spec.width * spec.depth * spec.height;
    EXPECT_NEAR(volume_of(mesh), exact, 1e-13 * exact);
  }
}

TEST(MeshColumn, InvalidSpecsNameTheFieldAndValue) {
  const auto expect_message = [](const biphasic::ColumnSpec& spec,
                                 const std::vector<std::string>& parts) {
    expect_error([&] { biphasic::generate_column(spec); }, parts);
    expect_error([&] { biphasic::column_layer_z(spec); }, parts);
  };
  auto s = box_spec();
  s.width = -1.0;
  expect_message(s, {"width", "-1"});
  expect_error([&] { biphasic::generate_column(s); }, {"generate_column"});
  s = box_spec();
  s.height = 0.0;
  expect_message(s, {"height", "0"});
  s = box_spec();
  s.depth = std::numeric_limits<double>::infinity();
  expect_message(s, {"depth", "inf"});
  s = box_spec();
  s.ny = 0;
  expect_message(s, {"ny", "0"});
  s = box_spec();
  s.nz = -3;
  expect_message(s, {"nz", "-3"});
  s = box_spec();
  s.grading_ratio = 0.5;
  expect_message(s, {"grading_ratio", "0.5"});
  s = box_spec();
  s.grading_faces = {"top", "side"};
  s.grading_ratio = 2.0;
  expect_message(s, {"'side'", "bottom", "top"});
  s = box_spec();
  s.grading_faces = {"bottom", "top"};
  s.grading_ratio = 2.0;
  s.nz = 2;
  expect_message(s, {"nz", "3", "2"});
  s.grading_faces = {"top"};
  s.nz = 1;
  expect_message(s, {"nz", "1"});
}

// ---- sphere octant -------------------------------------------------------------------------

constexpr double kR = 1.0;

biphasic::SphereOctantSpec octant_spec(double lc) {
  biphasic::SphereOctantSpec spec;
  spec.radius = kR;
  spec.lc = lc;
  return spec;
}

// The lc = 0.2 and 0.1 meshes, generated once per process on first use.
class MeshSphereOctant : public ::testing::Test {
 protected:
  static const Mesh& coarse() {
    static const Mesh mesh = biphasic::generate_sphere_octant(octant_spec(0.2));
    return mesh;
  }
  static const Mesh& fine() {
    static const Mesh mesh = biphasic::generate_sphere_octant(octant_spec(0.1));
    return mesh;
  }
};

const std::vector<Plane>& octant_planes() {
  static const std::vector<Plane> planes{
      {"symmetry_x", 0, 0.0, -1}, {"symmetry_y", 1, 0.0, -1}, {"symmetry_z", 2, 0.0, -1}};
  return planes;
}

TEST_F(MeshSphereOctant, HasTheFourNamedBoundariesAndIsValid) {
  for (const Mesh* mesh : {&coarse(), &fine()}) {
    EXPECT_EQ(mesh->boundary_names(),
              (std::vector<std::string>{"surface", "symmetry_x", "symmetry_y", "symmetry_z"}));
    for (const auto& b : mesh->boundaries) EXPECT_FALSE(b.faces.empty()) << b.name;
    EXPECT_NO_THROW(biphasic::check_mesh(*mesh));
  }
  EXPECT_GT(fine().tets.size(), 4 * coarse().tets.size());
}

// The P2 chords of the sphere lie inside it, so volume and area are low, by O(lc⁴): measured
// relative errors ≈ 0.013·(lc/R)⁴ for the volume and ≈ 0.009·(lc/R)⁴ for the curved area at
// lc = 0.4 … 0.05 (2.1e-5 and 1.4e-5 at lc = 0.2). Tolerance 0.02·(lc/R)⁴; halving lc must cut
// the error by more than 8 (measured ≈ 15). Straight edge nodes would give O(lc²) errors.
TEST_F(MeshSphereOctant, VolumeAndSurfaceAreaConvergeAsLcToTheFourth) {
  const double exact_volume = pi * kR * kR * kR / 6;
  const double exact_area = pi * kR * kR / 2;
  std::vector<double> volume_errors, area_errors;
  for (const auto& [mesh, lc] : {std::pair{&coarse(), 0.2}, std::pair{&fine(), 0.1}}) {
    SCOPED_TRACE("lc = " + std::to_string(lc));
    const double tol = 0.02 * std::pow(lc / kR, 4);
    const double volume = volume_of(*mesh);
    const double area = area_of(*mesh, "surface");
    volume_errors.push_back((exact_volume - volume) / exact_volume);
    area_errors.push_back((exact_area - area) / exact_area);
    EXPECT_GE(volume_errors.back(), 0.0);
    EXPECT_LE(volume_errors.back(), tol);
    EXPECT_GE(area_errors.back(), 0.0);
    EXPECT_LE(area_errors.back(), tol);
    // The quarter discs have one curved side: their area error is smaller still.
    for (const Plane& p : octant_planes()) {
      const double disc = pi * kR * kR / 4;
      EXPECT_NEAR(area_of(*mesh, p.name), disc, tol * disc) << p.name;
    }
  }
  EXPECT_GT(volume_errors[0], 8.0 * volume_errors[1]);
  EXPECT_GT(area_errors[0], 8.0 * area_errors[1]);
}

TEST_F(MeshSphereOctant, SurfaceNodesIncludingEdgeNodesLieOnTheSphere) {
  for (const Mesh* mesh : {&coarse(), &fine()}) {
    double worst = 0.0;
    std::size_t edge_nodes = 0;
    for (const auto& face : mesh->find_boundary("surface")->faces) {
      for (const Index n : face) {
        worst = std::max(worst, std::abs(norm(mesh->nodes[n]) - kR));
        if (n >= mesh->num_vertices) ++edge_nodes;
      }
    }
    EXPECT_GT(edge_nodes, 0u);
    EXPECT_LE(worst, 1e-12 * kR);
  }
}

TEST_F(MeshSphereOctant, SymmetryFacesArePlanarAndAllFacesPointOutward) {
  for (const Mesh* mesh : {&coarse(), &fine()}) {
    for (const Plane& p : octant_planes()) {
      EXPECT_LE(plane_error(*mesh, p.name, p.axis, p.value), 1e-12 * kR) << p.name;
      const double cosine = worst_alignment(*mesh, p.name, [&](const biphasic::Tri6&) {
        Point out{0, 0, 0};
        out[static_cast<std::size_t>(p.axis)] = p.outward;
        return out;
      });
      EXPECT_GT(cosine, 1.0 - 1e-9) << p.name;
    }
    // Radial direction at the face's corner centroid.
    const double cosine = worst_alignment(*mesh, "surface", [&](const biphasic::Tri6& face) {
      Point c{0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        for (int d = 0; d < 3; ++d) c[d] += mesh->nodes[face[k]][d] / 3;
      }
      return c;
    });
    EXPECT_GT(cosine, 0.9);
  }
}

TEST(MeshSphereOctantGrading, RefinesTowardTheSurface) {
  const Mesh uniform = biphasic::generate_sphere_octant(octant_spec(0.2));
  auto spec = octant_spec(0.2);
  spec.grading_ratio = 3.0;
  spec.grading_distance = 0.3;
  const Mesh graded = biphasic::generate_sphere_octant(spec);
  EXPECT_GT(graded.tets.size(), 2 * uniform.tets.size());
  // Mean edge length on the surface ≈ lc / ratio, deep inside (r < R/2) ≈ lc.
  const auto mean_edge = [&](auto&& keep) {
    double sum = 0.0;
    int count = 0;
    for (const auto& tet : graded.tets) {
      for (const auto& [a, b] : biphasic::kTetEdges) {
        const Point& p = graded.nodes[tet[a]];
        const Point& q = graded.nodes[tet[b]];
        if (!keep(p) || !keep(q)) continue;
        sum += norm({p[0] - q[0], p[1] - q[1], p[2] - q[2]});
        ++count;
      }
    }
    return sum / count;
  };
  const double surface = mean_edge([](const Point& p) { return norm(p) > kR * (1 - 1e-9); });
  const double inner = mean_edge([](const Point& p) { return norm(p) < 0.5 * kR; });
  EXPECT_LT(surface, 0.5 * spec.lc);
  EXPECT_GT(inner, 0.7 * spec.lc);
  const double exact = pi * kR * kR * kR / 6;
  EXPECT_NEAR(volume_of(graded), exact, 0.02 * std::pow(0.2, 4) * exact);
  EXPECT_NO_THROW(biphasic::check_mesh(graded));
}

TEST(MeshSphereOctantScaling, OtherRadiusScalesTheGeometry) {
  biphasic::SphereOctantSpec spec;
  spec.radius = 5.0;
  spec.lc = 1.0;
  const Mesh mesh = biphasic::generate_sphere_octant(spec);
  double worst = 0.0;
  for (const auto& face : mesh.find_boundary("surface")->faces) {
    for (const Index n : face) worst = std::max(worst, std::abs(norm(mesh.nodes[n]) - 5.0));
  }
  EXPECT_LE(worst, 1e-12 * 5.0);
  const double exact = pi * 125.0 / 6;
  EXPECT_NEAR(volume_of(mesh), exact, 0.02 * std::pow(0.2, 4) * exact);
}

TEST(MeshSphereOctantSpec, InvalidSpecsNameTheFieldAndValue) {
  const auto expect_message = [](const biphasic::SphereOctantSpec& spec,
                                 const std::vector<std::string>& parts) {
    expect_error([&] { biphasic::generate_sphere_octant(spec); }, parts);
  };
  auto s = octant_spec(0.5);
  s.radius = -2.0;
  expect_message(s, {"generate_sphere_octant", "radius", "-2"});
  s = octant_spec(0.0);
  expect_message(s, {"lc", "0"});
  s = octant_spec(0.5);
  s.grading_ratio = 0.25;
  expect_message(s, {"grading_ratio", "0.25"});
  s = octant_spec(0.5);
  s.grading_distance = -1.0;
  expect_message(s, {"grading_distance", "-1"});
}

// The session handling itself (gmsh finalized again, or an outer session's models and options
// restored) is shared with the quarter cylinder and tested in test_quarter_cylinder.cpp.
TEST(MeshSphereOctantSession, DeterministicInsideAndOutsideAGmshSessionAndWritesTheMesh) {
  const Mesh first = biphasic::generate_sphere_octant(octant_spec(0.3));
  const Mesh again = biphasic::generate_sphere_octant(octant_spec(0.3));

  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("outer");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 42.0);
  const Mesh inside = biphasic::generate_sphere_octant(octant_spec(0.3));
  std::string current;
  gmsh::model::getCurrent(current);
  EXPECT_EQ(current, "outer");
  double size_max = 0.0;
  gmsh::option::getNumber("Mesh.MeshSizeMax", size_max);
  EXPECT_EQ(size_max, 42.0);
  gmsh::finalize();

  for (const Mesh* other : {&again, &inside}) {
    EXPECT_TRUE(other->nodes == first.nodes);
    EXPECT_EQ(other->num_vertices, first.num_vertices);
    EXPECT_TRUE(other->tets == first.tets);
    ASSERT_EQ(other->boundary_names(), first.boundary_names());
    for (std::size_t b = 0; b < first.boundaries.size(); ++b) {
      EXPECT_TRUE(other->boundaries[b].faces == first.boundaries[b].faces) << b;
    }
  }

  const auto path = std::filesystem::temp_directory_path() /
                    ("biphasic_sphere_octant_" + std::to_string(::getpid()) + ".msh");
  auto spec = octant_spec(0.3);
  spec.write_msh = path.string();
  const Mesh written = biphasic::generate_sphere_octant(spec);
  const Mesh read = biphasic::read_gmsh(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(read.tets.size(), written.tets.size());
  EXPECT_EQ(read.num_nodes(), written.num_nodes());
  EXPECT_EQ(read.boundary_names(), written.boundary_names());
}

}  // namespace
