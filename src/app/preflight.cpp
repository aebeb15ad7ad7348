// The checks before the first step (see preflight.hpp and docs/constraints.md). Each check
// adds its problems to one list, so that a case is refused with everything wrong in it.
#include "biphasic/app/preflight.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "biphasic/app/probes.hpp"
#include "biphasic/app/run.hpp"
#include "biphasic/fe/quadrature.hpp"
#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/mesh/coincident_nodes.hpp"
#include "biphasic/mesh/constraint_analysis.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string point_text(const Point& x) {
  return "(" + number(x[0]) + ", " + number(x[1]) + ", " + number(x[2]) + ")";
}

const char* axis_name(int c) { return c == 0 ? "x" : c == 1 ? "y" : "z"; }

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

/// "boundary[2] (displacement z on 'top')".
std::string label(std::size_t i, const BoundaryCondition& bc) {
  std::string what = to_string(bc.type);
  if (bc.type == BcType::Displacement || bc.type == BcType::RigidPlaten)
    what += std::string(" ") + axis_name(bc.component);
  return "boundary[" + std::to_string(i) + "] (" + what + " on '" + bc.boundary + "')";
}

/// What a condition prescribes on an unknown: value · curve(t); equal when both vanish or both
/// scale the same curve by the same value.
struct Prescribed {
  std::size_t bc;
  double value;
  std::string curve;
  bool same_as(const Prescribed& o) const {
    return (value == 0.0 && o.value == 0.0) || (value == o.value && curve == o.curve);
  }
};

class Preflight {
 public:
  Preflight(const Config& config, const Mesh& mesh)
      : config_(config),
        mesh_(mesh),
        source_(config.case_file.empty() ? "case" : config.case_file) {}

  std::vector<std::string> run() {
    check_names();
    check_region_names();
    check_symmetry_planes();
    check_conflicts();
    check_formulas();
    check_coincident_nodes();
    check_rigid_modes();
    if (!problems_.empty()) throw CaseError(std::move(problems_));
    return std::move(notes_);
  }

 private:
  void problem(const std::string& text) { problems_.push_back(source_ + ": " + text); }

  /// The mesh as messages name it.
  std::string mesh_name() const {
    switch (config_.mesh.source) {
      case MeshSource::File:
        return "the mesh (mesh.file = " + quoted(config_.mesh.file) + ")";
      case MeshSource::Column:
        return "the generated column mesh";
      case MeshSource::SphereOctant:
        return "the generated sphere-octant mesh";
      case MeshSource::Section:
        return "the generated section mesh";
      case MeshSource::QuarterCylinder:
        break;
    }
    return "the generated quarter-cylinder mesh";
  }

  std::string available_names() const {
    std::vector<std::string> sets;
    for (const NodeSet& s : mesh_.node_sets) sets.push_back(s.name);
    std::string out = mesh_.boundaries.empty()
                          ? "the mesh has no named boundaries"
                          : "mesh boundaries: " + join(mesh_.boundary_names(), ", ");
    if (!sets.empty()) out += "; points and curves: " + join(sets, ", ");
    return out;
  }

  // ---- names ----------------------------------------------------------------------------

  /// Every [[region]] entry names a region of the mesh (mesh regions without an entry use
  /// [material]).
  void check_region_names() {
    std::vector<std::string> shown;
    for (const std::string& name : mesh_.region_names) shown.push_back(quoted(name));
    for (std::size_t i = 0; i < config_.regions.size(); ++i) {
      const std::string& name = config_.regions[i].name;
      if (mesh_.find_region(name) >= 0) continue;
      problem("region[" + std::to_string(i) + "].name = " + quoted(name) + ": no such region in " +
              mesh_name() + " (" +
              (shown.empty() ? std::string("it has no regions")
                             : "mesh regions: " + join(shown, ", ")) +
              ")");
    }
  }

  void check_names() {
    usable_.assign(config_.bcs.size(), false);
    for (std::size_t i = 0; i < config_.bcs.size(); ++i) {
      const BoundaryCondition& bc = config_.bcs[i];
      const std::string key = "boundary[" + std::to_string(i) + "].name = " + quoted(bc.boundary);
      const Boundary* b = mesh_.find_boundary(bc.boundary);
      const NodeSet* set = mesh_.find_node_set(bc.boundary);
      if (!b && !set) {
        problem(key + ": no such boundary in the mesh (" + available_names() + ")");
      } else if (b && set) {
        problem(key + ": both a physical surface and a physical " +
                (set->dimension == 0 ? "point" : "curve") +
                " of the mesh have this name; rename one in the mesh file");
      } else if (set && bc.type != BcType::Displacement) {
        problem(key + ": a physical " + (set->dimension == 0 ? "point" : "curve") +
                "; only displacement conditions apply to points and curves, not type = " +
                quoted(to_string(bc.type)));
      } else {
        usable_[i] = true;
      }
    }
    const auto& listed = config_.output.reactions;
    if (listed.size() >= 2 &&
        std::find(listed.begin(), listed.end(), BiphasicProblem::kReactionTotal) != listed.end())
      problem("output.reactions: a boundary named " + quoted(BiphasicProblem::kReactionTotal) +
              " cannot be listed with others: their total is written under that name");
    for (const std::string& face : config_.mesh.cylinder.grading_faces) {
      if (!mesh_.find_boundary(face))
        problem("mesh.grading_faces: " + quoted(face) + " is not a boundary of the mesh (" +
                available_names() + ")");
    }
  }

  /// Nodes a usable condition acts on: its boundary's face nodes, or its point or curve.
  std::set<Index> nodes_of(const BoundaryCondition& bc, bool vertices_only = false) const {
    std::set<Index> nodes;
    if (const Boundary* b = mesh_.find_boundary(bc.boundary)) {
      for (const Tri6& f : b->faces) nodes.insert(f.begin(), f.begin() + (vertices_only ? 3 : 6));
    } else if (const NodeSet* s = mesh_.find_node_set(bc.boundary)) {
      nodes.insert(s->nodes.begin(), s->nodes.end());
    }
    return nodes;
  }

  // ---- symmetry planes ------------------------------------------------------------------

  void check_symmetry_planes() {
    symmetry_axis_.assign(config_.bcs.size(), -1);
    for (std::size_t i = 0; i < config_.bcs.size(); ++i) {
      const BoundaryCondition& bc = config_.bcs[i];
      if (!usable_[i] || bc.type != BcType::Symmetry) continue;
      const Boundary& b = *mesh_.find_boundary(bc.boundary);
      int axis = -1;
      std::string why;
      for (std::size_t f = 0; f < b.faces.size() && why.empty(); ++f) {
        const auto& x = mesh_.nodes;
        const Tri6& face = b.faces[f];
        const Point& a = x[face[0]];
        double e1[3], e2[3];
        for (int c = 0; c < 3; ++c) {
          e1[c] = x[face[1]][c] - a[c];
          e2[c] = x[face[2]][c] - a[c];
        }
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
        const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        int best = 0;
        for (int c = 1; c < 3; ++c)
          if (std::abs(n[c]) > std::abs(n[best])) best = c;
        // Every node of the face (edge nodes too: a curved face may have flat corners) on the
        // plane through its first corner.
        double size = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        double off = 0.0;
        for (Index node : face) off = std::max(off, std::abs(x[node][best] - a[best]));
        if (!(std::abs(n[best]) >= (1.0 - 1e-8) * norm) || off > 1e-8 * size) {
          why = "face " + std::to_string(f) + " at " + point_text(a) + " has normal (" +
                number(n[0] / norm) + ", " + number(n[1] / norm) + ", " + number(n[2] / norm) + ")";
        } else if (axis >= 0 && best != axis) {
          why = "its faces are normal to " + std::string(axis_name(axis)) + " and to " +
                axis_name(best);
        }
        axis = best;
      }
      if (!why.empty()) {
        problem(label(i, bc) + ": symmetry needs a plane normal to x, y or z, but '" + bc.boundary +
                "' is not one (" + why +
                "); hold a curved face with displacement conditions instead");
      } else {
        symmetry_axis_[i] = axis;
      }
    }
  }

  // ---- conflicting conditions -----------------------------------------------------------

  void check_conflicts() {
    const auto& bcs = config_.bcs;
    // Flux and pressure on one boundary: the pressure fixes every vertex the flux acts on.
    for (std::size_t i = 0; i < bcs.size(); ++i)
      for (std::size_t j = 0; j < bcs.size(); ++j)
        if (bcs[i].type == BcType::Flux && bcs[j].type == BcType::Pressure &&
            bcs[i].boundary == bcs[j].boundary && usable_[i])
          problem(label(i, bcs[i]) + " conflicts with " + label(j, bcs[j]) +
                  ": the pressure condition fixes p on every vertex of '" + bcs[i].boundary +
                  "', so the flux would be ignored; keep one of them");

    // Two conditions prescribing different values for one unknown: (node, component 0–2)
    // for displacements and symmetry planes, (vertex, 3) for pressures.
    std::map<std::pair<Index, int>, Prescribed> held;
    std::map<std::pair<std::size_t, std::size_t>, std::pair<int, std::set<Index>>> clashes;
    for (std::size_t i = 0; i < bcs.size(); ++i) {
      const BoundaryCondition& bc = bcs[i];
      if (!usable_[i]) continue;
      int component = -1;
      Prescribed what{i, bc.value, bc.curve};
      if (bc.type == BcType::Displacement) {
        component = bc.component;
      } else if (bc.type == BcType::Symmetry) {
        component = symmetry_axis_[i];
        what = {i, 0.0, ""};
      } else if (bc.type == BcType::Pressure) {
        component = 3;
      }
      if (component < 0) continue;
      for (Index n : nodes_of(bc, component == 3)) {
        const auto [it, inserted] = held.emplace(std::make_pair(n, component), what);
        if (inserted || it->second.same_as(what)) continue;
        auto& clash = clashes[{it->second.bc, i}];
        clash.first = component;
        clash.second.insert(n);
      }
    }
    for (const auto& [pair, clash] : clashes) {
      const auto& [a, b] = pair;
      const auto& [component, nodes] = clash;
      const std::string unknown =
          component == 3 ? std::string("p") : std::string("u_") + axis_name(component);
      auto value_text = [&](std::size_t k) {
        const BoundaryCondition& bc = bcs[k];
        if (bc.type == BcType::Symmetry) return std::string("0");
        return number(bc.value) + (bc.curve.empty() ? "" : " * curve " + quoted(bc.curve));
      };
      problem(label(a, bcs[a]) + " and " + label(b, bcs[b]) + " prescribe different values of " +
              unknown + " (" + value_text(a) + " and " + value_text(b) + ") at the " +
              std::to_string(nodes.size()) + " node(s) they share, e.g. " +
              mesh_.describe_node(*nodes.begin()) + "; make them agree or drop one");
    }
  }

  // ---- formulas -------------------------------------------------------------------------

  /// Times at which the formulas are checked: 0, t_end, the load-curve kinks between, and 16
  /// equal steps.
  std::vector<double> check_times() const {
    const double t_end = config_.time.t_end;
    std::set<double> t{0.0, t_end};
    for (int k = 1; k < 16; ++k) t.insert(t_end * k / 16.0);
    for (const auto& [name, curve] : config_.curves)
      for (double kink : curve.kinks())
        if (kink > 0.0 && kink < t_end) t.insert(kink);
    return {t.begin(), t.end()};
  }

  void check_formulas() {
    const auto& loads = config_.loads;
    const std::array<std::pair<std::string, const Expression*>, 4> formulas{
        {{"body_force.x", &loads.body_force[0]},
         {"body_force.y", &loads.body_force[1]},
         {"body_force.z", &loads.body_force[2]},
         {"fluid_source.value", &loads.fluid_source}}};
    bool any = false;
    for (const auto& f : formulas) any = any || !f.second->is_zero();
    if (!any) return;
    // The quadrature points of the case's rule, where the loads are integrated.
    const QuadratureRule rule = tet_quadrature(config_.quadrature_points);
    std::vector<Eigen::Matrix<double, 10, 1>> shape;
    for (const QuadraturePoint& q : rule.points) shape.push_back(p2_values(q.xi));
    const std::vector<double> all_times = check_times();
    for (const auto& [key, f] : formulas) {
      if (f->is_zero()) continue;
      const Expression rate = f->derivative(Expression::Variable::T);
      const bool steady = !f->depends_on(Expression::Variable::T);
      const std::vector<double> times = steady ? std::vector<double>{0.0} : all_times;
      bool reported = false;
      for (std::size_t e = 0; e < mesh_.tets.size() && !reported; ++e) {
        for (std::size_t q = 0; q < shape.size() && !reported; ++q) {
          Point X{0.0, 0.0, 0.0};
          for (int a = 0; a < 10; ++a)
            for (int c = 0; c < 3; ++c) X[c] += shape[q](a) * mesh_.nodes[mesh_.tets[e][a]][c];
          for (double t : times) {
            const double v = (*f)(X, t);
            const double r = steady ? 0.0 : rate(X, t);
            if (std::isfinite(v) && std::isfinite(r)) continue;
            const double bad = std::isfinite(v) ? r : v;
            problem(key + " = " + quoted(f->text()) + ": " +
                    (std::isfinite(v) ? "its rate d/dt is " : "is ") +
                    (std::isnan(bad) ? "NaN"
                     : bad > 0       ? "+inf"
                                     : "-inf") +
                    " at X = " + point_text(X) + " mm, t = " + number(t) +
                    " s (a quadrature point of element " + std::to_string(e) +
                    "); the formula must be finite over the body and [0, time.t_end]");
            reported = true;
            break;
          }
        }
      }
    }
  }

  // ---- coincident nodes -----------------------------------------------------------------

  void check_coincident_nodes() {
    const double tolerance = coincidence_tolerance(mesh_);
    const auto pairs = coincident_nodes(mesh_, tolerance);
    if (pairs.empty()) return;
    std::ostringstream s;
    s << mesh_name() << " has " << pairs.size()
      << " pair(s) of distinct nodes at the same place (closer than " << tolerance << " mm): ";
    for (std::size_t k = 0; k < std::min<std::size_t>(pairs.size(), 5); ++k)
      s << (k ? "; " : "") << mesh_.describe_node(pairs[k].first) << " and "
        << mesh_.describe_node(pairs[k].second);
    if (pairs.size() > 5) s << "; …";
    s << ". The elements on either side are not joined there (a crack or an unmerged seam "
         "between volumes; gmsh's Coherence merges them)";
    if (config_.constraints.allow_coincident_nodes) {
      notes_.push_back("note: " + s.str() + "; accepted (constraints.allow_coincident_nodes)");
    } else {
      problem(s.str() + "; set constraints.allow_coincident_nodes = true if the cut is meant");
    }
  }

  // ---- rigid-body modes -----------------------------------------------------------------

  void check_rigid_modes() {
    std::vector<FixedComponent> fixed;
    for (std::size_t i = 0; i < config_.bcs.size(); ++i) {
      const BoundaryCondition& bc = config_.bcs[i];
      const bool holds = bc.type == BcType::Displacement || bc.type == BcType::Symmetry;
      // A holding condition already refused might be the one that holds the body: judge the
      // rigid modes once the conditions themselves are right.
      if (holds && (!usable_[i] || (bc.type == BcType::Symmetry && symmetry_axis_[i] < 0))) return;
      if (!usable_[i]) continue;
      int component = -1;
      if (bc.type == BcType::Displacement) component = bc.component;
      if (bc.type == BcType::Symmetry) component = symmetry_axis_[i];
      if (component < 0) continue;
      for (Index n : nodes_of(bc)) fixed.push_back({n, component});
    }
    const std::vector<PartFreedom> parts = free_rigid_modes(mesh_, fixed);
    for (const PartFreedom& part : parts) {
      if (part.free.empty()) continue;
      std::ostringstream s;
      s << "the displacement and symmetry conditions leave rigid motions of ";
      if (parts.size() == 1) {
        s << "the body";
      } else {
        s << "part " << part.part + 1 << " of the " << parts.size() << " unconnected parts of "
          << mesh_name();
      }
      s << " (" << part.tets << " tetrahedra around " << point_text(part.centroid) << " mm, "
        << part.fixed << " fixed displacement components) free: ";
      std::vector<std::string> modes, hints;
      for (const FreeMode& m : part.free) {
        modes.push_back(m.description);
        if (m.translation && m.axis >= 0) {
          hints.push_back(std::string("u_") + axis_name(m.axis) + " at some node (" +
                          m.description + ")");
        } else if (m.translation) {
          hints.push_back("the displacement along that direction at some node (" + m.description +
                          ")");
        } else if (m.axis >= 0) {
          hints.push_back(std::string("u_") + axis_name((m.axis + 1) % 3) + " or u_" +
                          axis_name((m.axis + 2) % 3) + " at a node away from the axis (" +
                          m.description + ")");
        } else {
          hints.push_back("a component across the axis at a node away from it (" + m.description +
                          ")");
        }
      }
      s << join(modes, ", ")
        << ". Its stiffness matrix is singular: the body would drift and the linear solvers "
           "disagree. Hold them with displacement conditions on named points or curves of the "
           "mesh (gmsh physical points and curves), e.g. "
        << join(hints, "; ")
        << ", or with symmetry planes; constraints.allow_free_rigid_modes = true runs anyway "
           "if the loads balance exactly";
      if (config_.constraints.allow_free_rigid_modes) {
        notes_.push_back("note: " + s.str() + " (accepted: constraints.allow_free_rigid_modes)");
      } else {
        problem(s.str());
      }
    }
  }

  const Config& config_;
  const Mesh& mesh_;
  std::string source_;
  std::vector<bool> usable_;        ///< per condition: its name resolves to something it fits
  std::vector<int> symmetry_axis_;  ///< per symmetry condition on a valid plane: its axis
  std::vector<std::string> problems_;
  std::vector<std::string> notes_;
};

}  // namespace

Mesh build_case_mesh(const Config& config, const std::string& output_dir, bool* from_cache) {
  if (config.mesh.source != MeshSource::File) return build_mesh(config, output_dir, from_cache);
  try {
    return build_mesh(config, output_dir, from_cache);
  } catch (const std::exception& e) {
    const std::string source = config.case_file.empty() ? "case" : config.case_file;
    throw CaseError({source + ": mesh.file = " + quoted(config.mesh.file) + ": " + e.what()});
  }
}

std::vector<std::string> preflight(const Config& config, const Mesh& mesh) {
  return Preflight(config, mesh).run();
}

SectionMesh build_case_section_mesh(const Config& config) {
  const std::string source = config.case_file.empty() ? "case" : config.case_file;
  try {
    if (config.mesh.source == MeshSource::Section)
      return generate_section_rectangle(config.mesh.section);
    return read_gmsh_section(config.mesh.file);
  } catch (const std::exception& e) {
    if (config.mesh.source == MeshSource::Section)
      throw CaseError({source + ": [mesh.section]: " + e.what()});
    throw CaseError({source + ": mesh.file = " + quoted(config.mesh.file) + ": " + e.what()});
  }
}

std::vector<std::string> preflight_section(const Config& config, const SectionMesh& mesh) {
  const std::string source = config.case_file.empty() ? "case" : config.case_file;
  std::vector<std::string> names = mesh.boundary_names();
  for (const NodeSet& set : mesh.node_sets) names.push_back(set.name);
  check_boundaries(config, names);
  std::vector<std::string> problems, notes;
  try {
    const SectionProblem problem(mesh, section_model(config.model), config);
    // Rigid-body modes: the held displacement components and where they are.
    const std::vector<char>& held = problem.constrained();
    bool x_held = false, y_held = false;
    // Rotation about (x0, y0) is free iff every held x lies at y = y0 and every held y at x = x0.
    std::optional<double> y0, x0;
    bool rotation_held = false;
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      const auto& X = mesh.nodes[static_cast<std::size_t>(n)];
      if (held[static_cast<std::size_t>(problem.pattern().u_dof(n, 0))]) {
        x_held = true;
        if (y0 && std::abs(*y0 - X[1]) > 1e-12) rotation_held = true;
        y0 = X[1];
      }
      if (held[static_cast<std::size_t>(problem.pattern().u_dof(n, 1))]) {
        y_held = true;
        if (x0 && std::abs(*x0 - X[0]) > 1e-12) rotation_held = true;
        x0 = X[0];
      }
    }
    std::vector<std::string> free;
    if (config.model == ModelKind::Axisymmetric) {
      if (!y_held) free.push_back("the translation along the axis (y)");
    } else {
      if (!x_held) free.push_back("the translation in x");
      if (!y_held) free.push_back("the translation in y");
      if (x_held && y_held && !rotation_held) free.push_back("the rotation about z");
    }
    if (!free.empty()) {
      std::string list;
      for (std::size_t i = 0; i < free.size(); ++i) list += (i ? ", " : "") + free[i];
      const std::string text =
          "the displacement and symmetry conditions leave rigid-body modes free: " + list;
      if (config.constraints.allow_free_rigid_modes)
        notes.push_back("note: " + text + " (constraints.allow_free_rigid_modes = true)");
      else
        problems.push_back(source + ": " + text +
                           "; hold them, or set constraints.allow_free_rigid_modes = true");
    }
  } catch (const CaseError&) {
    throw;
  } catch (const std::exception& e) {
    problems.push_back(source + ": " + e.what());
  }
  if (!problems.empty()) throw CaseError(std::move(problems));
  return notes;
}

std::vector<std::string> check_case(const Config& config) {
  if (is_two_dimensional(config.model)) {
    const SectionMesh mesh = build_case_section_mesh(config);
    std::vector<std::string> notes = preflight_section(config, mesh);
    for (const std::string& line : check_section_probes(config, mesh)) notes.push_back("  " + line);
    return notes;
  }
  Config quiet = config;
  quiet.mesh.cylinder.write_msh.clear();  // check writes nothing
  const Mesh mesh = build_case_mesh(quiet, "");
  std::vector<std::string> notes = preflight(config, mesh);
  for (const std::string& line : check_probes(config, mesh)) notes.push_back("  " + line);
  return notes;
}

}  // namespace biphasic
