// Internal plumbing shared by the section-mesh generator and the gmsh module's section reader.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic::detail {

/// A named curve as 2-node segments (corner indices), before the midside nodes exist.
using LinearCurve = std::pair<std::string, std::vector<std::array<Index, 2>>>;

/// P2 section mesh from straight 3-node triangles: `vertices` keep their order (every one must
/// be a triangle corner), one straight-midpoint edge node per vertex pair is added in order of
/// first use by the triangles, then triangles are oriented counter-clockwise and segments with
/// the body on their left. Throws std::runtime_error naming the triangle or the curve segment
/// on an index out of range, a degenerate triangle or a segment that is no triangle edge.
SectionMesh section_p2_from_linear(std::vector<Point2> vertices,
                                   const std::vector<std::array<Index, 3>>& triangles,
                                   const std::vector<LinearCurve>& curves);

}  // namespace biphasic::detail
