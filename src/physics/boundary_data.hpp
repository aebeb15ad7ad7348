// Helpers shared by the three- and two-dimensional problems for boundary data: labels in
// messages, the largest value of a condition over a run, and rates by central differences.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/io/config.hpp"

namespace biphasic::detail {

/// "boundary[i] (type on 'name')": how messages name a boundary condition.
inline std::string bc_label(std::size_t i, const BoundaryCondition& bc) {
  return "boundary[" + std::to_string(i) + "] (" + to_string(bc.type) + " on '" + bc.boundary +
         "')";
}

/// ∂f/∂t by a central difference with step 6e-6·max(1, |t|) (≈ ε^(1/3): truncation and
/// rounding errors balance near 1e-11 relative for smooth fields).
template <class Field>
auto central_rate(const Field& f, const Vec3& X, double t) {
  const double h = 6e-6 * std::max(1.0, std::abs(t));
  return (f(X, t + h) - f(X, t - h)) / (2.0 * h);
}

/// Largest |value · curve(t)| over [0, t_end] (curves are piecewise linear: their points
/// inside the interval and its ends).
inline double largest_value(const BoundaryCondition& bc,
                            const std::map<std::string, LoadCurve>& curves, double t_end) {
  const double scale = bc.type == BcType::Traction
                           ? std::sqrt(bc.vector[0] * bc.vector[0] + bc.vector[1] * bc.vector[1] +
                                       bc.vector[2] * bc.vector[2])
                           : std::abs(bc.value);
  auto it = bc.curve.empty() ? curves.end() : curves.find(bc.curve);
  if (it == curves.end()) return scale;
  const LoadCurve& c = it->second;
  double m = std::max(std::abs(c.value(0.0)), std::abs(c.value(t_end)));
  for (const auto& [t, v] : c.points)
    if (t >= 0.0 && t <= t_end) m = std::max(m, std::abs(v));
  return scale * m;
}

}  // namespace biphasic::detail

#include <functional>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/dirichlet_rows.hpp"

namespace biphasic::detail {

/// What a boundary condition acts on: the nodes and corner vertices of its named boundary (or
/// the nodes of its physical point or curve), its boundary and its load curve.
template <class Boundary>
struct ConditionTarget {
  const Boundary* boundary = nullptr;  ///< null for a node set
  std::set<Index> nodes, vertices;
  const LoadCurve* curve = nullptr;
};

inline const std::vector<Tri6>& elements_of(const Boundary& b) { return b.faces; }
inline const std::vector<Line3>& elements_of(const SectionBoundary& b) { return b.segments; }

/// Resolves condition i by name on `mesh` (a Mesh or a SectionMesh): its boundary's nodes and
/// vertices (the first corners of each boundary element), or a node set's nodes for a
/// displacement condition, and its curve. Throws std::runtime_error naming the condition:
/// "<label>: <no_boundary>" for an unknown name, "<label>: <node_set_only>" for a non-
/// displacement condition on a node set, and for an unknown curve.
template <class MeshT>
auto resolve_condition(std::size_t i, const BoundaryCondition& bc, const MeshT& mesh,
                       const std::map<std::string, LoadCurve>& curves,
                       const std::string& no_boundary, const std::string& node_set_only) {
  using B = std::remove_cv_t<std::remove_pointer_t<decltype(mesh.find_boundary(""))>>;
  ConditionTarget<B> target;
  target.boundary = mesh.find_boundary(bc.boundary);
  const NodeSet* node_set = target.boundary ? nullptr : mesh.find_node_set(bc.boundary);
  if (!target.boundary && !node_set) throw std::runtime_error(bc_label(i, bc) + ": " + no_boundary);
  if (node_set && bc.type != BcType::Displacement)
    throw std::runtime_error(bc_label(i, bc) + ": " + node_set_only);
  if (!bc.curve.empty()) {
    const auto it = curves.find(bc.curve);
    if (it == curves.end())
      throw std::runtime_error(bc_label(i, bc) + ": no load curve '" + bc.curve + "'");
    target.curve = &it->second;
  }
  if (node_set) target.nodes.insert(node_set->nodes.begin(), node_set->nodes.end());
  if (target.boundary) {
    for (const auto& element : elements_of(*target.boundary)) {
      constexpr int kCorners = std::tuple_size_v<std::decay_t<decltype(element)>> == 6 ? 3 : 2;
      target.nodes.insert(element.begin(), element.end());
      target.vertices.insert(element.begin(), element.begin() + kCorners);
    }
  }
  return target;
}

}  // namespace biphasic::detail

namespace biphasic::detail {

/// ‖F‖_∞ over the free rows below num_u [N] and over the free rows from num_u on [mm³/s].
inline std::pair<double, double> free_row_norms(const double* F,
                                                const std::vector<char>& constrained, Index num_u) {
  double ru = 0.0, rp = 0.0;
  for (Index i = 0; i < static_cast<Index>(constrained.size()); ++i) {
    if (constrained[static_cast<std::size_t>(i)]) continue;
    double& r = i < num_u ? ru : rp;
    r = std::max(r, std::abs(F[i]));
  }
  return {ru, rp};
}

/// The kinks of every load curve, sorted and unique [s].
inline std::vector<double> curve_kinks(const std::map<std::string, LoadCurve>& curves) {
  std::set<double> t;
  for (const auto& [name, c] : curves)
    for (double k : c.kinks()) t.insert(k);
  return {t.begin(), t.end()};
}

/// dt for the conservative volume rate; throws std::invalid_argument unless dt ≥ 0 and finite.
inline double checked_volume_rate_dt(double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt))
    throw std::invalid_argument("conservative volume rate: dt = " + std::to_string(dt) +
                                " s must be >= 0 and finite");
  return dt;
}

/// The rows each named boundary's displacement and symmetry conditions hold, in `boundaries`'
/// order; throws std::invalid_argument "reaction on '<name>': the <noun> has no displacement or
/// symmetry condition" for a name without.
inline std::vector<const std::vector<Index>*> reaction_rows(
    const std::map<std::string, std::vector<Index>>& held_rows,
    const std::vector<std::string>& boundaries, const std::string& noun) {
  std::vector<const std::vector<Index>*> rows;
  for (const std::string& name : boundaries) {
    const auto it = held_rows.find(name);
    if (it == held_rows.end())
      throw std::invalid_argument("reaction on '" + name + "': the " + noun +
                                  " has no displacement or symmetry condition");
    rows.push_back(&it->second);
  }
  return rows;
}

/// Reactions from the assembled residual F: per boundary the sum of F over its rows, by
/// component (u_dof(n, c) = components·n + c); with two or more boundaries also the total over
/// the union of their rows, a row held by several (a shared edge) counted once.
inline std::vector<std::array<double, 3>> sum_reactions(
    const std::vector<const std::vector<Index>*>& rows, const std::vector<double>& F,
    int components) {
  std::vector<std::array<double, 3>> out(rows.size(), {0.0, 0.0, 0.0});
  for (std::size_t b = 0; b < rows.size(); ++b)
    for (Index dof : *rows[b]) out[b][static_cast<std::size_t>(dof % components)] += F[dof];
  if (rows.size() >= 2) {
    std::set<Index> all;
    for (const auto* r : rows) all.insert(r->begin(), r->end());
    std::array<double, 3> total{0.0, 0.0, 0.0};
    for (Index dof : all) total[static_cast<std::size_t>(dof % components)] += F[dof];
    out.push_back(total);
  }
  return out;
}

}  // namespace biphasic::detail
