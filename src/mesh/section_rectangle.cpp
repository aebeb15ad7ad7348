// Generated rectangular section: a structured grid of cells, each split into two triangles along
// diagonals that alternate in a checkerboard, with optional geometric grading in r and z. No
// gmsh: no module start-up, exact grading, and the same mesh on every machine.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "generator_support.hpp"
#include "section_support.hpp"

namespace biphasic {

namespace {

constexpr std::array<const char*, 4> kSectionCurves{"axis", "lateral", "bottom", "top"};

bool grades_toward(const SectionRectangleSpec& spec, const char* curve) {
  return std::find(spec.grading_curves.begin(), spec.grading_curves.end(), curve) !=
         spec.grading_curves.end();
}

void require_count(const char* what, int value) {
  if (value < 1)
    throw std::runtime_error(std::string(what) + " must be >= 1, got " + std::to_string(value));
}

// Throws unless `cells` (named `what`) can be graded toward the curves `low` and `high` of
// that direction with the spec's ratio.
void require_gradable(const SectionRectangleSpec& spec, const char* what, int cells,
                      const char* low, const char* high) {
  const bool at_low = grades_toward(spec, low), at_high = grades_toward(spec, high);
  if (spec.grading_ratio <= 1.0 || !(at_low || at_high)) return;
  const bool both = at_low && at_high;
  const int needed = both ? 3 : 2;
  if (cells < needed) {
    std::ostringstream msg;
    msg << what << " must be >= " << needed << " for grading_ratio " << spec.grading_ratio
        << " toward "
        << (both ? "both '" + std::string(low) + "' and '" + high + "'"
                 : "'" + std::string(at_low ? low : high) + "'")
        << ", got " << cells;
    throw std::runtime_error(msg.str());
  }
}

void validate(const SectionRectangleSpec& spec) {
  detail::require_positive("width", spec.width);
  detail::require_positive("height", spec.height);
  require_count("nr", spec.nr);
  require_count("nz", spec.nz);
  const double cells = static_cast<double>(spec.nr) * spec.nz;
  if (cells > static_cast<double>(kMaxColumnCells)) {
    throw std::runtime_error("nr * nz = " + std::to_string(spec.nr) + " * " +
                             std::to_string(spec.nz) + " cells is more than the limit of " +
                             std::to_string(kMaxColumnCells));
  }
  detail::require_at_least_one("grading_ratio", spec.grading_ratio);
  for (const std::string& name : spec.grading_curves) {
    if (std::find(kSectionCurves.begin(), kSectionCurves.end(), name) != kSectionCurves.end())
      continue;
    throw std::runtime_error("grading_curves: unknown curve '" + name +
                             "' (valid names: axis, lateral, bottom, top)");
  }
  require_gradable(spec, "nr", spec.nr, "axis", "lateral");
  require_gradable(spec, "nz", spec.nz, "bottom", "top");
}

// The n + 1 cell boundaries over [0, length], graded like column_layer_z: cell k has size
// ∝ ratio^(e_k / m), e_k its distance in cells from the nearest graded end and m the largest
// e_k, so the smallest cells touch the graded ends and largest / smallest = ratio exactly.
std::vector<double> graded_coordinates(double length, int n, double ratio, bool at_low,
                                       bool at_high) {
  const int m = at_low && at_high ? (n - 1) / 2 : n - 1;
  std::vector<double> size(static_cast<std::size_t>(n), 1.0);
  if (ratio > 1.0 && (at_low || at_high)) {
    for (int k = 0; k < n; ++k) {
      const int e = at_low && at_high ? std::min(k, n - 1 - k) : (at_low ? k : n - 1 - k);
      size[static_cast<std::size_t>(k)] = std::pow(ratio, static_cast<double>(e) / m);
    }
  }
  std::vector<double> partial(static_cast<std::size_t>(n) + 1, 0.0);
  for (std::size_t k = 0; k < size.size(); ++k) partial[k + 1] = partial[k] + size[k];
  std::vector<double> x(partial.size());
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = length * partial[k] / partial.back();
  x.front() = 0.0;
  x.back() = length;
  return x;
}

}  // namespace

SectionMesh generate_section_rectangle(const SectionRectangleSpec& spec) {
  return detail::with_context("generate_section_rectangle", [&] {
    validate(spec);
    const int nr = spec.nr, nz = spec.nz;
    const std::vector<double> r =
        graded_coordinates(spec.width, nr, spec.grading_ratio, grades_toward(spec, "axis"),
                           grades_toward(spec, "lateral"));
    const std::vector<double> z =
        graded_coordinates(spec.height, nz, spec.grading_ratio, grades_toward(spec, "bottom"),
                           grades_toward(spec, "top"));

    // Vertex (i, j) at (r_i, z_j), numbered r fastest.
    const auto at = [nr](int i, int j) {
      return static_cast<Index>(i) + (static_cast<Index>(nr) + 1) * static_cast<Index>(j);
    };
    std::vector<Point2> vertices;
    vertices.reserve((static_cast<std::size_t>(nr) + 1) * (static_cast<std::size_t>(nz) + 1));
    for (int j = 0; j <= nz; ++j)
      for (int i = 0; i <= nr; ++i)
        vertices.push_back({r[static_cast<std::size_t>(i)], z[static_cast<std::size_t>(j)]});

    // Cell (i, j) split along (i, j)–(i+1, j+1) where i + j is even, along (i+1, j)–(i, j+1)
    // where it is odd; both triangles counter-clockwise.
    std::vector<std::array<Index, 3>> triangles;
    triangles.reserve(2 * static_cast<std::size_t>(nr) * static_cast<std::size_t>(nz));
    for (int j = 0; j < nz; ++j) {
      for (int i = 0; i < nr; ++i) {
        const Index v00 = at(i, j), v10 = at(i + 1, j), v01 = at(i, j + 1), v11 = at(i + 1, j + 1);
        if ((i + j) % 2 == 0) {
          triangles.push_back({v00, v10, v11});
          triangles.push_back({v00, v11, v01});
        } else {
          triangles.push_back({v00, v10, v01});
          triangles.push_back({v10, v11, v01});
        }
      }
    }

    // Curves run counter-clockwise around the rectangle (body on the left).
    std::vector<detail::LinearCurve> curves{
        {"axis", {}}, {"lateral", {}}, {"bottom", {}}, {"top", {}}};
    for (int j = 0; j < nz; ++j) {
      curves[0].second.push_back({at(0, j + 1), at(0, j)});
      curves[1].second.push_back({at(nr, j), at(nr, j + 1)});
    }
    for (int i = 0; i < nr; ++i) {
      curves[2].second.push_back({at(i, 0), at(i + 1, 0)});
      curves[3].second.push_back({at(i + 1, nz), at(i, nz)});
    }
    return detail::section_p2_from_linear(std::move(vertices), triangles, curves);
  });
}

}  // namespace biphasic
