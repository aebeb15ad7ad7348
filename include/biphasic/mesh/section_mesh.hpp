// Quadratic triangular mesh of a two-dimensional section (mm): the meridian half-plane
// (r, z) of an axisymmetric body or the cross-section (x, y) of a plane-strain body, with named
// boundary curves. The two-dimensional counterpart of Mesh (mesh.hpp).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// A point of the section [mm]: (r, z) for an axisymmetric model, (x, y) for plane strain.
using Point2 = std::array<double, 2>;

/// A 3-node boundary segment: its two ends, then its midside node.
using Line3 = std::array<Index, 3>;

/// A named boundary curve (a gmsh physical curve) as a set of 3-node segments.
struct SectionBoundary {
  std::string name;
  std::vector<Line3> segments;
};

/// P2 triangular mesh (6-node triangles, local order of kTriEdges in mesh.hpp). Invariant:
/// the first `num_vertices` entries of `nodes` are triangle corners (they carry the P1
/// pressure); the rest are edge nodes. Every triangle is counter-clockwise (positive area) in
/// the local order; every boundary segment runs with the body on its left (its outward normal
/// (t_y, −t_x) for the tangent t from end 0 to end 1).
struct SectionMesh {
  std::vector<Point2> nodes;  ///< node coordinates [mm]
  Index num_vertices = 0;     ///< corner nodes come first
  std::vector<Tri6> triangles;
  std::vector<SectionBoundary> boundaries;
  /// Physical points of a .msh file (dimension 0 node sets); empty for generated meshes.
  std::vector<NodeSet> node_sets;
  /// Per node, its tag in the .msh file it was read from (−1 for an edge node made here);
  /// empty for generated meshes.
  std::vector<Index> file_tags;
  /// Material regions: per triangle, an index into `region_names` (a .msh file's physical
  /// surfaces). Both empty: one unnamed region.
  std::vector<int> triangle_region;
  std::vector<std::string> region_names;

  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  /// The boundary with this name, or nullptr.
  const SectionBoundary* find_boundary(const std::string& name) const;
  /// Names of all boundaries, in stored order.
  std::vector<std::string> boundary_names() const;
  /// Region index of triangle t (0 when the mesh has no regions).
  int region_of(Index t) const { return triangle_region.empty() ? 0 : triangle_region[t]; }
  /// The node set with this name, or nullptr.
  const NodeSet* find_node_set(const std::string& name) const;
  /// "node 12 (file tag 40) at (1, 2) mm": how messages name node n.
  std::string describe_node(Index n) const;
};

/// Signed area [mm²] of the straight triangle (a, b, c): positive when counter-clockwise.
double triangle_signed_area(const Point2& a, const Point2& b, const Point2& c);

/// Gives every triangle a positive area: where the corner area is negative, swaps local
/// vertices 1 and 2 together with edge nodes 3↔5. Throws std::runtime_error naming the
/// triangle and its area if it is degenerate (|area| ≤ 1e-12 · longest edge²).
void orient_triangles(SectionMesh& mesh);

/// Orients every boundary segment so that the body lies on its left (swaps its ends where
/// needed); on a curve inside the body (an edge of two triangles) the first triangle having the
/// edge decides. Throws std::runtime_error naming the boundary and the segment if a segment is
/// the edge of no triangle.
void orient_boundary_segments(SectionMesh& mesh);

/// Checks every SectionMesh invariant: indices in range, corners < num_vertices ≤ edge
/// nodes, every vertex a corner of some triangle, one edge node per vertex pair shared by all
/// triangles and boundary segments using that edge, positive areas, boundary segments on
/// triangle edges and oriented (some triangle runs along the segment from end 0 to end 1 in
/// its counter-clockwise order), node sets' nodes in range, names distinct (boundaries, node
/// sets, regions; no node set named like a boundary), regions consistent, file_tags empty or
/// one per node. Throws std::runtime_error describing the first violation found.
void check_section_mesh(const SectionMesh& mesh);

/// The rectangle 0 ≤ r ≤ width, 0 ≤ z ≤ height of a cylinder's meridian section (or a
/// plane-strain slab), generated directly (no gmsh): a structured grid of nr × nz cells, each
/// split into two triangles along alternating diagonals (a "union jack" pattern that favours no
/// direction), cell sizes graded geometrically toward the named curves. Boundary curves, in this
/// order: "axis" (r = 0), "lateral" (r = width), "bottom" (z = 0), "top" (z = height).
struct SectionRectangleSpec {
  double width = 18.0;  ///< radius (axisymmetric) or half-width (plane strain) [mm]
  double height = 8.0;  ///< [mm]
  int nr = 18;          ///< cells across the width, ≥ 1
  int nz = 8;           ///< cells over the height, ≥ 1
  /// Curves the cells are graded toward: any of "axis", "lateral", "bottom", "top".
  std::vector<std::string> grading_curves;
  /// Largest over smallest cell size in each graded direction (≥ 1; 1 = uniform); the
  /// smallest cells touch the graded curves (both ends of a direction when both are named).
  double grading_ratio = 1.0;
};

/// Generates the rectangle as a P2 section mesh (straight edges). Deterministic. Throws
/// std::runtime_error naming the field and its value on an invalid spec (non-positive or
/// non-finite size, count < 1, grading_ratio < 1, unknown curve name, too few cells to grade).
SectionMesh generate_section_rectangle(const SectionRectangleSpec& spec);

/// Reads a gmsh .msh file (format 2.2 or 4.1) with 3- or 6-node triangles in the plane z = 0.
/// Boundaries are the physical curves (2- or 3-node lines) by name (an unnamed one by its tag
/// in decimal); physical surfaces become regions; physical points become node sets. A linear
/// mesh gets straight midside nodes. Triangles are oriented counter-clockwise, segments with
/// the body on their left; nodes used by no element are dropped. Throws std::runtime_error
/// naming the file on failure (missing file, no triangles, mixed orders, nodes off z = 0,
/// curve segments that are not triangle edges, degenerate triangles).
SectionMesh read_gmsh_section(const std::string& path);

}  // namespace biphasic
