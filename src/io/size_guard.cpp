#include "biphasic/io/size_guard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "biphasic/io/case_file.hpp"

namespace biphasic {

namespace {

/// Volume of a gmsh tetrahedron of size h, on average: c h³ [mm³] (a regular tet of edge h has
/// h³ / (6√2) ≈ 0.118 h³; gmsh's meshes at lc come out coarser: c ≈ 0.18 gives the 243 k
/// unknowns of the paper's mesh 4 within 6 %).
constexpr double kTetVolumeFactor = 0.18;
/// Unknowns per tetrahedron of a large P2 mesh: 3 × 1.35 nodes + 1/6 vertex.
constexpr double kUnknownsPerTet = 4.2;

/// Tets in a band of thickness d next to a face of area A where the size grows linearly from
/// f to h: ∫0^d A dz / (c (f + (h − f) z / d)³) = A d (1/f² − 1/h²) / (2c (h − f)).
double graded_band_tets(double area, double d, double f, double h) {
  if (h - f <= 1e-12 * h) return area * d / (kTetVolumeFactor * h * h * h);
  return area * d * (1.0 / (f * f) - 1.0 / (h * h)) / (2.0 * kTetVolumeFactor * (h - f));
}

/// Unstructured tets of a volume V with faces of total area A graded to lc / ratio over d.
double unstructured_tets(double volume, double graded_area, double lc, double ratio, double d) {
  const double uniform = volume / (kTetVolumeFactor * lc * lc * lc);
  if (graded_area <= 0.0 || ratio <= 1.0) return uniform;
  const double band = std::min(d, volume / graded_area);
  // gmsh's distance-threshold field puts about twice the tets of this integral in the band
  // (measured on the quarter cylinder, lc = 2 mm, ratio 3 on top and bottom).
  return uniform + 2.0 * graded_band_tets(graded_area, band, lc / ratio, lc);
}

double cylinder_face_area(const QuarterCylinderSpec& s, const std::string& face) {
  if (face == "bottom" || face == "top") return std::numbers::pi * s.radius * s.radius / 4.0;
  if (face == "lateral") return std::numbers::pi * s.radius / 2.0 * s.height;
  return s.radius * s.height;  // symmetry_x, symmetry_y
}

/// Nodes per element of the gmsh element types a tetrahedral mesh file holds (points, lines,
/// triangles, tetrahedra of order 1 and 2); 0 for any other type.
int msh_nodes_per_element(int type) {
  // gmsh type → nodes: 1 line(2), 2 triangle(3), 4 tet(4), 8 line(3), 9 triangle(6),
  // 11 tet(10), 15 point(1).
  constexpr int kNodes[16] = {0, 2, 3, 0, 4, 0, 0, 0, 3, 6, 0, 10, 0, 0, 0, 1};
  return type >= 0 && type < 16 ? kNodes[type] : 0;
}

bool is_tet(int type) { return type == 4 || type == 11; }

/// The tetrahedra in the $Elements section of a .msh file (2.2 or 4.1, ASCII or binary),
/// skipping points, lines and triangles block by block (2.2 ASCII: line by line). Where the
/// section cannot be walked (an element type other than those above, a truncated file), every
/// element of its header counts as a tetrahedron: an upper bound. 0 if even the header cannot
/// be read.
double msh_tet_count(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line, version;
  int file_type = 0, data_size = 0;
  while (std::getline(in, line) && line.rfind("$MeshFormat", 0) != 0) {
  }
  if (!(in >> version >> file_type >> data_size)) return 0.0;
  while (std::getline(in, line) && line.rfind("$Elements", 0) != 0) {
  }
  if (!in) return 0.0;
  const bool v2 = version.rfind("2", 0) == 0;
  double tets = 0.0;
  if (v2 && file_type == 0) {  // count, then one line per element: tag type ...
    double count = 0.0;
    if (!(in >> count)) return 0.0;
    std::getline(in, line);
    for (double i = 0; i < count; ++i) {
      long tag = 0;
      int type = 0;
      if (!std::getline(in, line) || std::sscanf(line.c_str(), "%ld %d", &tag, &type) != 2)
        return count;
      if (is_tet(type)) ++tets;
    }
    return tets;
  }
  if (v2) {  // binary 2.2: count, then blocks of (type, n, tags) headers and int data
    double count = 0.0;
    if (!(in >> count)) return 0.0;
    std::getline(in, line);
    for (double seen = 0; seen < count;) {
      std::int32_t header[3] = {0, 0, 0};
      if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return count;
      const int per = msh_nodes_per_element(header[0]);
      if (per == 0 || header[1] <= 0 || header[2] < 0 || header[2] > 1000) return count;
      if (is_tet(header[0])) tets += header[1];
      seen += header[1];
      in.seekg(static_cast<std::streamoff>(header[1]) * (1 + header[2] + per) * 4, std::ios::cur);
    }
    return tets;
  }
  if (file_type == 0) {  // ASCII 4.1: blocks, count, min, max; per block dim tag type n
    double blocks = 0.0, count = 0.0;
    if (!(in >> blocks >> count)) return 0.0;
    std::getline(in, line);
    for (double b = 0; b < blocks; ++b) {
      int dim = 0, tag = 0, type = 0;
      double n = 0.0;
      if (!(in >> dim >> tag >> type >> n) || n < 0) return count;
      std::getline(in, line);
      if (is_tet(type)) tets += n;
      for (double i = 0; i < n; ++i)
        if (!std::getline(in, line)) return count;
    }
    return tets;
  }
  // Binary 4.1: size_t blocks, count, min, max; per block int dim, tag, type, size_t n, then
  // n (1 + nodes) size_t.
  std::uint64_t header[4] = {0, 0, 0, 0};
  if (data_size != 8) return 0.0;
  if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return 0.0;
  const double count = static_cast<double>(header[1]);
  for (std::uint64_t b = 0; b < header[0]; ++b) {
    std::int32_t ints[3] = {0, 0, 0};
    std::uint64_t n = 0;
    if (!in.read(reinterpret_cast<char*>(ints), sizeof ints) ||
        !in.read(reinterpret_cast<char*>(&n), sizeof n))
      return count;
    const int per = msh_nodes_per_element(ints[2]);
    if (per == 0 || n > header[1]) return count;
    if (is_tet(ints[2])) tets += static_cast<double>(n);
    in.seekg(static_cast<std::streamoff>(n * (1 + static_cast<std::uint64_t>(per)) * 8),
             std::ios::cur);
  }
  return in ? tets : count;
}

std::string gigabytes(double bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g GB", bytes / 1e9);
  return buffer;
}

}  // namespace

SizeEstimate estimate_size(const Config& config) {
  SizeEstimate e;
  const MeshConfig& m = config.mesh;
  switch (m.source) {
    case MeshSource::Column: {
      const double nx = m.column.nx, ny = m.column.ny, nz = m.column.nz;
      const double vertices = (nx + 1) * (ny + 1) * (nz + 1);
      const double edges = nx * (ny + 1) * (nz + 1) + (nx + 1) * ny * (nz + 1) +
                           (nx + 1) * (ny + 1) * nz + nx * ny * (nz + 1) + nx * (ny + 1) * nz +
                           (nx + 1) * ny * nz + nx * ny * nz;
      e.tets = 6 * nx * ny * nz;
      e.unknowns = 3 * (vertices + edges) + vertices;
      e.keys = "mesh.column.nx, mesh.column.ny, mesh.column.nz";
      break;
    }
    case MeshSource::QuarterCylinder: {
      const QuarterCylinderSpec& s = m.cylinder;
      if (s.layers > 0) {
        const double area = std::numbers::pi * s.radius * s.radius / 4.0;
        e.tets = 3.0 * area / (0.43 * s.lc * s.lc) * s.layers;
        e.keys = "mesh.radius, mesh.lc, mesh.layers";
      } else {
        double graded = 0.0;
        for (const std::string& face : s.grading_faces) graded += cylinder_face_area(s, face);
        const double volume = std::numbers::pi * s.radius * s.radius * s.height / 4.0;
        e.tets = unstructured_tets(volume, graded, s.lc, s.grading_ratio, s.grading_distance);
        e.keys = "mesh.radius, mesh.height, mesh.lc";
        if (!s.grading_faces.empty() && s.grading_ratio > 1.0)
          e.keys += ", mesh.grading_ratio, mesh.grading_distance";
      }
      e.unknowns = kUnknownsPerTet * e.tets;
      break;
    }
    case MeshSource::SphereOctant: {
      const SphereOctantSpec& s = m.sphere_octant;
      const double volume = std::numbers::pi * s.radius * s.radius * s.radius / 6.0;
      const double surface = std::numbers::pi * s.radius * s.radius / 2.0;
      e.tets = unstructured_tets(volume, surface, s.lc, s.grading_ratio, s.grading_distance);
      e.unknowns = kUnknownsPerTet * e.tets;
      e.keys = "mesh.sphere_octant.radius, mesh.sphere_octant.lc";
      if (s.grading_ratio > 1.0) e.keys += ", mesh.sphere_octant.grading_ratio";
      break;
    }
    case MeshSource::Section: {
      // Triangles, not tetrahedra: 2 unknowns per node and 1 per vertex.
      const double nr = m.section.nr, nz = m.section.nz;
      e.tets = 2 * nr * nz;
      e.unknowns = 2 * (2 * nr + 1) * (2 * nz + 1) + (nr + 1) * (nz + 1);
      e.keys = "mesh.section.nr, mesh.section.nz";
      break;
    }
    case MeshSource::File:
      if (is_two_dimensional(config.model)) {
        // A section mesh: small next to any tetrahedral one; not estimated before reading.
        e.keys = "mesh.file";
        break;
      }
      e.tets = msh_tet_count(m.file);
      e.unknowns = kUnknownsPerTet * e.tets;
      e.keys = "mesh.file";
      break;
  }
  e.bytes = 1e8 + 4e9 * std::pow(e.unknowns / 243'000.0, 4.0 / 3.0);
  return e;
}

std::optional<double> available_memory() {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    double kilobytes = 0.0;
    if (std::sscanf(line.c_str(), "MemAvailable: %lf kB", &kilobytes) == 1)
      return kilobytes * 1024.0;
  }
  return std::nullopt;
}

std::string describe(const SizeEstimate& estimate) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "about %.2g unknowns (%.2g tetrahedra), %s",
                estimate.unknowns, estimate.tets, gigabytes(estimate.bytes).c_str());
  return buffer;
}

void check_size(const Config& config, const std::string& case_path,
                std::optional<double> available) {
  if (!available || config.mesh.ignore_memory_estimate) return;
  const SizeEstimate e = estimate_size(config);
  if (e.bytes <= *available) return;
  throw CaseError({case_path + ": " + e.keys + ": the mesh would have " + describe(e) +
                   " of memory, more than the " + gigabytes(*available) +
                   " available; use a coarser mesh, or set mesh.ignore_memory_estimate = true "
                   "to run anyway"});
}

}  // namespace biphasic
