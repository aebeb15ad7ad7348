#include "biphasic/io/line_probe.hpp"

#include "biphasic/io/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
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
    : a_(a),
      b_(b),
      tolerance_(tolerance),
      num_nodes_(mesh.num_nodes()),
      num_vertices_(mesh.num_vertices),
      at_nodes_(true) {
  take_nodes_on_segment(mesh.nodes, edge_node_vertices(mesh));
}

LineProbe::LineProbe(const SectionMesh& mesh, Point a, Point b, double tolerance)
    : a_(a),
      b_(b),
      tolerance_(tolerance),
      num_nodes_(mesh.num_nodes()),
      num_vertices_(mesh.num_vertices),
      at_nodes_(true) {
  std::vector<Point> nodes;
  nodes.reserve(mesh.nodes.size());
  for (const Point2& x : mesh.nodes) nodes.push_back({x[0], x[1], 0.0});
  take_nodes_on_segment(nodes, edge_node_vertices(mesh));
}

void LineProbe::take_nodes_on_segment(const std::vector<Point>& nodes,
                                      const std::vector<std::array<Index, 2>>& edges) {
  const Point a = a_;
  const Point b = b_;
  const double tolerance = tolerance_;
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

  struct Hit {
    double s;
    Index node;
  };
  std::vector<Hit> hits;
  Index vertex_hits = 0;
  for (Index n = 0; n < num_nodes_; ++n) {
    const Point& x = nodes[static_cast<std::size_t>(n)];
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
    ProbeSample sample;
    sample.s = h.s;
    sample.x = nodes[static_cast<std::size_t>(h.node)];
    sample.u_weights = {{h.node, 1.0}};
    if (h.node < num_vertices_) {
      sample.p_weights = {{h.node, 1.0}};
    } else {
      const auto [v0, v1] = edges[static_cast<std::size_t>(h.node - num_vertices_)];
      sample.p_weights = {{v0, 0.5}, {v1, 0.5}};
    }
    s_.push_back(h.s);
    samples_.push_back(std::move(sample));
  }
}

LineProbe::LineProbe(Point a, Point b, std::vector<ProbeSample> samples, Index num_nodes,
                     Index num_vertices)
    : a_(a),
      b_(b),
      num_nodes_(num_nodes),
      num_vertices_(num_vertices),
      samples_(std::move(samples)) {
  const std::string where = "LineProbe from " + fmt_point(a) + " to " + fmt_point(b);
  const Point ab = sub(b, a);
  const double length = std::sqrt(dot(ab, ab));
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::runtime_error(where + ": end points must be distinct and finite");
  }
  if (samples_.size() < 2) {
    throw std::runtime_error(where + ": " + std::to_string(samples_.size()) +
                             " samples, need at least 2");
  }
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const ProbeSample& sample = samples_[i];
    if (i > 0 && !(sample.s >= samples_[i - 1].s)) {
      throw std::runtime_error(where + ": sample " + std::to_string(i) + " at s = " +
                               fmt_double(sample.s) + " mm comes before the previous one");
    }
    auto check = [&](const std::vector<std::pair<Index, double>>& weights, Index count,
                     const char* what) {
      if (weights.empty())
        throw std::runtime_error(where + ": sample " + std::to_string(i) + " has no " + what +
                                 " weights");
      for (const auto& [n, w] : weights) {
        if (n < 0 || n >= count)
          throw std::runtime_error(where + ": sample " + std::to_string(i) + " weighs " + what +
                                   " " + std::to_string(n) + ", out of range (" +
                                   std::to_string(count) + ")");
      }
    };
    check(sample.u_weights, num_nodes_, "node");
    check(sample.p_weights, num_vertices_, "vertex");
    s_.push_back(sample.s);
  }
}

Index LineProbe::node(std::size_t i) const {
  const ProbeSample& sample = samples_.at(i);
  return at_nodes_ ? sample.u_weights.front().first : Index{-1};
}

bool LineProbe::is_vertex(std::size_t i) const {
  const Index n = node(i);
  return n >= 0 && n < num_vertices_;
}

namespace {
/// Σ w f over the weights, starting from the first term so that a single weight 1 returns the
/// value itself bit for bit (signed zeros included).
double weighted_sum(const std::vector<std::pair<Index, double>>& weights,
                    const std::vector<double>& f, std::size_t stride, std::size_t offset) {
  double sum =
      weights.front().second * f[stride * static_cast<std::size_t>(weights.front().first) + offset];
  for (std::size_t k = 1; k < weights.size(); ++k)
    sum += weights[k].second * f[stride * static_cast<std::size_t>(weights[k].first) + offset];
  return sum;
}
}  // namespace

std::vector<double> LineProbe::pressure(const std::vector<double>& p_vertices) const {
  if (p_vertices.size() != static_cast<std::size_t>(num_vertices_)) {
    throw std::runtime_error("LineProbe: pressure has " + std::to_string(p_vertices.size()) +
                             " entries, expected " + std::to_string(num_vertices_) +
                             " (one per vertex)");
  }
  std::vector<double> p(samples_.size());
  for (std::size_t i = 0; i < samples_.size(); ++i)
    p[i] = weighted_sum(samples_[i].p_weights, p_vertices, 1, 0);
  return p;
}

std::array<double, 3> LineProbe::displacement(const std::vector<double>& u, std::size_t i) const {
  if (u.size() != 3 * static_cast<std::size_t>(num_nodes_)) {
    throw std::runtime_error("LineProbe: displacement has " + std::to_string(u.size()) +
                             " entries, expected 3 x " + std::to_string(num_nodes_) +
                             " nodes = " + std::to_string(3 * num_nodes_));
  }
  if (i >= samples_.size()) {
    throw std::runtime_error("LineProbe: probe sample " + std::to_string(i) + " out of range (" +
                             std::to_string(samples_.size()) + " samples)");
  }
  const auto& w = samples_[i].u_weights;
  return {weighted_sum(w, u, 3, 0), weighted_sum(w, u, 3, 1), weighted_sum(w, u, 3, 2)};
}

namespace {

/// runs_along_mesh over any list of elements (each a list of node indices).
template <class Elements>
bool runs_along_elements(const LineProbe& probe, Index num_nodes, const Elements& elements) {
  if (!probe.at_mesh_nodes() || probe.size() < 2) return false;
  const Point ab = sub(probe.b(), probe.a());
  const double length = std::sqrt(dot(ab, ab));
  const double tol = probe.tolerance();
  if (std::abs(probe.s().front()) > tol || std::abs(probe.s().back() - length) > tol) return false;
  // Elements of each probe node, then a common one for every consecutive pair.
  std::vector<std::size_t> sample_of(static_cast<std::size_t>(num_nodes), SIZE_MAX);
  for (std::size_t i = 0; i < probe.size(); ++i)
    sample_of[static_cast<std::size_t>(probe.node(i))] = i;
  std::vector<std::vector<Index>> tets_of(probe.size());
  for (std::size_t t = 0; t < elements.size(); ++t) {
    for (Index n : elements[t]) {
      const std::size_t i = sample_of[static_cast<std::size_t>(n)];
      if (i != SIZE_MAX) tets_of[i].push_back(static_cast<Index>(t));
    }
  }
  for (std::size_t i = 0; i + 1 < probe.size(); ++i) {
    const auto& l = tets_of[i];
    const auto& r = tets_of[i + 1];
    // Both lists are in increasing element order.
    std::vector<Index> common;
    std::set_intersection(l.begin(), l.end(), r.begin(), r.end(), std::back_inserter(common));
    if (common.empty()) return false;
  }
  return true;
}

}  // namespace

bool runs_along_mesh(const LineProbe& probe, const Mesh& mesh) {
  return runs_along_elements(probe, mesh.num_nodes(), mesh.tets);
}

bool runs_along_mesh(const LineProbe& probe, const SectionMesh& mesh) {
  return runs_along_elements(probe, mesh.num_nodes(), mesh.triangles);
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
