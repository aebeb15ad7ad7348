// The size guard's estimate against meshes actually generated: exact for the column, within
// 40 % for gmsh's quarter cylinder (uniform, graded, swept) and sphere octant.
#include <gtest/gtest.h>

#include <string>

#include "biphasic/io/config.hpp"
#include "biphasic/io/size_guard.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace {

using biphasic::Config;
using biphasic::MeshSource;

double unknowns(const biphasic::Mesh& mesh) {
  return 3.0 * static_cast<double>(mesh.num_nodes()) + static_cast<double>(mesh.num_vertices);
}

TEST(SizeEstimate, ColumnIsExact) {
  Config c;
  c.mesh.source = MeshSource::Column;
  c.mesh.column.nx = 3;
  c.mesh.column.ny = 4;
  c.mesh.column.nz = 5;
  const biphasic::Mesh mesh = biphasic::generate_column(c.mesh.column);
  const biphasic::SizeEstimate e = biphasic::estimate_size(c);
  EXPECT_EQ(e.tets, static_cast<double>(mesh.tets.size()));
  EXPECT_EQ(e.unknowns, unknowns(mesh));
}

TEST(SizeEstimate, GmshMeshesWithinFortyPercent) {
  const auto expect_close = [](const Config& c, const biphasic::Mesh& mesh, const char* what) {
    const double estimate = biphasic::estimate_size(c).unknowns, actual = unknowns(mesh);
    EXPECT_GT(estimate, 0.6 * actual) << what << ": " << estimate << " vs " << actual;
    EXPECT_LT(estimate, 1.4 * actual) << what << ": " << estimate << " vs " << actual;
  };
  Config c;
  c.mesh.cylinder.lc = 2.0;
  expect_close(c, biphasic::generate_quarter_cylinder(c.mesh.cylinder), "uniform lc = 2");
  c.mesh.cylinder.grading_faces = {"top", "bottom"};
  c.mesh.cylinder.grading_ratio = 3.0;
  expect_close(c, biphasic::generate_quarter_cylinder(c.mesh.cylinder), "graded x3");
  c.mesh.cylinder.grading_faces = {};
  c.mesh.cylinder.grading_ratio = 1.0;
  c.mesh.cylinder.layers = 6;
  expect_close(c, biphasic::generate_quarter_cylinder(c.mesh.cylinder), "6 layers");
  Config s;
  s.mesh.source = MeshSource::SphereOctant;
  s.mesh.sphere_octant.lc = 0.15;
  expect_close(s, biphasic::generate_sphere_octant(s.mesh.sphere_octant), "sphere octant");
}

// A mesh file's estimate counts its tetrahedra alone (not its points, lines and triangles), in
// each of gmsh's formats: equal to the tetrahedra the reader finds.
TEST(SizeEstimate, MeshFilesCountTheirTetrahedraInEveryFormat) {
  for (const char* name : {"full_cylinder_tet4_v22.msh", "full_cylinder_tet4_v22_binary.msh",
                           "full_cylinder_tet10_v41.msh", "full_cylinder_tet10_v41_binary.msh"}) {
    Config c;
    c.mesh.source = MeshSource::File;
    c.mesh.file = std::string(BIPHASIC_SOURCE_DIR) + "/tests/mesh/data/" + name;
    const biphasic::Mesh mesh = biphasic::read_gmsh(c.mesh.file);
    EXPECT_EQ(biphasic::estimate_size(c).tets, static_cast<double>(mesh.tets.size())) << name;
  }
}

TEST(SizeEstimate, MemoryFollowsTheMeasuredRunsOfThePapersMeshes) {
  // Peak memory measured with MUMPS on meshes 1-4 (docs/performance.md) [GB].
  const double measured[4][2] = {{24'910, 0.25}, {54'370, 0.62}, {119'773, 1.69}, {243'403, 4.06}};
  for (const auto& [n, gb] : measured) {
    Config c;
    c.mesh.source = MeshSource::Column;
    // A column of 1 x 1 x nz cells with about n unknowns.
    c.mesh.column.nx = c.mesh.column.ny = 1;
    int nz = 1;
    c.mesh.column.nz = nz;
    while (biphasic::estimate_size(c).unknowns < n && nz < 1'000'000) c.mesh.column.nz = ++nz;
    const double estimate = biphasic::estimate_size(c).bytes / 1e9;
    EXPECT_GT(estimate, 0.8 * gb) << n;
    EXPECT_LT(estimate, 1.25 * gb) << n;
  }
}

}  // namespace

// The guard refuses a quarter cylinder at lc = 1e-4 mm with 1 GB available, and lets it through
// when mesh.ignore_memory_estimate is set (check and run then go on to mesh it, which is why
// this is not an end-to-end test).
TEST(SizeGuard, TheGuardCanBeOverriddenByAKey) {
  Config c;
  c.mesh.cylinder.lc = 1e-4;
  EXPECT_THROW(biphasic::check_size(c, "case.toml", 1e9), std::exception);
  c.mesh.ignore_memory_estimate = true;
  EXPECT_NO_THROW(biphasic::check_size(c, "case.toml", 1e9));
}
