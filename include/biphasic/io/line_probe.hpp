// Sampling of the solution along a straight line through the mesh, and CSV output of it.
#pragma once

#include <array>
#include <cstddef>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// One sampling point of a probe: its position, its arc length from the probe's start, and
/// the weights that give the fields there, u(x) = Σ w_a u_a over P2 nodes a and
/// p(x) = Σ v_c p_c over vertices c (the element's shape functions at x).
struct ProbeSample {
  double s = 0.0;                                   ///< arc length from the start point [mm]
  Point x{};                                        ///< position [mm]
  std::vector<std::pair<Index, double>> u_weights;  ///< (node, N_a(x))
  std::vector<std::pair<Index, double>> p_weights;  ///< (vertex, N^p_c(x))
};

/// Samples of the solution along a segment a–b, in order of arc length s from a: either the
/// mesh nodes on the segment (the constructor from a mesh), or any points with their
/// interpolation weights (the constructor from samples, see biphasic/app/probes.hpp).
class LineProbe {
 public:
  /// The mesh nodes (vertices and edge nodes) lying on the segment a–b, sorted by s. A node
  /// counts as on the segment if its distance to the segment is at most the tolerance [mm]; s
  /// is its projection on the line through a and b [mm]. Throws std::runtime_error if a == b,
  /// the tolerance is negative or not finite, or fewer than two vertices lie on the segment.
  LineProbe(const Mesh& mesh, Point a, Point b, double tolerance);

  /// The same on a section mesh: its nodes taken at (x, y, 0) (or (r, z, 0)), so a and b
  /// should have z = 0 (a node off the segment by its z does not count).
  LineProbe(const SectionMesh& mesh, Point a, Point b, double tolerance);

  /// Given samples (in order of increasing s) on a mesh of `num_nodes` nodes, the first
  /// `num_vertices` of them vertices. Throws std::runtime_error if a == b, there are fewer than
  /// two samples, s decreases, or a weight names a node (vertex) out of range.
  LineProbe(Point a, Point b, std::vector<ProbeSample> samples, Index num_nodes,
            Index num_vertices);

  std::size_t size() const { return samples_.size(); }
  const std::vector<double>& s() const { return s_; }  ///< arc length from a [mm]
  const ProbeSample& sample(std::size_t i) const { return samples_.at(i); }
  /// Whether the samples are the mesh nodes on the segment (the first constructor).
  bool at_mesh_nodes() const { return at_nodes_; }
  /// Mesh node of sample i when at_mesh_nodes(), else −1.
  Index node(std::size_t i) const;
  /// Whether sample i is a mesh vertex (a node sample at a vertex).
  bool is_vertex(std::size_t i) const;
  const Point& position(std::size_t i) const { return samples_.at(i).x; }  ///< [mm]
  const Point& a() const { return a_; }
  const Point& b() const { return b_; }
  double tolerance() const { return tolerance_; }  ///< [mm] (node samples only)

  /// Pressure [MPa] at every sample from the vertex pressures (size num_vertices): at a node
  /// sample on an edge, the mean of the edge's two vertices.
  std::vector<double> pressure(const std::vector<double>& p_vertices) const;
  /// Displacement [mm] at sample i; `u` is node-major, size 3·num_nodes (a section model's u
  /// expanded with displacement_in_3d, field_writer.hpp).
  std::array<double, 3> displacement(const std::vector<double>& u, std::size_t i) const;

 private:
  /// The node constructors' work, for nodes at `nodes` and edge nodes on `edges`.
  void take_nodes_on_segment(const std::vector<Point>& nodes,
                             const std::vector<std::array<Index, 2>>& edges);

  Point a_{};
  Point b_{};
  double tolerance_ = 0.0;
  Index num_nodes_ = 0;
  Index num_vertices_ = 0;
  bool at_nodes_ = false;
  std::vector<ProbeSample> samples_;
  std::vector<double> s_;
};

/// Whether a node probe (LineProbe from a mesh) covers its whole segment along the mesh:
/// its first and last samples lie at a and b (within the probe's tolerance) and every two
/// consecutive samples are nodes of one element, so that the segment runs along element
/// edges or through elements from node to node.
bool runs_along_mesh(const LineProbe& probe, const Mesh& mesh);

/// The same for a node probe on a section mesh (consecutive samples nodes of one triangle).
bool runs_along_mesh(const LineProbe& probe, const SectionMesh& mesh);

/// Piecewise-linear interpolation of samples f(s) at s_query; s must be non-decreasing and the
/// result is clamped to the end values outside [s.front(), s.back()]. Throws
/// std::runtime_error on empty input, mismatched sizes or decreasing s.
double interpolate_on_line(const std::vector<double>& s, const std::vector<double>& f,
                           double s_query);

/// Long-format CSV of line samples: header `t,s,x,y,z,ux,uy,uz,p` (t in s; s, x, y, z, u in mm;
/// p in MPa) and one row per probe sample and output time, at full (round-trip) precision. The
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
