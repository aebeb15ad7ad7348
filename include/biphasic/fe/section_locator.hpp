// Finding the triangle of a section mesh that contains a point of the section, and the point's
// reference coordinates in it: the two-dimensional counterpart of point_locator.hpp.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// Where a point lies in a section mesh.
struct SectionPointLocation {
  Index triangle = -1;          ///< triangle index
  std::array<double, 2> eta{};  ///< reference coordinates η (tri6_values order)
  double distance_outside = 0;  ///< estimated distance [mm] from the triangle, 0 when inside
};

/// Reference coordinates of x in the 6-node triangle with nodes X (local order of Tri6) and an
/// estimate of how far x lies outside it [mm]. Straight-sided triangles (edge nodes at the
/// midpoints): the barycentric coordinates, exact. Curved ones: Newton iterations on
/// x(η) = Σ N_a(η) X_a from that guess. The distance is max_i(−L_i / |∇L_i|) over the
/// barycentric coordinates L_i(η) with the map's gradients at η (0 when all L_i ≥ 0). `eta` is
/// not clamped.
SectionPointLocation locate_in_triangle(const std::array<Point2, 6>& X, const Point2& x);

/// Point location over a section mesh: each triangle whose node bounding box (enlarged by the
/// tolerance) holds the point is tried. Section meshes are small: no search structure.
class SectionPointLocator {
 public:
  /// Throws std::runtime_error for a mesh without triangles.
  explicit SectionPointLocator(const SectionMesh& mesh);

  /// The triangle containing x, or failing that the one x lies closest outside of when that
  /// is at most `tolerance` [mm] away, η moved onto the triangle (negative barycentric
  /// coordinates set to 0, the others rescaled). std::nullopt when x is farther out.
  std::optional<SectionPointLocation> locate(const Point2& x, double tolerance) const;

  /// Diagonal of the mesh's bounding box [mm].
  double diagonal() const;

 private:
  const SectionMesh& mesh_;
  /// Per triangle, its nodes' bounding box (x_lo, y_lo, x_hi, y_hi) [mm].
  std::vector<std::array<double, 4>> boxes_;
  Point2 lo_{};
  Point2 hi_{};
};

}  // namespace biphasic
