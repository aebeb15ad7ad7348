// Distinct nodes at the same place: a mesh whose elements do not share the nodes they touch
// (a crack, an unmerged seam between two volumes) is cut there and comes out much softer.
#pragma once

#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// Tolerance for coincidence [mm]: 1e-6 times the shortest tetrahedron edge (corner to corner),
/// far below the distance between any two nodes of a sound mesh.
double coincidence_tolerance(const Mesh& mesh);

/// Pairs (a, b), a < b, of nodes closer than `tolerance` [mm], sorted; found by hashing the
/// nodes into cells of that size (expected linear time).
std::vector<std::pair<Index, Index>> coincident_nodes(const Mesh& mesh, double tolerance);

}  // namespace biphasic
