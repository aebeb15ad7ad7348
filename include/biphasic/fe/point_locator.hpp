// Finding the element of a P2 tetrahedral mesh that contains a point, and the point's
// reference coordinates in it (the inverse of the isoparametric map x(ξ) = Σ_a N_a(ξ) X_a).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// Where a point lies in the mesh.
struct PointLocation {
  Index tet = -1;               ///< element index
  std::array<double, 3> xi{};   ///< reference coordinates ξ, inside the reference tetrahedron
  double distance_outside = 0;  ///< estimated distance [mm] from the element, 0 when inside
};

/// Reference coordinates of x in the P2 element with nodes X (local order of mesh.hpp), and
/// an estimate of how far x lies outside it [mm]. Straight-sided elements: the barycentric
/// coordinates (exact). Curved ones: Newton iterations on x(ξ) = x from the straight-sided
/// guess. The distance is max_i(−L_i / |∇L_i|) over the barycentric coordinates L_i(ξ) with the
/// gradients of the map at ξ (0 when every L_i ≥ 0). `xi` is not clamped.
PointLocation locate_in_element(const std::array<Point, 10>& X, const Point& x);

/// Point location over a whole mesh through a uniform grid of cells over the mesh's bounding
/// box; each cell lists the elements whose (slightly enlarged) node bounding box meets it.
class PointLocator {
 public:
  /// Throws std::runtime_error for a mesh without elements.
  explicit PointLocator(const Mesh& mesh);

  /// The element containing x, or failing that the element x lies closest outside of when
  /// that is at most `tolerance` [mm] away; ξ is then moved onto the element's surface
  /// (negative barycentric coordinates set to 0). std::nullopt when x is farther from the
  /// body (or outside the bounding box by more than the tolerance).
  std::optional<PointLocation> locate(const Point& x, double tolerance) const;

  /// Diagonal of the mesh's bounding box [mm].
  double diagonal() const;

 private:
  const Mesh& mesh_;
  Point lo_{};
  Point hi_{};
  std::array<int, 3> cells_{};
  std::array<double, 3> cell_size_{};
  std::vector<std::size_t> cell_start_;  ///< CSR offsets into cell_tets_, size cells + 1
  std::vector<Index> cell_tets_;

  std::array<int, 3> cell_of(const Point& x) const;
};

}  // namespace biphasic
