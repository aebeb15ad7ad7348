#include "biphasic/physics/section_problem.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "biphasic/physics/stabilisation/stabilisations.hpp"
#include "boundary_data.hpp"

namespace biphasic {

namespace {

using detail::bc_label;
using detail::central_rate;
using detail::largest_value;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Eigen::Vector2d point(const SectionMesh& mesh, Index n) {
  return {mesh.nodes[n][0], mesh.nodes[n][1]};
}

/// The element length of stabilisation.length for a straight triangle with corners a, b, c:
/// circumradius, shortest or longest edge, or the diameter of the disc of the same area.
double triangle_length(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       ElementLength choice) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  const double area = 0.5 * std::abs((b - a)(0) * (c - a)(1) - (c - a)(0) * (b - a)(1));
  switch (choice) {
    case ElementLength::Circumradius:
      return ab * bc * ca / (4.0 * area);
    case ElementLength::ShortestEdge:
      return std::min({ab, bc, ca});
    case ElementLength::LongestEdge:
      return std::max({ab, bc, ca});
    case ElementLength::VolumeDiameter:
      return 2.0 * std::sqrt(area / std::numbers::pi);
  }
  return 0.0;
}

/// Three-point Gauss rule on [0, 1] (degree 5).
struct LinePoint {
  double xi, weight;
};
constexpr std::array<LinePoint, 3> kLineRule{{{0.5 - 0.3872983346207417, 5.0 / 18.0},
                                              {0.5, 8.0 / 18.0},
                                              {0.5 + 0.3872983346207417, 5.0 / 18.0}}};

/// P2 functions of a 3-node segment (end 0, end 1, midside node) at ξ ∈ [0, 1], and their
/// derivatives.
Eigen::Vector3d line3_values(double x) {
  return {(1.0 - x) * (1.0 - 2.0 * x), x * (2.0 * x - 1.0), 4.0 * x * (1.0 - x)};
}
Eigen::Vector3d line3_derivatives(double x) {
  return {4.0 * x - 3.0, 4.0 * x - 1.0, 4.0 - 8.0 * x};
}

/// Adds a triangle's measure (Σ w_q: dX dY, or 2πR dR dZ) and its area (Σ w_q / 2πR_q
/// axisymmetric) [mm², or mm³ and mm²].
void accumulate_measure(const std::vector<SectionPointGeometry>& points, bool axisymmetric,
                        double& measure, double& area) {
  for (const SectionPointGeometry& g : points) {
    measure += g.weight;
    area += axisymmetric ? g.weight * g.inverse_radius / (2.0 * std::numbers::pi) : g.weight;
  }
}

}  // namespace

SectionProblem::SectionProblem(const SectionMesh& mesh, SectionModel model, const Config& config,
                               AssemblyScope scope)
    : mesh_(mesh),
      model_(model),
      curves_(config.curves),
      laws_{make_material_laws(config.material)},
      platens_(scope.platens
                   ? RigidPlatens()
                   : RigidPlatens(mesh, model == SectionModel::Axisymmetric, config, curves_)),
      pattern_(mesh, platens_.couplings()) {
  const bool axisymmetric = model == SectionModel::Axisymmetric;
  const std::size_t num_elements = mesh.triangles.size();
  const bool whole = scope.whole_mesh();
  for (Index e = 0; e < static_cast<Index>(num_elements); ++e)
    if (whole || scope.element_owned[static_cast<std::size_t>(e)]) elements_.push_back(e);
  // Face loads go to the rows of owned nodes only (row → node: u rows 2n + c, p rows by vertex).
  auto row_owned = [&](Index row) {
    if (whole) return true;
    const Index node = row < pattern_.num_u() ? row / 2 : row - pattern_.num_u();
    return scope.node_owned[static_cast<std::size_t>(node)] != 0;
  };
  // Material regions, as in the three-dimensional problem.
  std::vector<int> region_law(mesh.region_names.size(), 0);
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r)
    for (const RegionConfig& entry : config.regions)
      if (entry.name == mesh.region_names[r]) {
        region_law[r] = static_cast<int>(laws_.size());
        laws_.push_back(make_material_laws(entry.material));
      }
  for (const RegionConfig& entry : config.regions)
    if (std::find(mesh.region_names.begin(), mesh.region_names.end(), entry.name) ==
        mesh.region_names.end())
      throw std::runtime_error("region '" + entry.name + "': the mesh has no region of that name");
  if (laws_.size() > 1) {
    element_law_.resize(num_elements);
    for (std::size_t e = 0; e < num_elements; ++e)
      element_law_[e] = region_law[static_cast<std::size_t>(mesh.region_of(static_cast<Index>(e)))];
  }
  // The largest H_A and k(1) over the laws some triangle of the whole mesh uses (a part: the
  // regions the whole mesh has, AssemblyScope::region_used).
  double HA = 0.0, k_ref = 0.0;
  auto include_laws = [&](const MaterialLaws& laws) {
    HA = std::max(HA, laws.p_wave_modulus());
    k_ref = std::max(k_ref, laws.reference_permeability());
  };
  if (whole || element_law_.empty()) {
    for (std::size_t e = 0; e < std::max<std::size_t>(num_elements, 1); ++e)
      include_laws(num_elements ? laws_of(static_cast<Index>(e)) : laws_[0]);
  } else {
    for (std::size_t r = 0; r < region_law.size(); ++r)
      if (scope.region_used[r]) include_laws(laws_[static_cast<std::size_t>(region_law[r])]);
  }
  modulus_ = HA;

  // Geometry and stabilisation coefficients per triangle.
  const AnyStabilisation stabilisation = make_stabilisation(config.stabilisation.type);
  const bool sized = describe(stabilisation).sized_by_element;
  geometry_.resize(num_elements);
  stabilisation_.resize(num_elements);
  const StabilisationContext context = stabilisation_context(config.stabilisation, config.time.dt);
  double measure = 0.0, area = 0.0;
  for (std::size_t e = 0; e < num_elements; ++e) {
    const Tri6& tri = mesh.triangles[e];
    Eigen::Matrix<double, 6, 2> X;
    for (int a = 0; a < 6; ++a) X.row(a) = point(mesh, tri[a]).transpose();
    try {
      section_point_geometry(X, model, geometry_[e]);
    } catch (const std::domain_error& err) {
      throw std::runtime_error("triangle " + std::to_string(e) + ": " + err.what());
    }
    accumulate_measure(geometry_[e], axisymmetric, measure, area);
    if (sized) {
      const double h = triangle_length(point(mesh, tri[0]), point(mesh, tri[1]),
                                       point(mesh, tri[2]), config.stabilisation.length);
      const MaterialLaws& laws = laws_of(static_cast<Index>(e));
      stabilisation_.set(
          e, element_coefficients(stabilisation, config.stabilisation.scale * h * h, laws, context),
          laws);
    }
  }
  stabilisation_.finish();  // a term no element has is absent (has_gls(), ...)
  // Mean depth of the measure: 1 mm in plane strain, 2πR̄ axisymmetric.
  const double depth = !whole ? scope.section_depth : area > 0.0 ? measure / area : 1.0;
  row_scale_u_ = HA * depth;
  row_scale_p_ = k_ref * depth;

  // Boundary conditions by curve (or point) name.
  DirichletRows rows_held(pattern_.size());
  constexpr std::size_t kAxis = static_cast<std::size_t>(-1);
  const auto label = [&](std::size_t i) {
    return i == kAxis ? std::string("the axis condition u_r = 0") : bc_label(i, config.bcs[i]);
  };
  auto constrain = [&](std::size_t i, Index dof, double value, const LoadCurve* curve, Index node,
                       int field) {
    rows_held.add(i, {dof, value, curve, node, field}, label, mesh_.describe_node(node));
  };
  const std::string axis_names[2] = {axisymmetric ? "r" : "x", axisymmetric ? "z" : "y"};
  for (std::size_t i = 0; i < config.bcs.size(); ++i) {
    const BoundaryCondition& bc = config.bcs[i];
    const auto target = detail::resolve_condition(
        i, bc, mesh, curves_, "the mesh has no boundary curve of that name",
        "only displacement conditions apply to a physical point");
    const SectionBoundary* b = target.boundary;
    const LoadCurve* curve = target.curve;
    switch (bc.type) {
      case BcType::Displacement:
      case BcType::Symmetry: {
        const bool symmetry = bc.type == BcType::Symmetry;
        int component = bc.component;
        if (symmetry) {
          // The curve's normal must lie along x/r or y/z: that component is held.
          component = -1;
          for (const Line3& s : b->segments) {
            const Eigen::Vector2d t = (point(mesh, s[1]) - point(mesh, s[0])).normalized();
            const Eigen::Vector2d m = (point(mesh, s[2]) - point(mesh, s[0]));
            const int c = std::abs(t(0)) > std::abs(t(1)) ? 1 : 0;  // normal component
            const bool straight =
                std::abs(t(1 - c)) > 1.0 - 1e-8 && std::abs(m(c)) <= 1e-8 * m.norm();
            if (!straight || (component >= 0 && c != component)) {
              std::ostringstream msg;
              msg << bc_label(i, bc) << ": symmetry needs a straight curve normal to "
                  << axis_names[0] << " or " << axis_names[1] << "; its segment from "
                  << mesh.describe_node(s[0]) << " to " << mesh.describe_node(s[1]) << " is not";
              throw std::runtime_error(msg.str());
            }
            component = c;
          }
          if (component < 0) break;
        } else if (component < 0 || component > 1) {
          throw std::runtime_error(bc_label(i, bc) + ": component " + std::to_string(component) +
                                   " does not exist in a two-dimensional model (0 = " +
                                   axis_names[0] + ", 1 = " + axis_names[1] + ")");
        }
        std::vector<Index>& held = held_rows_[bc.boundary];
        for (Index n : target.nodes) {
          const Index dof = pattern_.u_dof(n, component);
          constrain(i, dof, symmetry ? 0.0 : bc.value, symmetry ? nullptr : curve, n,
                    symmetry ? kHeldAtZero : component);
          held.push_back(dof);
        }
        break;
      }
      case BcType::Pressure:
        for (Index v : target.vertices)
          constrain(i, pattern_.p_dof(v), bc.value, curve, v, kPressureField);
        break;
      case BcType::Flux:
      case BcType::Traction:
      case BcType::NormalTraction: {
        // Consistent nodal loads on the reference curve, dA = ds (× 1 mm) or 2πR ds.
        std::map<Index, double> load;
        for (const Line3& s : b->segments) {
          Eigen::Matrix<double, 3, 2> X;
          for (int a = 0; a < 3; ++a) X.row(a) = point(mesh, s[a]).transpose();
          for (const LinePoint& q : kLineRule) {
            const Eigen::Vector3d N = line3_values(q.xi);
            const Eigen::Vector2d tangent = X.transpose() * line3_derivatives(q.xi);
            const double R = N.dot(X.col(0));
            const double dA = q.weight * (axisymmetric ? 2.0 * std::numbers::pi * R : 1.0);
            if (bc.type == BcType::Flux) {
              // R_p += ∫ g q̄ dA with the P1 functions of the segment's ends.
              const double ds = tangent.norm() * dA;
              load[pattern_.p_dof(s[0])] += (1.0 - q.xi) * ds;
              load[pattern_.p_dof(s[1])] += q.xi * ds;
            } else if (bc.type == BcType::Traction) {
              // R_u −= ∫ N_a t̄ dA (nominal, dead load).
              const double ds = tangent.norm() * dA;
              for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 2; ++c)
                  load[pattern_.u_dof(s[a], c)] -=
                      N(a) * bc.vector[static_cast<std::size_t>(c)] * ds;
            } else {
              // t̄ = −value N, N ds = (t_y, −t_x) dξ (the body lies on the segment's left).
              const Eigen::Vector2d n_ds(tangent(1), -tangent(0));
              for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 2; ++c) load[pattern_.u_dof(s[a], c)] += N(a) * n_ds(c) * dA;
            }
          }
        }
        if (bc.type == BcType::Traction && bc.vector[2] != 0.0)
          throw std::runtime_error(bc_label(i, bc) +
                                   ": a two-dimensional model has no third traction component");
        NodalLoad nl{{}, bc.type == BcType::Traction ? 1.0 : bc.value, curve};
        for (const auto& entry : load)
          if (row_owned(entry.first)) nl.entries.push_back(entry);
        nodal_loads_.push_back(std::move(nl));
        break;
      }
      case BcType::RigidPlaten:  // platens_, or the caller's (scope.platens): reaction rows
        if (scope.platens) {
          std::vector<Index>& held = held_rows_[bc.boundary];
          for (Index n : target.nodes) held.push_back(pattern_.u_dof(n, bc.component));
        }
        break;
    }
  }
  // The whole mesh's extent along x/r and y/z [mm] (a part: the whole's box from the scope).
  const auto [lower, upper] = whole ? bounding_box(mesh) : std::pair{scope.lower, scope.upper};
  const Eigen::Vector2d extent =
      Eigen::Vector2d(upper[0] - lower[0], upper[1] - lower[1]).cwiseMax(1e-300);
  // Axisymmetric: u_r = 0 on the axis.
  if (axisymmetric) {
    const double tol = 1e-10 * extent.maxCoeff();
    for (Index n = 0; n < mesh.num_nodes(); ++n)
      if (std::abs(mesh.nodes[n][0]) <= tol)
        constrain(kAxis, pattern_.u_dof(n, 0), 0.0, nullptr, n, kHeldAtZero);
  }
  dirichlet_ = std::move(rows_held.rows());
  dirichlet_held_ = std::move(rows_held.constrained());
  constrained_ = platens_.tie(dirichlet_held_, pattern_, row_scale_u_, config.bcs, held_rows_);
  for (auto& [name, rows] : held_rows_) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  }
  // Scales the boundary data imply (as BiphasicProblem's).
  double us = 0.0, ps = 0.0;
  for (const BoundaryCondition& bc : config.bcs) {
    const double v = largest_value(bc, config.curves, config.time.t_end);
    if (bc.type == BcType::Displacement && bc.component >= 0 && bc.component < 2) {
      us = std::max(us, v);
      ps = std::max(ps, HA * v / extent(bc.component));
    } else if (bc.type == BcType::Pressure) {
      ps = std::max(ps, v);
    } else if (bc.type == BcType::Traction || bc.type == BcType::NormalTraction) {
      ps = std::max(ps, v);
      us = std::max(us, v / HA * extent.maxCoeff());
    }
  }
  solution_scales_ = {us, ps};
  platens_.raise_solution_scales(config, HA, extent.data(), solution_scales_);
  if (scope.platens)
    scope.platens->raise_solution_scales(config, HA, extent.data(), solution_scales_);

  // Volume loads from the case's formulas.
  const auto& bf = config.loads.body_force;
  if (!bf[2].is_zero())
    throw std::runtime_error("loads.body_force.z = \"" + bf[2].text() +
                             "\": a two-dimensional model has no third component");
  using V = Expression::Variable;
  if (!(bf[0].is_zero() && bf[1].is_zero())) {
    auto field = [](Expression fx, Expression fy) {
      return [fx, fy](const Vec3& X, double t) {
        return Vec3(fx(X(0), X(1), 0.0, t), fy(X(0), X(1), 0.0, t), 0.0);
      };
    };
    set_body_force(field(bf[0], bf[1]), field(bf[0].derivative(V::T), bf[1].derivative(V::T)));
  }
  if (!config.loads.fluid_source.is_zero()) {
    auto field = [](Expression f) {
      return [f](const Vec3& X, double t) { return f(X(0), X(1), 0.0, t); };
    };
    set_fluid_source(field(config.loads.fluid_source),
                     field(config.loads.fluid_source.derivative(V::T)));
  }
}

double section_mean_depth(const SectionMesh& mesh, SectionModel model) {
  double measure = 0.0, area = 0.0;
  std::vector<SectionPointGeometry> points;
  for (const Tri6& tri : mesh.triangles) {
    Eigen::Matrix<double, 6, 2> X;
    for (int a = 0; a < 6; ++a) X.row(a) = point(mesh, tri[a]).transpose();
    section_point_geometry(X, model, points);
    accumulate_measure(points, model == SectionModel::Axisymmetric, measure, area);
  }
  return area > 0.0 ? measure / area : 1.0;
}

void SectionProblem::set_body_force(VectorField b, VectorField rate) {
  body_force_ = std::move(b);
  body_force_rate_ = body_force_ ? std::move(rate) : VectorField{};
}

void SectionProblem::set_fluid_source(ScalarField s, ScalarField rate) {
  source_ = std::move(s);
  source_rate_ = source_ ? std::move(rate) : ScalarField{};
}

void SectionProblem::set_dirichlet_fields(VectorField u, ScalarField p, VectorField u_rate,
                                          ScalarField p_rate) {
  dirichlet_u_ = std::move(u);
  dirichlet_u_rate_ = dirichlet_u_ ? std::move(u_rate) : VectorField{};
  dirichlet_p_ = std::move(p);
  dirichlet_p_rate_ = dirichlet_p_ ? std::move(p_rate) : ScalarField{};
}

void SectionProblem::set_conservative_volume_rate(double dt) {
  volume_rate_dt_ = detail::checked_volume_rate_dt(dt);
}

double SectionProblem::dirichlet_value(const Dirichlet& d, double t) const {
  if (d.field >= 0 && d.field < 2 && dirichlet_u_)
    return dirichlet_u_(node_position(d.node), t)(d.field);
  if (d.field == kPressureField && dirichlet_p_) return dirichlet_p_(node_position(d.node), t);
  return d.value * curve_value(d.curve, t);
}

double SectionProblem::dirichlet_rate(const Dirichlet& d, double t) const {
  const Vec3 X = node_position(d.node);
  if (d.field >= 0 && d.field < 2 && dirichlet_u_)
    return (dirichlet_u_rate_ ? dirichlet_u_rate_(X, t)
                              : central_rate(dirichlet_u_, X, t))(d.field);
  if (d.field == kPressureField && dirichlet_p_)
    return dirichlet_p_rate_ ? dirichlet_p_rate_(X, t) : central_rate(dirichlet_p_, X, t);
  return d.curve ? d.value * d.curve->slope(t) : 0.0;
}

Vec3 SectionProblem::point_position(Index e, std::size_t q) const {
  Vec3 X = Vec3::Zero();
  const SectionPointGeometry& g = geometry_[e][q];
  for (int a = 0; a < 6; ++a) X += g.N(a) * node_position(mesh_.triangles[e][a]);
  return X;
}

void SectionProblem::add_volume_loads(double t, bool rate, double* out) const {
  if (!body_force_ && !source_) return;
  for (const Index e : elements_) {
    const Tri6& tri = mesh_.triangles[static_cast<std::size_t>(e)];
    for (std::size_t q = 0; q < geometry_[e].size(); ++q) {
      const SectionPointGeometry& g = geometry_[e][q];
      const Vec3 X = point_position(e, q);
      if (body_force_) {
        const Vec3 b = !rate              ? body_force_(X, t)
                       : body_force_rate_ ? body_force_rate_(X, t)
                                          : central_rate(body_force_, X, t);
        for (int a = 0; a < 6; ++a)
          for (int i = 0; i < 2; ++i) out[pattern_.u_dof(tri[a], i)] -= g.weight * g.N(a) * b(i);
      }
      if (source_) {
        const double s = !rate          ? source_(X, t)
                         : source_rate_ ? source_rate_(X, t)
                                        : central_rate(source_, X, t);
        for (int c = 0; c < 3; ++c) out[pattern_.p_dof(tri[c])] -= g.weight * g.Np(c) * s;
      }
    }
  }
}

std::vector<double> SectionProblem::breakpoints() const { return detail::curve_kinks(curves_); }

void SectionProblem::apply_dirichlet(double t, double* y, double* ydot) const {
  for (const Dirichlet& d : dirichlet_) {
    y[d.dof] = dirichlet_value(d, t);
    if (ydot) ydot[d.dof] = dirichlet_rate(d, t);
  }
  platens_.apply(y, ydot);
}

void SectionProblem::element(Index e, const double* y, const double* ydot, bool with_jacobian,
                             SectionElementOutput& out) const {
  SectionElementVector ye, ydote;
  const Tri6& tri = mesh_.triangles[e];
  for (int s = 0; s < kSectionElementDofs; ++s) {
    const Index g = pattern_.global_dof(tri, s);
    ye(s) = y[g];
    ydote(s) = ydot[g];
  }
  const ElementCoefficients c =
      stabilisation_.coefficients(static_cast<std::size_t>(e), volume_rate_dt_);
  const MaterialLaws& laws = laws_of(e);
  try {
    std::visit(
        [&](const auto& solid, const auto& permeability) {
          section_element(geometry_[e], solid, permeability, c, ye, ydote, with_jacobian, out);
        },
        laws.solid, laws.permeability);
  } catch (const std::domain_error& err) {
    throw InvertedElement("triangle " + std::to_string(e) + ": " + err.what());
  }
}

void SectionProblem::assemble(double t, const double* y, const double* ydot, double* F) {
  std::fill(F, F + size(), 0.0);
  SectionElementOutput out;
  for (const Index e : elements_) {
    element(e, y, ydot, false, out);
    const Tri6& tri = mesh_.triangles[static_cast<std::size_t>(e)];
    for (int s = 0; s < kSectionElementDofs; ++s) F[pattern_.global_dof(tri, s)] += out.residual(s);
  }
  for (const NodalLoad& l : nodal_loads_) {
    const double scale = l.value * curve_value(l.curve, t);
    for (const auto& [row, amount] : l.entries) F[row] += scale * amount;
  }
  add_volume_loads(t, false, F);
}

void SectionProblem::residual(double t, const double* y, const double* ydot, double* F) {
  const auto t0 = Clock::now();
  assemble(t, y, ydot, F);
  platens_.residual(t, y, F);
  for (const Dirichlet& d : dirichlet_)
    F[d.dof] = dirichlet_scale(d) * (y[d.dof] - dirichlet_value(d, t));
  ++stats_.residual_evaluations;
  stats_.residual_seconds += seconds_since(t0);
}

std::pair<double, double> SectionProblem::field_norms(const double* F) const {
  return detail::free_row_norms(F, constrained_, num_u());
}

void SectionProblem::time_derivative(double t, double* dFdt) const {
  std::fill(dFdt, dFdt + size(), 0.0);
  for (const NodalLoad& l : nodal_loads_) {
    if (!l.curve) continue;
    const double rate = l.value * l.curve->slope(t);
    for (const auto& [row, amount] : l.entries) dFdt[row] += rate * amount;
  }
  add_volume_loads(t, true, dFdt);
  platens_.time_derivative(t, dFdt);
  for (const Dirichlet& d : dirichlet_) dFdt[d.dof] = -dirichlet_scale(d) * dirichlet_rate(d, t);
}

void SectionProblem::jacobian(double /*t*/, const double* y, const double* ydot, double cj,
                              double* values, double* rate_values) {
  const auto t0 = Clock::now();
  std::fill(values, values + pattern_.nnz(), 0.0);
  if (rate_values) std::fill(rate_values, rate_values + pattern_.nnz(), 0.0);
  SectionElementOutput out;
  for (const Index el : elements_) {
    const Tri6& tri = mesh_.triangles[static_cast<std::size_t>(el)];
    element(el, y, ydot, true, out);
    pattern_.scatter(el, tri, out.dfdy, out.dfdydot, cj, dirichlet_held_, values);
    if (rate_values)
      pattern_.scatter(el, tri, out.dfdydot, out.dfdydot, 0.0, dirichlet_held_, rate_values);
  }
  platens_.jacobian(values, rate_values);
  for (const Dirichlet& d : dirichlet_) values[pattern_.find(d.dof, d.dof)] = dirichlet_scale(d);
  ++stats_.jacobian_evaluations;
  stats_.jacobian_seconds += seconds_since(t0);
}

std::vector<std::array<double, 3>> SectionProblem::reactions(
    const std::vector<std::string>& boundaries, double t, const double* y, const double* ydot) {
  const auto rows = detail::reaction_rows(held_rows_, boundaries, "curve");
  std::vector<double> F(static_cast<std::size_t>(size()));
  assemble(t, y, ydot, F.data());
  return detail::sum_reactions(rows, F, 2);
}

FluidRates SectionProblem::fluid_rates(double t, const double* y, const double* ydot) {
  std::vector<double> F(static_cast<std::size_t>(size()));
  assemble(t, y, ydot, F.data());
  FluidRates out;
  for (const Dirichlet& d : dirichlet_)
    if (d.dof >= num_u()) out.drained -= F[d.dof];
  for (const NodalLoad& l : nodal_loads_) {
    const double scale = l.value * curve_value(l.curve, t);
    for (const auto& [row, amount] : l.entries)
      if (row >= num_u()) out.prescribed += scale * amount;
  }
  if (source_) {
    std::vector<double> s(static_cast<std::size_t>(size()), 0.0);
    add_volume_loads(t, false, s.data());
    for (Index i = num_u(); i < size(); ++i) out.source -= s[i];
  }
  return out;
}

double SectionProblem::volume_change(const double* y) const {
  double sum = 0.0;
  for (const Index e : elements_) {
    const Tri6& tri = mesh_.triangles[static_cast<std::size_t>(e)];
    Eigen::Matrix<double, 2, 6> u;
    for (int a = 0; a < 6; ++a)
      for (int i = 0; i < 2; ++i) u(i, a) = y[pattern_.u_dof(tri[a], i)];
    for (const SectionPointGeometry& g : geometry_[static_cast<std::size_t>(e)]) {
      // J − 1 = det(I + H) − 1 = (tr H₂ + det H₂)(1 + h) + h, H₂ the in-plane block, h the hoop
      // strain u_r/R: no cancellation at small strain.
      const Eigen::Matrix2d H = u * g.dN;
      const double hoop = g.inverse_radius * u.row(0).dot(g.N.transpose());
      const double plane = H.trace() + H.determinant();
      sum += g.weight * (plane * (1.0 + hoop) + hoop);
    }
  }
  return sum;
}

double SectionProblem::gls_time_scale() const {
  double time = 0.0;
  for (const Index e : elements_) {
    const double ce = gls_coefficient(e);
    if (!(ce > 0.0)) continue;
    const double te = ce / laws_of(e).p_wave_modulus();
    if (time == 0.0 || te < time) time = te;
  }
  return time;
}

void SectionProblem::pressure_schur_term(double cj, double cj_gls,
                                         std::vector<PressureEntry>& out) const {
  out.reserve(out.size() + 9 * elements_.size());
  for (const Index e : elements_) {
    const double w = cj / (laws_of(e).p_wave_modulus() + cj_gls * gls_coefficient(e));
    // P1 mass matrix with the element's own measure: ∫ N^p_a N^p_b dΩ₀ by its quadrature rule.
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    for (const SectionPointGeometry& g : geometry_[static_cast<std::size_t>(e)])
      M += g.weight * g.Np * g.Np.transpose();
    const Tri6& tri = mesh_.triangles[static_cast<std::size_t>(e)];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) out.push_back({tri[a], tri[b], w * M(a, b)});
  }
}

SaddlePointStructure SectionProblem::saddle_point_structure(
    std::function<std::pair<double, double>()> shifts) const {
  SaddlePointStructure s;
  s.num_u = num_u();
  s.components = 2;
  s.constrained = constrained_;
  s.schur_term = [this, shifts = std::move(shifts)](std::vector<PressureEntry>& out) {
    const auto [cj, cj_gls] = shifts();
    pressure_schur_term(cj, cj_gls, out);
  };
  return s;
}

}  // namespace biphasic
