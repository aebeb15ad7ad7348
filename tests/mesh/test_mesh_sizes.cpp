// Slow: the quarter cylinder at the four mesh sizes of the study (R = 18 mm, H = 8 mm).
// Prints node, tet and axis-element counts and the generation time of each.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "p2_geometry.hpp"

namespace {

TEST(MeshQuarterCylinderSizes, StudyMeshesAreValidAndRefine) {
  const double radius = 18.0, height = 8.0;
  biphasic::Index previous_nodes = 0;
  for (const double lc : {1.3, 0.98, 0.73, 0.57}) {
    SCOPED_TRACE("lc = " + std::to_string(lc));
    biphasic::QuarterCylinderSpec spec;
    spec.radius = radius;
    spec.height = height;
    spec.lc = lc;
    const auto start = std::chrono::steady_clock::now();
    const biphasic::Mesh mesh = biphasic::generate_quarter_cylinder(spec);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NO_THROW(biphasic::check_mesh(mesh));

    int axis_vertices = 0;
    for (biphasic::Index v = 0; v < mesh.num_vertices; ++v) {
      if (std::hypot(mesh.nodes[v][0], mesh.nodes[v][1]) <= 1e-9 * radius) ++axis_vertices;
    }
    // The axis is a geometric edge of length H meshed with segments of at most lc.
    EXPECT_EQ(axis_vertices - 1, static_cast<int>(std::ceil(height / lc)));

    // Volume error of the P2 geometry is below (lc/R)⁴/480 (see test_quarter_cylinder.cpp).
    double volume = 0.0;
    for (const auto& tet : mesh.tets) volume += p2test::tet_volume(mesh, tet);
    const double exact = std::numbers::pi * radius * radius * height / 4;
    EXPECT_NEAR(volume, exact, 2.5e-7 * exact);

    EXPECT_GT(mesh.num_nodes(), previous_nodes);
    previous_nodes = mesh.num_nodes();
    std::printf(
        "lc = %.2f mm: %lld P2 nodes (%lld vertices), %zu tets, %d elements on the axis, "
        "%.2f s\n",
        lc, static_cast<long long>(mesh.num_nodes()), static_cast<long long>(mesh.num_vertices),
        mesh.tets.size(), axis_vertices - 1, seconds);
  }
}

}  // namespace
