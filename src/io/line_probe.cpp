#include "biphasic/io/line_probe.hpp"

#include "biphasic/io/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>
#include <system_error>

#include "biphasic/io/field_writer.hpp"

namespace biphasic {

namespace {

std::string fmt_double(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string fmt_point(const Point& x) {
  return "(" + fmt_double(x[0]) + ", " + fmt_double(x[1]) + ", " + fmt_double(x[2]) + ")";
}

double dot(const Point& x, const Point& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }

Point sub(const Point& x, const Point& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }

}  // namespace

LineProbe::LineProbe(const Mesh& mesh, Point a, Point b, double tolerance)
    : a_(a), b_(b), tolerance_(tolerance), num_vertices_(mesh.num_vertices) {
  const std::string where = "LineProbe from " + fmt_point(a) + " to " + fmt_point(b) +
                            " with tolerance " + fmt_double(tolerance) + " mm";
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw std::runtime_error(where + ": tolerance must be finite and non-negative");
  }
  const Point ab = sub(b, a);
  const double length = std::sqrt(dot(ab, ab));
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::runtime_error(where + ": end points must be distinct and finite");
  }
  const std::vector<std::array<Index, 2>> edges = edge_node_vertices(mesh);
  num_nodes_ = mesh.num_nodes();

  struct Hit {
    double s;
    Index node;
  };
  std::vector<Hit> hits;
  Index vertex_hits = 0;
  for (Index n = 0; n < num_nodes_; ++n) {
    const Point& x = mesh.nodes[static_cast<std::size_t>(n)];
    const Point ax = sub(x, a);
    const double s = dot(ax, ab) / length;
    const double s_clamped = std::clamp(s, 0.0, length);
    const Point foot{a[0] + ab[0] * (s_clamped / length), a[1] + ab[1] * (s_clamped / length),
                     a[2] + ab[2] * (s_clamped / length)};
    const Point off = sub(x, foot);
    if (std::sqrt(dot(off, off)) <= tolerance) {
      hits.push_back({s, n});
      if (n < num_vertices_) ++vertex_hits;
    }
  }
  if (vertex_hits < 2) {
    throw std::runtime_error(where + ": " + std::to_string(vertex_hits) +
                             " mesh vertices lie on the segment, need at least 2");
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& l, const Hit& r) {
    return l.s < r.s || (l.s == r.s && l.node < r.node);
  });

  for (const Hit& h : hits) {
    nodes_.push_back(h.node);
    s_.push_back(h.s);
    positions_.push_back(mesh.nodes[static_cast<std::size_t>(h.node)]);
    vertex_pairs_.push_back(h.node < num_vertices_
                                ? std::array<Index, 2>{h.node, h.node}
                                : edges[static_cast<std::size_t>(h.node - num_vertices_)]);
  }
}

std::vector<double> LineProbe::pressure(const std::vector<double>& p_vertices) const {
  if (p_vertices.size() != static_cast<std::size_t>(num_vertices_)) {
    throw std::runtime_error("LineProbe: pressure has " + std::to_string(p_vertices.size()) +
                             " entries, expected " + std::to_string(num_vertices_) +
                             " (one per vertex)");
  }
  std::vector<double> p(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const auto [v0, v1] = vertex_pairs_[i];
    p[i] = v0 == v1 ? p_vertices[static_cast<std::size_t>(v0)]
                    : 0.5 * (p_vertices[static_cast<std::size_t>(v0)] +
                             p_vertices[static_cast<std::size_t>(v1)]);
  }
  return p;
}

std::array<double, 3> LineProbe::displacement(const std::vector<double>& u, std::size_t i) const {
  if (u.size() != 3 * static_cast<std::size_t>(num_nodes_)) {
    throw std::runtime_error("LineProbe: displacement has " + std::to_string(u.size()) +
                             " entries, expected 3 x " + std::to_string(num_nodes_) +
                             " nodes = " + std::to_string(3 * num_nodes_));
  }
  if (i >= nodes_.size()) {
    throw std::runtime_error("LineProbe: probe node " + std::to_string(i) + " out of range (" +
                             std::to_string(nodes_.size()) + " nodes)");
  }
  const auto n = static_cast<std::size_t>(nodes_[i]);
  return {u[3 * n], u[3 * n + 1], u[3 * n + 2]};
}

double interpolate_on_line(const std::vector<double>& s, const std::vector<double>& f,
                           double s_query) {
  if (s.empty() || s.size() != f.size()) {
    throw std::runtime_error("interpolate_on_line: " + std::to_string(s.size()) +
                             " positions and " + std::to_string(f.size()) +
                             " values (need the same non-zero number)");
  }
  if (!std::is_sorted(s.begin(), s.end())) {
    throw std::runtime_error("interpolate_on_line: positions are not in increasing order");
  }
  if (s_query <= s.front()) return f.front();
  if (s_query >= s.back()) return f.back();
  // s[k] <= s_query < s[k + 1], so the interval has positive length.
  const auto k =
      static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), s_query) - s.begin()) - 1;
  const double w = (s_query - s[k]) / (s[k + 1] - s[k]);
  return (1.0 - w) * f[k] + w * f[k + 1];
}

LineCsvWriter::LineCsvWriter(const std::string& path, bool append) : path_(path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec) {
      throw std::runtime_error("LineCsvWriter: cannot create folder " + parent.string() + " for " +
                               path + ": " + ec.message());
    }
  }
  out_.open(path, std::ios::out | (append ? std::ios::app : std::ios::trunc));
  if (!out_) throw std::runtime_error("LineCsvWriter: cannot open " + path);
  if (!append) out_ << "t,s,x,y,z,ux,uy,uz,p\n";
  flush_checked(out_, path);
}

void LineCsvWriter::write(double t, const LineProbe& probe, const std::vector<double>& u,
                          const std::vector<double>& p_vertices) {
  const std::vector<double> p = probe.pressure(p_vertices);
  std::string rows;
  const std::string time = fmt_double(t);
  for (std::size_t i = 0; i < probe.size(); ++i) {
    const Point& x = probe.position(i);
    const std::array<double, 3> d = probe.displacement(u, i);
    rows += time;
    for (double v : {probe.s()[i], x[0], x[1], x[2], d[0], d[1], d[2], p[i]}) {
      rows += ',';
      rows += fmt_double(v);
    }
    rows += '\n';
  }
  out_ << rows;
  flush_checked(out_, path_);
}

}  // namespace biphasic
