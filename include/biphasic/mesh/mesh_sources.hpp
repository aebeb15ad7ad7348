// Ways to obtain a Mesh: generated quarter cylinder, or a user's gmsh .msh file.
#pragma once

#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// Quarter cylinder 0 ≤ θ ≤ π/2, 0 ≤ z ≤ height, generated with the gmsh C++ API.
/// Boundaries: "bottom" (z = 0), "top" (z = height), "lateral" (r = radius),
/// "symmetry_x" (plane x = 0), "symmetry_y" (plane y = 0).
struct QuarterCylinderSpec {
  double radius = 18.0;       ///< [mm]
  double height = 8.0;        ///< [mm]
  double lc = 1.3;            ///< uniform characteristic length [mm]
  /// Optional grading: element size grows linearly from lc / grading_ratio on the named
  /// faces to lc at distance grading_distance from them. Empty = uniform.
  std::vector<std::string> grading_faces;
  double grading_ratio = 1.0;     ///< ≥ 1
  double grading_distance = 2.0;  ///< [mm]
  std::string write_msh;          ///< if not empty, write the generated mesh here (.msh 4.1)
};

/// Generates the quarter cylinder with gmsh and returns it as a P2 mesh (edge nodes placed
/// on the curved lateral surface). Throws std::runtime_error on failure.
Mesh generate_quarter_cylinder(const QuarterCylinderSpec& spec);

/// Reads a gmsh .msh file (format 2.2 or 4.1) with 4-node or 10-node tetrahedra. Boundaries
/// are the physical surfaces (triangles) by name; a linear mesh gets straight-edge midpoints.
/// Throws std::runtime_error naming the file on failure (missing file, no tetrahedra,
/// unnamed physical groups, inverted elements).
Mesh read_gmsh(const std::string& path);

/// Builds P2 edge nodes (straight midpoints) for linear tetrahedra and linear boundary
/// triangles given as corner indices into `vertices`. Returns a mesh satisfying the
/// Mesh invariants.
Mesh make_p2_from_linear(std::vector<Point> vertices, const std::vector<std::array<Index, 4>>& tets,
                         const std::vector<std::pair<std::string, std::vector<std::array<Index, 3>>>>&
                             boundaries);

}  // namespace biphasic
