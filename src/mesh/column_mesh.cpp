// Generated column (box) of tetrahedra: structured hexahedral cells, each split into six
// tetrahedra along its main diagonal (Kuhn / Freudenthal), with optional geometric grading of
// the layers in z. For 1D-like consolidation benchmarks (Terzaghi, confined compression).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "generator_support.hpp"

namespace biphasic {

namespace {

constexpr std::array<const char*, 2> kGradingFaces{"bottom", "top"};

void require_count(const char* what, int value) {
  if (value < 1)
    throw std::runtime_error(std::string(what) + " must be >= 1, got " + std::to_string(value));
}

bool grades_toward(const ColumnSpec& spec, const char* face) {
  return std::find(spec.grading_faces.begin(), spec.grading_faces.end(), face) !=
         spec.grading_faces.end();
}

void validate(const ColumnSpec& spec) {
  detail::require_positive("width", spec.width);
  detail::require_positive("depth", spec.depth);
  detail::require_positive("height", spec.height);
  require_count("nx", spec.nx);
  require_count("ny", spec.ny);
  require_count("nz", spec.nz);
  // Counts in 64 bits: nx = 2^31 − 1 overflowed int arithmetic in the lattice numbering.
  // The product in double: three counts near 2^31 would overflow 64 bits.
  const double cells = static_cast<double>(spec.nx) * spec.ny * spec.nz;
  if (cells > static_cast<double>(kMaxColumnCells)) {
    throw std::runtime_error("nx * ny * nz = " + std::to_string(spec.nx) + " * " +
                             std::to_string(spec.ny) + " * " + std::to_string(spec.nz) +
                             " cells is more than the limit of " + std::to_string(kMaxColumnCells));
  }
  detail::require_at_least_one("grading_ratio", spec.grading_ratio);
  detail::require_known_faces(spec.grading_faces, kGradingFaces);
  if (spec.grading_ratio > 1.0 && !spec.grading_faces.empty()) {
    const bool both = grades_toward(spec, "bottom") && grades_toward(spec, "top");
    const int needed = both ? 3 : 2;
    if (spec.nz < needed) {
      std::ostringstream msg;
      msg << "nz must be >= " << needed << " for grading_ratio " << spec.grading_ratio << " toward "
          << (both ? "both 'bottom' and 'top'" : "one face") << ", got " << spec.nz;
      throw std::runtime_error(msg.str());
    }
  }
}

// Coordinate i of n equal divisions of [0, length], exact at both ends.
double uniform_coordinate(double length, int i, int n) {
  return i == n ? length : length * static_cast<double>(i) / static_cast<double>(n);
}

// Corner indices of the linear mesh: vertex (i, j, k) of the (nx+1)(ny+1)(nz+1) lattice.
struct Lattice {
  int nx, ny;
  Index operator()(int i, int j, int k) const {
    return i + (static_cast<Index>(nx) + 1) * (j + (static_cast<Index>(ny) + 1) * k);
  }
};

// Two triangles of the lattice square with lowest corner `o` spanned by the unit steps `a`
// and `b`, split along the diagonal o → o + a + b, which is an edge of the Kuhn tets.
void add_square(const Lattice& at, std::array<int, 3> o, std::array<int, 3> a, std::array<int, 3> b,
                std::vector<std::array<Index, 3>>& faces) {
  const auto vertex = [&](int sa, int sb) {
    return at(o[0] + sa * a[0] + sb * b[0], o[1] + sa * a[1] + sb * b[1],
              o[2] + sa * a[2] + sb * b[2]);
  };
  faces.push_back({vertex(0, 0), vertex(1, 0), vertex(1, 1)});
  faces.push_back({vertex(0, 0), vertex(0, 1), vertex(1, 1)});
}

// z of the nz + 1 layer interfaces of a valid spec (see column_layer_z).
std::vector<double> layer_coordinates(const ColumnSpec& spec) {
  const int nz = spec.nz;
  const bool bottom = grades_toward(spec, "bottom"), top = grades_toward(spec, "top");
  // Layer k has thickness ∝ ratio^(e_k / m), e_k its distance in layers from the nearest
  // graded face and m the largest e_k.
  const int m = bottom && top ? (nz - 1) / 2 : nz - 1;
  std::vector<double> thickness(static_cast<std::size_t>(nz), 1.0);
  if (spec.grading_ratio > 1.0 && (bottom || top)) {
    for (int k = 0; k < nz; ++k) {
      const int e = bottom && top ? std::min(k, nz - 1 - k) : (bottom ? k : nz - 1 - k);
      thickness[static_cast<std::size_t>(k)] =
          std::pow(spec.grading_ratio, static_cast<double>(e) / m);
    }
  }
  std::vector<double> partial(static_cast<std::size_t>(nz) + 1, 0.0);
  for (std::size_t k = 0; k < thickness.size(); ++k) partial[k + 1] = partial[k] + thickness[k];
  std::vector<double> z(partial.size());
  for (std::size_t k = 0; k < z.size(); ++k) z[k] = spec.height * partial[k] / partial.back();
  z.back() = spec.height;
  return z;
}

/// Regions of the column's tets from spec.region_names and region_tops (tets are stored layer by
/// layer, 6·nx·ny per layer); throws naming the region whose top is not a layer interface.
void assign_column_regions(const ColumnSpec& spec, const std::vector<double>& z, Mesh& mesh) {
  if (spec.region_names.empty() && spec.region_tops.empty()) return;
  if (spec.region_names.size() != spec.region_tops.size())
    throw std::runtime_error(std::to_string(spec.region_names.size()) + " region names but " +
                             std::to_string(spec.region_tops.size()) + " region tops");
  const double tolerance = 1e-9 * spec.height;
  std::vector<int> layer_region(z.size() - 1, -1);
  std::size_t next_layer = 0;
  double below = 0.0;
  for (std::size_t r = 0; r < spec.region_names.size(); ++r) {
    const std::string& name = spec.region_names[r];
    const double top = spec.region_tops[r];
    const std::string label = "region " + std::to_string(r) + " ('" + name + "')";
    if (name.empty()) throw std::runtime_error(label + ": empty name");
    for (std::size_t q = 0; q < r; ++q)
      if (spec.region_names[q] == name)
        throw std::runtime_error(label + ": the name is used twice");
    if (!(top > below + tolerance))
      throw std::runtime_error(label + ": top z = " + std::to_string(top) +
                               " mm must be above the region below it (" + std::to_string(below) +
                               " mm)");
    std::size_t k = next_layer;
    while (k + 1 < z.size() && z[k + 1] < top - tolerance) ++k;
    if (k + 1 >= z.size() || std::abs(z[k + 1] - top) > tolerance)
      throw std::runtime_error(label + ": top z = " + std::to_string(top) +
                               " mm is not a layer interface of the column");
    for (std::size_t l = next_layer; l <= k; ++l) layer_region[l] = static_cast<int>(r);
    next_layer = k + 1;
    below = top;
    mesh.region_names.push_back(name);
  }
  if (next_layer != layer_region.size())
    throw std::runtime_error("the last region's top z = " + std::to_string(below) +
                             " mm must be the column's height, " + std::to_string(spec.height) +
                             " mm");
  const std::size_t per_layer = 6 * static_cast<std::size_t>(spec.nx) * spec.ny;
  mesh.tet_region.resize(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    mesh.tet_region[t] = layer_region[t / per_layer];
}

}  // namespace

std::vector<double> column_layer_z(const ColumnSpec& spec) {
  return detail::with_context("column_layer_z", [&] {
    validate(spec);
    return layer_coordinates(spec);
  });
}

Mesh generate_column(const ColumnSpec& spec) {
  return detail::with_context("generate_column", [&] {
    validate(spec);
    const std::vector<double> z = layer_coordinates(spec);
    const int nx = spec.nx, ny = spec.ny, nz = spec.nz;
    const Lattice at{nx, ny};
    std::vector<Point> vertices;
    vertices.reserve((static_cast<std::size_t>(nx) + 1) * (static_cast<std::size_t>(ny) + 1) *
                     (static_cast<std::size_t>(nz) + 1));
    for (int k = 0; k <= nz; ++k) {
      for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
          vertices.push_back({uniform_coordinate(spec.width, i, nx),
                              uniform_coordinate(spec.depth, j, ny),
                              z[static_cast<std::size_t>(k)]});
        }
      }
    }

    // Kuhn split: for each order (p, q, r) of the axes, the tet along the path
    // 000 → e_p → e_p + e_q → 111 of the cell. Every cell face is then cut along the diagonal
    // from its lowest to its highest corner, the same from both sides: the mesh is conforming.
    static constexpr std::array<std::array<int, 3>, 6> kAxisOrders{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<std::array<Index, 4>> tets;
    tets.reserve(6 * static_cast<std::size_t>(nx) * ny * nz);
    for (int k = 0; k < nz; ++k) {
      for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
          for (const auto& order : kAxisOrders) {
            std::array<int, 3> c{i, j, k};
            std::array<Index, 4> tet{at(i, j, k), 0, 0, 0};
            for (int s = 0; s < 3; ++s) {
              ++c[static_cast<std::size_t>(order[static_cast<std::size_t>(s)])];
              tet[static_cast<std::size_t>(s) + 1] = at(c[0], c[1], c[2]);
            }
            tets.push_back(tet);
          }
        }
      }
    }

    constexpr std::array<int, 3> ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
    std::vector<std::pair<std::string, std::vector<std::array<Index, 3>>>> boundaries{
        {"bottom", {}}, {"top", {}}, {"x0", {}}, {"x1", {}}, {"y0", {}}, {"y1", {}}};
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        add_square(at, {i, j, 0}, ex, ey, boundaries[0].second);
        add_square(at, {i, j, nz}, ex, ey, boundaries[1].second);
      }
    }
    for (int k = 0; k < nz; ++k) {
      for (int j = 0; j < ny; ++j) {
        add_square(at, {0, j, k}, ey, ez, boundaries[2].second);
        add_square(at, {nx, j, k}, ey, ez, boundaries[3].second);
      }
      for (int i = 0; i < nx; ++i) {
        add_square(at, {i, 0, k}, ex, ez, boundaries[4].second);
        add_square(at, {i, ny, k}, ex, ez, boundaries[5].second);
      }
    }
    Mesh mesh = make_p2_from_linear(std::move(vertices), tets, boundaries);
    assign_column_regions(spec, z, mesh);
    return mesh;
  });
}

}  // namespace biphasic
