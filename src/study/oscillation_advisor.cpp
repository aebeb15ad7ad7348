#include "biphasic/study/oscillation_advisor.hpp"

#include "biphasic/material/material_laws.hpp"
#include "biphasic/physics/stabilisation/stabilisations.hpp"
#include "biphasic/time/time_integrator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace biphasic {

namespace {

using FaceKey = std::array<Index, 3>;

FaceKey sorted_key(Index a, Index b, Index c) {
  FaceKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

double triangle_area(const Point& a, const Point& b, const Point& c) {
  const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const std::array<double, 3> v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                          u[0] * v[1] - u[1] * v[0]);
}

std::string fmt(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

/// First time after 0 where a boundary condition's load curve has a kink, else t_end: IDA's
/// first stop time (src/time/bdf_integrator.cpp).
double first_stop(const Config& config) {
  const double t_end = config.time.t_end;
  double stop = t_end;
  for (const auto& bc : config.bcs) {
    if (bc.curve.empty()) continue;
    const auto curve = config.curves.find(bc.curve);
    if (curve == config.curves.end()) continue;
    for (double k : curve->second.kinks())
      if (k > 1e-12 * std::max(1.0, t_end) && k < stop) stop = k;
  }
  return stop;
}

}  // namespace

std::vector<double> heights_over_boundary(const Mesh& mesh, const std::string& boundary) {
  std::vector<double> heights;
  for (const auto& [tet, h] : tetrahedra_over_boundary(mesh, boundary)) heights.push_back(h);
  return heights;
}

std::vector<std::pair<Index, double>> tetrahedra_over_boundary(const Mesh& mesh,
                                                               const std::string& boundary) {
  const Boundary* b = mesh.find_boundary(boundary);
  if (!b) throw std::runtime_error("oscillation advisor: no boundary named '" + boundary + "'");
  std::map<FaceKey, std::size_t> faces;  // corner triple → index in b->faces
  for (std::size_t f = 0; f < b->faces.size(); ++f)
    faces.emplace(sorted_key(b->faces[f][0], b->faces[f][1], b->faces[f][2]), f);
  std::vector<char> found(b->faces.size(), 0);
  std::vector<std::pair<Index, double>> heights;
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet10& t = mesh.tets[e];
    double h = -1.0;
    for (int opposite = 0; opposite < 4; ++opposite) {
      std::array<Index, 3> c{};
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != opposite) c[j++] = t[i];
      const auto it = faces.find(sorted_key(c[0], c[1], c[2]));
      if (it == faces.end()) continue;
      found[it->second] = 1;
      // h = 3V/A: the distance of the opposite corner from the face's plane.
      const double volume = std::abs(tet_signed_volume(mesh.nodes[t[0]], mesh.nodes[t[1]],
                                                       mesh.nodes[t[2]], mesh.nodes[t[3]]));
      const double area = triangle_area(mesh.nodes[c[0]], mesh.nodes[c[1]], mesh.nodes[c[2]]);
      const double height = 3.0 * volume / area;
      h = h < 0.0 ? height : std::min(h, height);
    }
    if (h >= 0.0) heights.emplace_back(static_cast<Index>(e), h);
  }
  for (std::size_t f = 0; f < found.size(); ++f)
    if (!found[f])
      throw std::runtime_error("oscillation advisor: face " + std::to_string(f) + " of boundary '" +
                               boundary + "' belongs to no tetrahedron");
  return heights;
}

OscillationAdvice advise_oscillation(const Mesh& mesh, const Config& config) {
  OscillationAdvice advice;
  const MaterialLaws laws = make_material_laws(config.material);
  const double c = laws.reference_permeability() * laws.p_wave_modulus();
  advice.consolidation_coefficient = c;
  advice.bdf = uses_ida(config.time.integrator);
  advice.stabilisation = config.stabilisation.type;
  if (!advice.bdf) {
    advice.first_step = std::min(config.time.dt, config.time.t_end);
    advice.first_step_source = "time.dt";
  } else if (config.time.bdf.initial_step > 0.0) {
    advice.first_step = config.time.bdf.initial_step;
    advice.first_step_source = "time.bdf.initial_step";
  } else {
    advice.first_step = default_first_step(config.time.dt, first_stop(config));
    advice.first_step_source =
        "IDA's default first step, 1 % of the first output interval or of the time to the first "
        "load-curve kink";
  }
  const double dt = advice.first_step;
  const bool stabilised =
      !std::holds_alternative<NoStabilisation>(make_stabilisation(config.stabilisation.type));

  // c per mesh region: its [[region]] entry's material, else [material].
  std::vector<double> region_c(std::max<std::size_t>(1, mesh.region_names.size()), c);
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r)
    for (const RegionConfig& entry : config.regions)
      if (entry.name == mesh.region_names[r]) {
        const MaterialLaws own = make_material_laws(entry.material);
        region_c[r] = own.reference_permeability() * own.p_wave_modulus();
      }

  std::set<std::string> seen;
  for (const auto& bc : config.bcs) {
    if (bc.type != BcType::Pressure || !seen.insert(bc.boundary).second) continue;
    const auto over = tetrahedra_over_boundary(mesh, bc.boundary);
    if (over.empty()) continue;
    std::vector<double> h;
    double c_face = std::numeric_limits<double>::infinity();
    for (const auto& [tet, height] : over) {
      h.push_back(height);
      c_face = std::min(c_face, region_c[static_cast<std::size_t>(mesh.region_of(tet))]);
    }
    std::sort(h.begin(), h.end());
    DrainedFaceAdvice face;
    face.face = bc.boundary;
    face.consolidation_coefficient = c_face;
    face.elements = static_cast<long>(h.size());
    face.h_min = h.front();
    face.h_median = h[h.size() / 2];
    face.h_max = h.back();
    face.r_min = c_face * dt / (face.h_max * face.h_max);
    face.r_median = c_face * dt / (face.h_median * face.h_median);
    face.in_regime = face.r_min < face.threshold;
    if (face.in_regime) {
      if (stabilised) {
        face.advice.push_back("stabilisation \"" + advice.stabilisation +
                              "\" is on: it damps the first-step overshoot");
      } else {
        face.advice.push_back("stabilisation.type = \"gls\" (or \"flux_perturbation\")");
        if (advice.bdf) {
          face.advice.push_back(
              "BDF's first steps are small (it starts at 1 % of the first output interval unless "
              "time.bdf.initial_step is set), so its start is in the oscillation regime whatever "
              "time.dt");
        } else {
          face.advice.push_back(
              "time.dt >= " + fmt("%.3g", face.threshold * face.h_max * face.h_max / c_face) +
              " s");
          face.advice.push_back("a first-layer thickness h <= " +
                                fmt("%.3g", std::sqrt(c_face * dt / face.threshold)) + " mm at '" +
                                face.face + "' (grade the mesh toward it)");
        }
      }
    }
    advice.faces.push_back(std::move(face));
  }
  return advice;
}

nlohmann::json to_json(const OscillationAdvice& advice) {
  nlohmann::json faces = nlohmann::json::object();
  for (const auto& f : advice.faces)
    faces[f.face] = {{"consolidation_coefficient", f.consolidation_coefficient},
                     {"elements", f.elements},
                     {"h_min", f.h_min},
                     {"h_median", f.h_median},
                     {"h_max", f.h_max},
                     {"r_min", f.r_min},
                     {"r_median", f.r_median},
                     {"threshold", f.threshold},
                     {"in_regime", f.in_regime},
                     {"advice", f.advice}};
  return {{"consolidation_coefficient", advice.consolidation_coefficient},
          {"first_step", advice.first_step},
          {"first_step_source", advice.first_step_source},
          {"h", "height of each tetrahedron over its face on the drained boundary, 3V/A [mm]"},
          {"stabilisation", advice.stabilisation},
          {"faces", faces}};
}

std::vector<std::string> advice_lines(const OscillationAdvice& advice) {
  std::vector<std::string> lines;
  for (const auto& f : advice.faces) {
    char buf[320];
    std::snprintf(
        buf, sizeof buf,
        "advisor: drained face '%s': %ld elements, h_max %.3g mm, %s %.3g s: r = c dt/h^2 "
        "min %.3g, median %.3g %s threshold %.3g: %s",
        f.face.c_str(), f.elements, f.h_max, advice.bdf ? "BDF's first step <=" : "dt",
        advice.first_step, f.r_min, f.r_median, f.in_regime ? "<" : ">=", f.threshold,
        f.in_regime ? "first-step pressure overshoot expected"
                    : "no first-step overshoot expected");
    lines.emplace_back(buf);
    if (!f.in_regime) continue;
    std::string remedy = "  ";
    if (advice.stabilisation != "none") {
      remedy += f.advice.front();
    } else {
      remedy += "avoid it with " + f.advice.front();
      for (std::size_t i = 1; i < f.advice.size(); ++i)
        remedy += (advice.bdf ? "; " : (i + 1 == f.advice.size() ? ", or " : ", ")) + f.advice[i];
    }
    lines.push_back(remedy);
  }
  return lines;
}

}  // namespace biphasic
