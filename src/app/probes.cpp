#include "biphasic/app/probes.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "biphasic/app/run.hpp"
#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/field_writer.hpp"
#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

namespace {

std::string number(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string point_text(const Point& x) {
  return "(" + number(x[0]) + ", " + number(x[1]) + ", " + number(x[2]) + ")";
}

/// Round-off allowance for points on the body's surface: 1e-6 of the mesh's extent [mm].
template <class Locator>
double surface_tolerance(const Locator& locator) {
  return 1e-6 * std::max(locator.diagonal(), 1.0);
}

/// A probe from a to b sampled as `points` asks (0: mesh nodes when the line runs along the
/// mesh, else kDefaultProbePoints; n: n points); `where` prefixes errors.
template <class AnyMesh, class Locator>
LineProbe sample_line(const AnyMesh& mesh, const Locator& locator, const Point& a, const Point& b,
                      int points, const std::string& where) {
  if (points == 0) {
    // The tolerance of the node search is the one the probe line always had.
    const double length = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    try {
      LineProbe nodes(mesh, a, b, 1e-6 * std::max(length, 1.0));
      if (runs_along_mesh(nodes, mesh)) return nodes;
    } catch (const std::runtime_error&) {
      // fewer than two vertices on the line: interpolate
    }
    points = kDefaultProbePoints;
  }
  try {
    return interpolating_probe(mesh, locator, a, b, points, surface_tolerance(locator));
  } catch (const std::out_of_range& e) {
    throw CaseError({where + ": " + e.what()});
  }
}

}  // namespace

LineProbe interpolating_probe(const Mesh& mesh, const PointLocator& locator, const Point& a,
                              const Point& b, int n, double tolerance) {
  if (n < 2) throw std::invalid_argument("interpolating_probe: needs at least 2 points");
  const double length = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  std::vector<ProbeSample> samples;
  std::size_t outside = 0;
  std::string first_outside;
  for (int i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / (n - 1);
    ProbeSample sample;
    sample.s = i == n - 1 ? length : f * length;
    for (int d = 0; d < 3; ++d) sample.x[d] = i == n - 1 ? b[d] : a[d] + f * (b[d] - a[d]);
    const std::optional<PointLocation> loc = locator.locate(sample.x, tolerance);
    if (!loc) {
      if (outside++ == 0) {
        first_outside = "point " + std::to_string(i + 1) + " of " + std::to_string(n) + " at " +
                        point_text(sample.x) + " mm";
        // How far out, when it is close (a point meant to be on a curved face, say).
        const auto near = locator.locate(sample.x, 0.01 * locator.diagonal());
        if (near) first_outside += " (about " + number(near->distance_outside) + " mm outside)";
      }
      continue;
    }
    const Tet10& tet = mesh.tets[static_cast<std::size_t>(loc->tet)];
    const Eigen::Matrix<double, 10, 1> N = p2_values(loc->xi);
    const Eigen::Vector4d L = p1_values(loc->xi);
    for (int k = 0; k < 10; ++k) sample.u_weights.emplace_back(tet[k], N(k));
    for (int k = 0; k < 4; ++k) sample.p_weights.emplace_back(tet[k], L(k));
    samples.push_back(std::move(sample));
  }
  if (outside > 0) {
    throw std::out_of_range(
        first_outside + " lies outside the body" +
        (outside > 1 ? " (" + std::to_string(outside) + " of the points do)" : std::string{}) +
        "; the body is the mesh, its curved faces as the quadratic elements describe them "
        "(they depart from a true curved surface between nodes: move such points inward)");
  }
  return LineProbe(a, b, std::move(samples), mesh.num_nodes(), mesh.num_vertices);
}

LineProbe interpolating_probe(const SectionMesh& mesh, const SectionPointLocator& locator,
                              const Point& a, const Point& b, int n, double tolerance) {
  if (n < 2) throw std::invalid_argument("interpolating_probe: needs at least 2 points");
  const double length = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  std::vector<ProbeSample> samples;
  std::size_t outside = 0;
  std::string first_outside;
  for (int i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / (n - 1);
    ProbeSample sample;
    sample.s = i == n - 1 ? length : f * length;
    for (int d = 0; d < 3; ++d) sample.x[d] = i == n - 1 ? b[d] : a[d] + f * (b[d] - a[d]);
    const Point2 x2{sample.x[0], sample.x[1]};
    const std::optional<SectionPointLocation> loc = locator.locate(x2, tolerance);
    if (!loc) {
      if (outside++ == 0) {
        first_outside = "point " + std::to_string(i + 1) + " of " + std::to_string(n) + " at " +
                        point_text(sample.x) + " mm";
        const auto near = locator.locate(x2, 0.01 * locator.diagonal());
        if (near) first_outside += " (about " + number(near->distance_outside) + " mm outside)";
      }
      continue;
    }
    const Tri6& tri = mesh.triangles[static_cast<std::size_t>(loc->triangle)];
    const Eigen::Matrix<double, 6, 1> N = tri6_values(loc->eta);
    const Eigen::Vector3d L = tri3_values(loc->eta);
    for (int k = 0; k < 6; ++k) sample.u_weights.emplace_back(tri[k], N(k));
    for (int k = 0; k < 3; ++k) sample.p_weights.emplace_back(tri[k], L(k));
    samples.push_back(std::move(sample));
  }
  if (outside > 0) {
    throw std::out_of_range(
        first_outside + " lies outside the section" +
        (outside > 1 ? " (" + std::to_string(outside) + " of the points do)" : std::string{}) +
        "; the section is the mesh, its curved edges as the quadratic triangles describe them "
        "(move points on a curved boundary inward)");
  }
  return LineProbe(a, b, std::move(samples), mesh.num_nodes(), mesh.num_vertices);
}

namespace {

template <class AnyMesh>
struct LocatorOf {
  using type = PointLocator;
};
template <>
struct LocatorOf<SectionMesh> {
  using type = SectionPointLocator;
};

/// build_probes on either kind of mesh; a section's probe points must have z = 0.
template <class AnyMesh>
std::vector<Probe> build_probes_on(const Config& config, const AnyMesh& mesh) {
  constexpr bool section = std::is_same_v<AnyMesh, SectionMesh>;
  const OutputConfig& out = config.output;
  if (!out.line && out.probes.empty()) return {};
  const typename LocatorOf<AnyMesh>::type locator(mesh);
  const std::string source = config.case_file.empty() ? std::string{} : config.case_file + ": ";
  std::vector<Probe> probes;
  std::vector<std::string> problems;
  auto add = [&](std::string name, std::string key, std::string file, const Point& a,
                 const Point& b, int points, bool measured, const std::string& start_key,
                 const std::string& end_key) {
    if constexpr (section) {
      bool in_plane = true;
      for (const auto& [x, x_key] : {std::pair{a, start_key}, std::pair{b, end_key}}) {
        if (x[2] != 0.0) {
          in_plane = false;
          problems.push_back(source + key + ": " + x_key + " = " + point_text(x) +
                             " mm has z = " + number(x[2]) +
                             "; a probe of a two-dimensional model lies in its section, z = 0 "
                             "(points (x, y, 0) or (r, z, 0))");
        }
      }
      if (!in_plane) return;
    }
    try {
      probes.push_back(Probe{std::move(name), key, std::move(file),
                             sample_line(mesh, locator, a, b, points, source + key), measured});
    } catch (const CaseError& e) {
      problems.insert(problems.end(), e.problems().begin(), e.problems().end());
    }
  };
  if (out.line)
    add("line", "output.line_start .. output.line_end", "line.csv", out.line_start, out.line_end,
        out.line_points, true, "output.line_start", "output.line_end");
  for (std::size_t i = 0; i < out.probes.size(); ++i) {
    const ProbeConfig& p = out.probes[i];
    const std::string index = "probe[" + std::to_string(i) + "]";
    add(p.name, index + " \"" + p.name + "\"", "probe_" + p.name + ".csv", p.start, p.end, p.points,
        false, index + ".start", index + ".end");
  }
  if (!problems.empty()) throw CaseError(std::move(problems));
  return probes;
}

std::vector<std::string> describe_probes(const std::vector<Probe>& probes) {
  std::vector<std::string> lines;
  for (const Probe& probe : probes) {
    const LineProbe& s = probe.samples;
    lines.push_back(
        (probe.measured ? std::string("probe line") : "probe \"" + probe.name + "\"") + " from " +
        point_text(s.a()) + " to " + point_text(s.b()) + " mm: " + std::to_string(s.size()) +
        (s.at_mesh_nodes() ? " mesh nodes" : " interpolated points") + " -> " + probe.file);
  }
  return lines;
}

}  // namespace

std::vector<Probe> build_probes(const Config& config, const Mesh& mesh) {
  return build_probes_on(config, mesh);
}

std::vector<std::string> check_probes(const Config& config, const Mesh& mesh) {
  return describe_probes(build_probes(config, mesh));
}

std::vector<Probe> build_section_probes(const Config& config, const SectionMesh& mesh) {
  return build_probes_on(config, mesh);
}

std::vector<std::string> check_section_probes(const Config& config, const SectionMesh& mesh) {
  return describe_probes(build_section_probes(config, mesh));
}

ProbeRecorder::ProbeRecorder(std::vector<Probe> probes, const SemidiscreteSystem& problem,
                             const std::string& output_dir, std::optional<double> resume_t)
    : ProbeRecorder(std::move(probes), problem.constrained(), problem.pattern().p_dof(0),
                    output_dir, resume_t) {}

ProbeRecorder::ProbeRecorder(std::vector<Probe> probes, const std::vector<char>& constrained,
                             Index first_pressure, const std::string& output_dir,
                             std::optional<double> resume_t)
    : probes_(std::move(probes)) {
  for (const Probe& probe : probes_) {
    const std::string path = (std::filesystem::path(output_dir) / probe.file).string();
    if (resume_t) keep_csv_rows_until(path, *resume_t);
    writers_.push_back(std::make_unique<LineCsvWriter>(path, resume_t.has_value()));
    if (probe.measured) drained_ = drained_ends(probe.samples, constrained, first_pressure);
  }
}

ProbeRecorder::~ProbeRecorder() = default;

void ProbeRecorder::describe(nlohmann::json& summary) const {
  auto block = [](const Probe& probe) {
    const LineProbe& s = probe.samples;
    nlohmann::json j{{"start", s.a()},
                     {"end", s.b()},
                     {"file", probe.file},
                     {"sampling", s.at_mesh_nodes() ? "mesh nodes" : "interpolated points"},
                     {"points", s.size()}};
    if (s.at_mesh_nodes()) j["nodes"] = s.size();
    return j;
  };
  summary["line"] = {{"enabled", false},
                     {"note", "output.line = false: no probe line, no line.csv, no measures"}};
  nlohmann::json named = nlohmann::json::array();
  for (const Probe& probe : probes_) {
    if (probe.measured) {
      summary["line"] = block(probe);
      summary["line"]["enabled"] = true;
      summary["line"]["drained_ends"] = to_string(drained_);
    } else {
      nlohmann::json j = block(probe);
      j["name"] = probe.name;
      named.push_back(j);
    }
  }
  if (!named.empty()) summary["probes"] = named;
}

std::optional<LineMeasures> ProbeRecorder::write(double t, const std::vector<double>& u,
                                                 const std::vector<double>& p) {
  std::optional<LineMeasures> measures;
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    const LineProbe& samples = probes_[i].samples;
    writers_[i]->write(t, samples, u, p);
    if (probes_[i].measured) measures = line_measures(samples.s(), samples.pressure(p), drained_);
  }
  return measures;
}

}  // namespace biphasic
