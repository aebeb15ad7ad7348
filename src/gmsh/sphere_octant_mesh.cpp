// Generated sphere octant x, y, z ≥ 0, |x| ≤ R: a verification geometry with a doubly curved
// surface (exact volume πR³/6, curved area πR²/2).
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "gmsh_meshing.hpp"

namespace biphasic {

namespace {

using detail::kOctantFaces;

// Surface tags of the octant, indexed like kOctantFaces. A symmetry face (a quarter disc) has
// its centre of mass in its own plane and 4R/(3π) from the other two; the spherical face has
// all three coordinates R/2. Unlike bounding boxes (padded by OCC's absolute tolerance) this
// works for any radius.
std::vector<int> classify_octant_faces(double radius) {
  return detail::classify_surfaces(kOctantFaces, "sphere-octant", [&](int tag) {
    std::array<double, 3> c{};
    gmsh::model::occ::getCenterOfMass(2, tag, c[0], c[1], c[2]);
    const auto nearest = std::min_element(
        c.begin(), c.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    const auto axis = static_cast<std::size_t>(nearest - c.begin());
    return std::abs(*nearest) < 1e-6 * radius ? 1 + axis : std::size_t{0};
  });
}

}  // namespace

Mesh detail::gmsh_sphere_octant(const SphereOctantSpec& spec) {
  return detail::with_context("generate_sphere_octant", [&] {
    const double quarter_circle = spec.radius * std::numbers::pi / 2;
    const detail::GmshSizing sizing{spec.lc, spec.grading_ratio, spec.grading_distance,
                                    quarter_circle};
    return detail::mesh_with_gmsh(sizing, spec.write_msh, [&] {
      // Polar angle from the equator (z = 0) to the pole, azimuth over a quarter turn.
      const double quarter = std::numbers::pi / 2;
      const int volume =
          gmsh::model::occ::addSphere(0, 0, 0, spec.radius, -1, 0.0, quarter, quarter);
      gmsh::model::occ::synchronize();
      const std::vector<int> faces = classify_octant_faces(spec.radius);
      detail::add_physical_groups(volume, faces, kOctantFaces);
      return std::vector<int>{faces[0]};
    });
  });
}

}  // namespace biphasic
