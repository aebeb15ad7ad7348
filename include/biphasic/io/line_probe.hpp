// Sampling of the nodal fields along a straight line through the mesh, and CSV output of it.
#pragma once

#include <array>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// The mesh nodes (vertices and edge nodes) lying on the segment a–b, sorted by arc length s
/// from a. A node counts as on the segment if its distance to the segment is at most the
/// tolerance [mm]; s is its projection on the line through a and b [mm].
class LineProbe {
 public:
  /// Throws std::runtime_error if a == b, the tolerance is negative or not finite, the mesh is
  /// inconsistent, or fewer than two vertices lie on the segment.
  LineProbe(const Mesh& mesh, Point a, Point b, double tolerance);

  std::size_t size() const { return nodes_.size(); }
  const std::vector<double>& s() const { return s_; }       ///< arc length from a [mm]
  Index node(std::size_t i) const { return nodes_.at(i); }  ///< mesh node index
  bool is_vertex(std::size_t i) const { return node(i) < num_vertices_; }
  const Point& position(std::size_t i) const { return positions_.at(i); }  ///< [mm]
  const Point& a() const { return a_; }
  const Point& b() const { return b_; }
  double tolerance() const { return tolerance_; }  ///< [mm]

  /// Pressure [MPa] at every probe node from the vertex pressures (size num_vertices); an edge
  /// node gets the mean of its edge's two vertices.
  std::vector<double> pressure(const std::vector<double>& p_vertices) const;
  /// Displacement [mm] of probe node i; `u` is node-major, size 3·num_nodes.
  std::array<double, 3> displacement(const std::vector<double>& u, std::size_t i) const;

 private:
  Point a_{};
  Point b_{};
  double tolerance_ = 0.0;
  Index num_nodes_ = 0;
  Index num_vertices_ = 0;
  std::vector<Index> nodes_;
  std::vector<double> s_;
  std::vector<Point> positions_;
  std::vector<std::array<Index, 2>> vertex_pairs_;  ///< {n, n} for a vertex, its edge otherwise
};

/// Piecewise-linear interpolation of samples f(s) at s_query; s must be non-decreasing and the
/// result is clamped to the end values outside [s.front(), s.back()]. Throws
/// std::runtime_error on empty input, mismatched sizes or decreasing s.
double interpolate_on_line(const std::vector<double>& s, const std::vector<double>& f,
                           double s_query);

/// Long-format CSV of line samples: header `t,s,x,y,z,ux,uy,uz,p` (t in s; s, x, y, z, u in mm;
/// p in MPa) and one row per probe node and output time, at full (round-trip) precision. The
/// file is flushed after every write so that it survives a crash.
class LineCsvWriter {
 public:
  /// Creates (or truncates) the file, creating its folder if needed, and writes the header;
  /// with `append`, keeps the rows already in the file (a restarted run) and writes no header.
  explicit LineCsvWriter(const std::string& path, bool append = false);

  void write(double t, const LineProbe& probe, const std::vector<double>& u,
             const std::vector<double>& p_vertices);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace biphasic
