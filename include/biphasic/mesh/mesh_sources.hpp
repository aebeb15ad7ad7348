// Ways to obtain a Mesh: generated quarter cylinder, or a user's gmsh .msh file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// Quarter cylinder 0 ≤ θ ≤ π/2, 0 ≤ z ≤ height, generated with the gmsh C++ API.
/// Boundaries: "bottom" (z = 0), "top" (z = height), "lateral" (r = radius),
/// "symmetry_x" (plane x = 0), "symmetry_y" (plane y = 0).
struct QuarterCylinderSpec {
  double radius = 18.0;  ///< [mm]
  double height = 8.0;   ///< [mm]
  double lc = 1.3;       ///< uniform characteristic length [mm]
  /// Optional grading: element size grows linearly from lc / grading_ratio on the named
  /// faces to lc at distance grading_distance from them. Empty = uniform.
  std::vector<std::string> grading_faces;
  double grading_ratio = 1.0;     ///< ≥ 1
  double grading_distance = 2.0;  ///< [mm]
  std::string write_msh;          ///< if not empty, write the generated mesh here (.msh 4.1)
};

/// Generates the quarter cylinder with gmsh and returns it as a P2 mesh (edge nodes placed
/// on the curved lateral surface, boundary faces pointing outward). Deterministic for a given
/// spec; leaves gmsh initialized or not, with its current model and options, as it found it.
/// Throws std::runtime_error on failure or on an invalid spec (non-positive sizes, unknown
/// grading face, grading_ratio < 1).
Mesh generate_quarter_cylinder(const QuarterCylinderSpec& spec);

/// Reads a gmsh .msh file (format 2.2 or 4.1) with 4-node or 10-node tetrahedra. Boundaries
/// are the physical surfaces (triangles) by name; a physical surface without a name is named
/// by its tag in decimal ("3"). A linear mesh gets straight-edge midpoints, a 10-node mesh
/// keeps its edge nodes. Inverted tets are re-oriented (see orient_tets), boundary faces point
/// outward (see orient_boundary_faces), nodes used by no tet are dropped.
/// Throws std::runtime_error naming the file on failure (missing or unreadable file, no
/// tetrahedra, mixed element orders, boundary nodes that are not tet nodes, degenerate tets).
Mesh read_gmsh(const std::string& path);

/// Builds P2 edge nodes (straight midpoints) for linear tetrahedra and linear boundary
/// triangles given as corner indices into `vertices`. Returns a mesh satisfying the
/// Mesh invariants: vertices used by no tet are dropped (the others keep their relative
/// order), edge nodes follow in order of first use by the tets, tets are re-oriented and
/// boundary faces point outward. Throws std::runtime_error on an index out of range, a
/// degenerate tet, or a boundary face edge that is no tet edge (naming boundary and face).
Mesh make_p2_from_linear(
    std::vector<Point> vertices, const std::vector<std::array<Index, 4>>& tets,
    const std::vector<std::pair<std::string, std::vector<std::array<Index, 3>>>>& boundaries);

}  // namespace biphasic
