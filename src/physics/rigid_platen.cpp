#include "biphasic/physics/rigid_platen.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "biphasic/physics/boundary_integrals.hpp"
#include "boundary_data.hpp"

namespace biphasic {

namespace {

/// Reference area of a 6-node boundary triangle [mm²].
double face_area(const Mesh& mesh, const Tri6& f) {
  Eigen::Matrix<double, 6, 3> X;
  for (int a = 0; a < 6; ++a)
    for (int c = 0; c < 3; ++c) X(a, c) = mesh.nodes[static_cast<std::size_t>(f[a])][c];
  return face_p1_integrals(X).sum();
}

/// Length of a 3-node boundary segment [mm], or with `axisymmetric` the area it sweeps about
/// the axis, ∫ 2πR ds [mm²] (3-point Gauss rule, exact for the quadratic segment's R ds).
double segment_measure(const SectionMesh& mesh, const Line3& s, bool axisymmetric) {
  const double g = std::sqrt(0.6);
  const double xi[3] = {0.5 * (1.0 - g), 0.5, 0.5 * (1.0 + g)};
  const double w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  double sum = 0.0;
  for (int q = 0; q < 3; ++q) {
    const double x = xi[q];
    const double N[3] = {(1.0 - x) * (1.0 - 2.0 * x), x * (2.0 * x - 1.0), 4.0 * x * (1.0 - x)};
    const double dN[3] = {4.0 * x - 3.0, 4.0 * x - 1.0, 4.0 - 8.0 * x};
    double R = 0.0, dx = 0.0, dy = 0.0;
    for (int a = 0; a < 3; ++a) {
      const Point2& p = mesh.nodes[static_cast<std::size_t>(s[a])];
      R += N[a] * p[0];
      dx += dN[a] * p[0];
      dy += dN[a] * p[1];
    }
    sum += w[q] * std::hypot(dx, dy) * (axisymmetric ? 2.0 * std::numbers::pi * R : 1.0);
  }
  return sum;
}

/// The platens of `config` on a mesh with `components` unknowns per node; `measure(element)`
/// is a boundary element's area.
template <class MeshT, class Elements, class Measure>
std::vector<RigidPlaten> find_platens(const MeshT& mesh, const Elements& elements, int components,
                                      const Config& config,
                                      const std::map<std::string, LoadCurve>& curves,
                                      Measure&& measure) {
  std::vector<RigidPlaten> out;
  std::vector<long> owner(static_cast<std::size_t>(mesh.num_nodes()), -1);
  for (std::size_t i = 0; i < config.bcs.size(); ++i) {
    const BoundaryCondition& bc = config.bcs[i];
    if (bc.type != BcType::RigidPlaten) continue;
    const auto target = detail::resolve_condition(
        i, bc, mesh, curves, "the mesh has no boundary of that name",
        "a rigid platen needs a boundary (a physical surface, or a curve in 2-D), not a point");
    if (bc.component < 0 || bc.component >= components)
      throw std::runtime_error(detail::bc_label(i, bc) + ": component " +
                               std::to_string(bc.component) + " does not exist here");
    RigidPlaten p;
    p.condition = i;
    p.boundary = bc.boundary;
    p.component = bc.component;
    p.value = bc.value;
    p.curve = target.curve;
    const auto edge_node = std::find_if(target.nodes.begin(), target.nodes.end(),
                                        [&](Index n) { return n >= mesh.num_vertices; });
    if (edge_node == target.nodes.end())
      throw std::runtime_error(detail::bc_label(i, bc) + ": the boundary has no edge nodes");
    p.master_node = *edge_node;
    p.master = components * p.master_node + p.component;
    for (Index n : target.nodes) {
      long& o = owner[static_cast<std::size_t>(n)];
      if (o >= 0)
        throw std::runtime_error(
            detail::bc_label(i, bc) + " and " +
            detail::bc_label(static_cast<std::size_t>(o), config.bcs[static_cast<std::size_t>(o)]) +
            " share node " + std::to_string(n) + ": a node can belong to one rigid platen only");
      o = static_cast<long>(i);
      p.dofs.push_back(components * n + p.component);
    }
    std::sort(p.dofs.begin(), p.dofs.end());
    std::set<Index> near;
    for (const auto& element : elements) {
      const bool touches = std::any_of(element.begin(), element.end(),
                                       [&](Index n) { return target.nodes.count(n) > 0; });
      if (touches) near.insert(element.begin(), element.end());
    }
    p.neighbourhood.assign(near.begin(), near.end());
    for (const auto& b : detail::elements_of(*target.boundary)) p.area += measure(b);
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

RigidPlatens::RigidPlatens(const Mesh& mesh, const Config& config,
                           const std::map<std::string, LoadCurve>& curves)
    : platens_(find_platens(mesh, mesh.tets, 3, config, curves,
                            [&](const Tri6& f) { return face_area(mesh, f); })) {}

RigidPlatens::RigidPlatens(const SectionMesh& mesh, bool axisymmetric, const Config& config,
                           const std::map<std::string, LoadCurve>& curves)
    : platens_(find_platens(mesh, mesh.triangles, 2, config, curves, [&](const Line3& s) {
        return segment_measure(mesh, s, axisymmetric);
      })) {}

std::vector<NodeCoupling> RigidPlatens::couplings() const {
  std::vector<NodeCoupling> out;
  for (const RigidPlaten& p : platens_) out.push_back({p.master_node, p.neighbourhood});
  return out;
}

void RigidPlatens::check_free(const std::vector<char>& held, int components,
                              const std::vector<BoundaryCondition>& bcs) const {
  for (const RigidPlaten& p : platens_)
    for (Index dof : p.dofs)
      if (held[static_cast<std::size_t>(dof)])
        throw std::runtime_error(
            detail::bc_label(p.condition, bcs[p.condition]) + ": node " +
            std::to_string(dof / components) +
            " is also held along the platen's component by a displacement or symmetry condition "
            "(or the axis); a rigid platen's nodes move with the platen");
}

std::vector<char> RigidPlatens::tie(const std::vector<char>& held, const SparsityPattern& pattern,
                                    double row_scale, const std::vector<BoundaryCondition>& bcs,
                                    std::map<std::string, std::vector<Index>>& held_rows) {
  check_free(held, pattern.components(), bcs);
  bind(pattern, row_scale);
  std::vector<char> constrained = held;
  for (const RigidPlaten& p : platens_) {
    for (Index i : p.dofs)
      if (i != p.master) constrained[static_cast<std::size_t>(i)] = 1;
    std::vector<Index>& rows = held_rows[p.boundary];
    rows.insert(rows.end(), p.dofs.begin(), p.dofs.end());
  }
  return constrained;
}

void RigidPlatens::bind(const SparsityPattern& pattern, double row_scale) {
  row_scale_ = row_scale;
  positions_.assign(platens_.size(), {});
  const auto& cp = pattern.colptr();
  const auto& ri = pattern.rowind();
  auto at = [&](Index row, Index col) {
    const Index q = pattern.find(row, col);
    if (q < 0)
      throw std::logic_error("rigid platen: entry (" + std::to_string(row) + ", " +
                             std::to_string(col) + ") is outside the pattern");
    return q;
  };
  for (std::size_t k = 0; k < platens_.size(); ++k) {
    const RigidPlaten& p = platens_[k];
    Positions& pos = positions_[k];
    for (Index i : p.dofs) {
      if (i == p.master) continue;
      // The pattern is structurally symmetric: row i's columns are column i's rows.
      for (Index q = cp[i]; q < cp[i + 1]; ++q) {
        const Index j = ri[q];
        pos.into_master.emplace_back(at(i, j), at(p.master, j));
      }
      pos.tie_diagonal.push_back(at(i, i));
      pos.tie_master.push_back(at(i, p.master));
    }
  }
}

void RigidPlatens::raise_solution_scales(const Config& config, double HA, const double* extent,
                                         std::pair<double, double>& scales) const {
  for (const RigidPlaten& p : platens_) {
    const double stress =
        detail::largest_value(config.bcs[p.condition], config.curves, config.time.t_end) /
        std::max(p.area, 1e-300);
    scales.second = std::max(scales.second, stress);
    scales.first = std::max(scales.first, stress / HA * extent[p.component]);
  }
}

double RigidPlatens::force(std::size_t k, double t) const {
  const RigidPlaten& p = platens_[k];
  return p.value * (p.curve ? p.curve->value(t) : 1.0);
}

void RigidPlatens::residual(double t, const double* y, double* F) const {
  for (std::size_t k = 0; k < platens_.size(); ++k) {
    const RigidPlaten& p = platens_[k];
    double sum = 0.0;
    for (Index i : p.dofs) sum += F[i];
    for (Index i : p.dofs) F[i] = row_scale_ * (y[i] - y[p.master]);
    F[p.master] = sum - force(k, t);
  }
}

void RigidPlatens::time_derivative(double t, double* dFdt) const {
  for (const RigidPlaten& p : platens_) {
    double sum = 0.0;
    for (Index i : p.dofs) {
      sum += dFdt[i];
      dFdt[i] = 0.0;
    }
    dFdt[p.master] = sum - p.value * (p.curve ? p.curve->slope(t) : 0.0);
  }
}

void RigidPlatens::jacobian(double* values, double* rate_values) const {
  for (std::size_t k = 0; k < platens_.size(); ++k) {
    const Positions& pos = positions_[k];
    for (double* v : {values, rate_values}) {
      if (!v) continue;
      for (const auto& [from, to] : pos.into_master) v[to] += v[from];
      for (const auto& [from, to] : pos.into_master) v[from] = 0.0;
    }
    for (std::size_t r = 0; r < pos.tie_diagonal.size(); ++r) {
      values[pos.tie_diagonal[r]] = row_scale_;
      values[pos.tie_master[r]] = -row_scale_;
    }
  }
}

void RigidPlatens::apply(double* y, double* ydot) const {
  for (const RigidPlaten& p : platens_)
    for (Index i : p.dofs) {
      y[i] = y[p.master];
      if (ydot) ydot[i] = ydot[p.master];
    }
}

}  // namespace biphasic
