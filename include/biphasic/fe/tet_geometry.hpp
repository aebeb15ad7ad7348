// Geometry of a tetrahedron from its four corners [mm].
#pragma once

#include <array>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

using TetCorners = std::array<Vec3, 4>;

/// Signed volume (positive for the local order of mesh.hpp) [mm³].
double tet_volume(const TetCorners& x);
/// Radius of the circumscribed sphere [mm].
double tet_circumradius(const TetCorners& x);
/// Shortest and longest of the six edges [mm].
double tet_shortest_edge(const TetCorners& x);
double tet_longest_edge(const TetCorners& x);
/// Diameter of the sphere of equal volume, (6V/π)^{1/3} [mm].
double tet_volume_diameter(const TetCorners& x);

}  // namespace biphasic
