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

AssemblyScope subdomain_scope(const Mesh& whole, const Subdomain& sub) {
  AssemblyScope s;
  s.element_owned = sub.element_owned;
  s.node_owned = sub.node_owned;
  s.mean_element_length = mean_element_length(whole);
  std::tie(s.lower, s.upper) = bounding_box(whole);
  s.region_used.assign(whole.region_names.size(), 0);
  for (std::size_t e = 0; e < whole.tets.size(); ++e)
    if (!s.region_used.empty())
      s.region_used[static_cast<std::size_t>(whole.region_of(static_cast<Index>(e)))] = 1;
  return s;
}

AssemblyScope subdomain_scope(const SectionMesh& whole, const SectionSubdomain& sub,
                              SectionModel model) {
  AssemblyScope s;
  s.element_owned = sub.element_owned;
  s.node_owned = sub.node_owned;
  s.section_depth = section_mean_depth(whole, model);
  s.lower = {1e300, 1e300, 0.0};
  s.upper = {-1e300, -1e300, 0.0};
  for (const Point2& x : whole.nodes)
    for (std::size_t c = 0; c < 2; ++c) {
      s.lower[c] = std::min(s.lower[c], x[c]);
      s.upper[c] = std::max(s.upper[c], x[c]);
    }
  s.region_used.assign(whole.region_names.size(), 0);
  for (std::size_t e = 0; e < whole.triangles.size(); ++e)
    if (!s.region_used.empty())
      s.region_used[static_cast<std::size_t>(whole.region_of(static_cast<Index>(e)))] = 1;
  return s;
}

}  // namespace biphasic
