#include "biphasic/physics/assembly_scope.hpp"

#include <algorithm>

#include "biphasic/fe/tet_geometry.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {

double mean_element_length(const Mesh& mesh) {
  double sum = 0.0;
  for (const Tet10& t : mesh.tets) {
    TetCorners x;
    for (int a = 0; a < 4; ++a) {
      const Point& p = mesh.nodes[static_cast<std::size_t>(t[a])];
      x[a] = Vec3(p[0], p[1], p[2]);
    }
    sum += tet_volume_diameter(x);
  }
  return sum / static_cast<double>(std::max<std::size_t>(1, mesh.tets.size()));
}

std::pair<Point, Point> bounding_box(const Mesh& mesh) {
  Point lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Point& x : mesh.nodes)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], x[c]);
      hi[c] = std::max(hi[c], x[c]);
    }
  return {lo, hi};
}

std::pair<Point, Point> bounding_box(const SectionMesh& mesh) {
  Point lo{1e300, 1e300, 0.0}, hi{-1e300, -1e300, 0.0};
  for (const Point2& x : mesh.nodes)
    for (std::size_t c = 0; c < 2; ++c) {
      lo[c] = std::min(lo[c], x[c]);
      hi[c] = std::max(hi[c], x[c]);
    }
  return {lo, hi};
}

namespace {

/// What every part's scope takes alike: its own elements and nodes, the whole mesh's bounding
/// box and the regions its elements use.
template <class AnyMesh>
AssemblyScope common_scope(const AnyMesh& whole, std::size_t num_elements,
                           const SubdomainMap& sub) {
  AssemblyScope s;
  s.element_owned = sub.element_owned;
  s.node_owned = sub.node_owned;
  std::tie(s.lower, s.upper) = bounding_box(whole);
  s.region_used.assign(whole.region_names.size(), 0);
  for (std::size_t e = 0; e < num_elements; ++e)
    if (!s.region_used.empty())
      s.region_used[static_cast<std::size_t>(whole.region_of(static_cast<Index>(e)))] = 1;
  return s;
}

}  // namespace

AssemblyScope subdomain_scope(const Mesh& whole, const Subdomain& sub) {
  AssemblyScope s = common_scope(whole, whole.tets.size(), sub);
  s.mean_element_length = mean_element_length(whole);
  return s;
}

AssemblyScope subdomain_scope(const SectionMesh& whole, const SectionSubdomain& sub,
                              SectionModel model) {
  AssemblyScope s = common_scope(whole, whole.triangles.size(), sub);
  s.section_depth = section_mean_depth(whole, model);
  return s;
}

}  // namespace biphasic
