// Ways to obtain a Mesh: generated quarter cylinder, column and sphere octant, or a user's gmsh
// .msh file.
#pragma once

#include <cstdint>
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
  /// > 0: a swept mesh instead — the bottom quarter disc triangulated at lc and extruded
  /// along z in this many layers of tetrahedra (three per prism), the layer thicknesses graded
  /// toward layer_grading_faces ("bottom", "top") as in column_layer_z. Resolves the thin
  /// boundary layers at the drained faces with few elements. Excludes grading_faces.
  int layers = 0;
  std::vector<std::string> layer_grading_faces;
  double layer_grading_ratio = 1.0;  ///< thickest over thinnest layer, ≥ 1
  std::string write_msh;             ///< if not empty, write the generated mesh here (.msh 4.1)
};

/// Generates the quarter cylinder with gmsh and returns it as a P2 mesh (edge nodes placed
/// on the curved lateral surface, boundary faces pointing outward). Deterministic for a given
/// spec; leaves gmsh initialized or not, with its current model and options, as it found it.
/// Throws std::runtime_error on failure or on an invalid spec (non-positive sizes, unknown
/// grading face, grading_ratio < 1).
Mesh generate_quarter_cylinder(const QuarterCylinderSpec& spec);

/// Box [0, width] × [0, depth] × [0, height] of nx × ny × nz hexahedral cells, each split
/// into six tetrahedra along its diagonal from (x_i, y_j, z_k) to (x_{i+1}, y_{j+1}, z_{k+1})
/// (Kuhn split, conforming). x and y are divided uniformly; the nz layers follow
/// column_layer_z. Boundaries, in this order: "bottom" (z = 0), "top" (z = height),
/// "x0" (x = 0), "x1" (x = width), "y0" (y = 0), "y1" (y = depth).
struct ColumnSpec {
  double width = 1.0;   ///< extent in x [mm]
  double depth = 1.0;   ///< extent in y [mm]
  double height = 1.0;  ///< extent in z [mm]
  int nx = 1;           ///< cells in x, ≥ 1
  int ny = 1;           ///< cells in y, ≥ 1
  int nz = 10;          ///< layers in z, ≥ 1
  /// Faces the layers are graded toward: "bottom", "top" or both. Empty = uniform.
  std::vector<std::string> grading_faces;
  /// Thickness of the thickest layer over that of the thinnest (≥ 1; 1 = uniform). Needs
  /// nz ≥ 2 when grading toward one face, nz ≥ 3 toward both.
  double grading_ratio = 1.0;
  /// Material regions stacked in z, from the bottom: region r, named region_names[r], spans
  /// [region_tops[r − 1] (0 for the first), region_tops[r]] [mm]. Every top must be a layer
  /// interface (column_layer_z, within 1e-9 · height), increasing, the last one = height; names
  /// distinct and not empty; the lists of equal length. Both empty: a mesh without regions.
  std::vector<std::string> region_names;
  std::vector<double> region_tops;
};

/// Most cells (nx · ny · nz) of a column: 6e8 tets, far beyond any machine's memory; it only
/// keeps every count and index well inside 64-bit arithmetic.
inline constexpr std::int64_t kMaxColumnCells = 100'000'000;

/// z [mm] of the nz + 1 layer interfaces of the column: layer k spans [z_k, z_{k+1}],
/// z_0 = 0, z_nz = height exactly, and z_k = height · S_k / S_nz with S_k = Σ_{j<k} h_j and
/// h_j = grading_ratio^(e_j / m), where e_j is the distance in layers of layer j from the graded
/// face (j toward "bottom", nz − 1 − j toward "top", min(j, nz − 1 − j) toward both) and m the
/// largest e_j (nz − 1, or ⌊(nz − 1)/2⌋ for both). Uniform: h_j = 1, z_k = height · k / nz.
/// Thicknesses thus form a geometric progression of factor grading_ratio^(1/m) away from the
/// graded face(s), thinnest layer at a graded face, thickest/thinnest = grading_ratio. These are
/// exactly the vertex z-coordinates of generate_column. Throws like generate_column.
std::vector<double> column_layer_z(const ColumnSpec& spec);

/// Generates the column as a P2 mesh (straight edges, through make_p2_from_linear): vertices
/// numbered x fastest, then y, then z; tets re-oriented to positive volume, boundary faces
/// pointing outward. 6·nx·ny·nz tets, (nx+1)(ny+1)(nz+1) vertices. Throws std::runtime_error
/// naming the field and its value on an invalid spec (non-positive or non-finite size, count
/// < 1, grading_ratio < 1, unknown grading face, too few layers for the grading).
Mesh generate_column(const ColumnSpec& spec);

/// Octant of the ball of radius `radius` centred at the origin (x, y, z ≥ 0), generated with
/// the gmsh C++ API (OpenCASCADE). Boundaries, in this order: "surface" (r = radius),
/// "symmetry_x" (x = 0), "symmetry_y" (y = 0), "symmetry_z" (z = 0).
struct SphereOctantSpec {
  double radius = 1.0;  ///< [mm]
  double lc = 0.2;      ///< characteristic length [mm]
  /// Optional grading toward "surface": element size grows linearly from lc / grading_ratio on
  /// the surface to lc at distance grading_distance from it. 1 = uniform.
  double grading_ratio = 1.0;      ///< ≥ 1
  double grading_distance = 0.25;  ///< [mm]
  std::string write_msh;           ///< if not empty, write the generated mesh here (.msh 4.1)
};

/// Generates the sphere octant with gmsh and returns it as a P2 mesh: edge nodes of "surface"
/// lie on the sphere (gmsh places them on the CAD surface), boundary faces point outward.
/// Deterministic for a given spec; leaves gmsh initialized or not, with its current model and
/// options, as it found it. Throws std::runtime_error on failure or on an invalid spec
/// (radius, lc or grading_distance not positive and finite, grading_ratio < 1).
Mesh generate_sphere_octant(const SphereOctantSpec& spec);

/// Reads a gmsh .msh file (format 2.2 or 4.1) with 4-node or 10-node tetrahedra. Boundaries
/// are the physical surfaces (triangles) by name; a physical surface without a name is named
/// by its tag in decimal ("3"). A linear mesh gets straight-edge midpoints, a 10-node mesh
/// keeps its edge nodes. Inverted tets are re-oriented (see orient_tets), boundary faces point
/// outward (see orient_boundary_faces), nodes used by no element at all are dropped. Physical
/// points and curves become node sets (Mesh::node_sets, see NodeSet); each node keeps its file
/// tag (Mesh::file_tags). Throws std::runtime_error naming the file on failure (missing or
/// unreadable file, no tetrahedra, mixed element orders, boundary, point or curve nodes that
/// are not tet nodes, curve segments that are not tet edges, degenerate tets).
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
