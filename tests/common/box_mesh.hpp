// Structured box meshes for tests: n_x × n_y × n_z cells, each split into six tetrahedra
// (Kuhn subdivision, conforming), P2 edge nodes at midpoints. Boundaries "x0", "x1", "y0",
// "y1", "z0", "z1" (planes at the box's bounds).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh_sources.hpp"

namespace biphasic::test {

inline Mesh box_mesh(std::array<int, 3> cells, std::array<double, 3> size) {
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  auto vid = [&](int i, int j, int k) -> Index {
    return (static_cast<Index>(k) * (ny + 1) + j) * (nx + 1) + i;
  };
  std::vector<Point> vertices;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        vertices.push_back({size[0] * i / nx, size[1] * j / ny, size[2] * k / nz});
  std::vector<std::array<Index, 4>> tets;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          int c[3] = {0, 0, 0};
          std::array<Index, 4> t{};
          t[0] = vid(i, j, k);
          for (int s = 0; s < 3; ++s) {
            c[p[s]] = 1;
            t[s + 1] = vid(i + c[0], j + c[1], k + c[2]);
          }
          tets.push_back(t);
        }
  // Boundary triangles: cell faces on the box surface, split along the diagonal that the
  // Kuhn tetrahedra use (from the lower corner to the upper corner of the face).
  std::vector<std::pair<std::string, std::vector<std::array<Index, 3>>>> boundaries;
  const char* names[3][2] = {{"x0", "x1"}, {"y0", "y1"}, {"z0", "z1"}};
  const int n[3] = {nx, ny, nz};
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      std::vector<std::array<Index, 3>> faces;
      for (int u = 0; u < n[a1]; ++u)
        for (int v = 0; v < n[a2]; ++v) {
          auto at = [&](int du, int dv) {
            int idx[3];
            idx[axis] = side * n[axis];
            idx[a1] = u + du;
            idx[a2] = v + dv;
            return vid(idx[0], idx[1], idx[2]);
          };
          faces.push_back({at(0, 0), at(1, 0), at(1, 1)});
          faces.push_back({at(0, 0), at(1, 1), at(0, 1)});
        }
      boundaries.emplace_back(names[axis][side], std::move(faces));
    }
  }
  return make_p2_from_linear(std::move(vertices), tets, boundaries);
}

}  // namespace biphasic::test
