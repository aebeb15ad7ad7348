#include "biphasic/physics/biphasic_problem.hpp"

#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "biphasic/assembly/colouring.hpp"
#include "biphasic/assembly/threads.hpp"
#include "biphasic/fe/tet_geometry.hpp"
#include "biphasic/physics/boundary_integrals.hpp"
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

Vec3 node_vec(const Mesh& mesh, Index n) {
  return {mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]};
}

TetCorners corners(const Mesh& mesh, const Tet10& t) {
  return {node_vec(mesh, t[0]), node_vec(mesh, t[1]), node_vec(mesh, t[2]), node_vec(mesh, t[3])};
}

double element_length(const TetCorners& x, ElementLength choice) {
  switch (choice) {
    case ElementLength::Circumradius:
      return tet_circumradius(x);
    case ElementLength::ShortestEdge:
      return tet_shortest_edge(x);
    case ElementLength::LongestEdge:
      return tet_longest_edge(x);
    case ElementLength::VolumeDiameter:
      return tet_volume_diameter(x);
  }
  return 0.0;
}

/// Axis (0, 1, 2) normal to every face of a plane boundary; throws otherwise.
int plane_axis(const Mesh& mesh, const Boundary& b, const std::string& label) {
  int axis = -1;
  for (std::size_t f = 0; f < b.faces.size(); ++f) {
    const Vec3 x0 = node_vec(mesh, b.faces[f][0]);
    const Vec3 n =
        (node_vec(mesh, b.faces[f][1]) - x0).cross(node_vec(mesh, b.faces[f][2]) - x0).normalized();
    int best = 0;
    n.cwiseAbs().maxCoeff(&best);
    if (std::abs(n(best)) < 1.0 - 1e-8 || (axis >= 0 && best != axis)) {
      std::ostringstream msg;
      msg << label << ": symmetry needs a plane normal to x, y or z; face " << f << " has normal ("
          << n(0) << ", " << n(1) << ", " << n(2) << ")";
      throw std::runtime_error(msg.str());
    }
    axis = best;
  }
  return axis;
}

/// The solution's displacement [mm] and pressure [MPa] scales implied by the boundary data and
/// the solid's P-wave modulus HA [MPa].
std::pair<double, double> data_scales(const Vec3& body_extent, const Config& config, double HA) {
  const Vec3 extent = body_extent.cwiseMax(1e-300);
  double u = 0.0, p = 0.0;
  for (const BoundaryCondition& bc : config.bcs) {
    const double v = largest_value(bc, config.curves, config.time.t_end);
    switch (bc.type) {
      case BcType::Displacement:
        u = std::max(u, v);
        p = std::max(p, HA * v / extent(bc.component));
        break;
      case BcType::Pressure:
        p = std::max(p, v);
        break;
      case BcType::Traction:
      case BcType::NormalTraction:
        p = std::max(p, v);
        u = std::max(u, v / HA * extent.maxCoeff());
        break;
      case BcType::Symmetry:
      case BcType::Flux:
      case BcType::RigidPlaten:  // by RigidPlatens::raise_solution_scales
        break;
    }
  }
  return {u, p};
}

}  // namespace

BiphasicProblem::BiphasicProblem(const Mesh& mesh, const Config& config, AssemblyScope scope)
    : mesh_(mesh),
      curves_(config.curves),
      laws_{make_material_laws(config.material)},
      platens_(scope.platens ? RigidPlatens() : RigidPlatens(mesh, config, curves_)),
      pattern_(mesh, platens_.couplings()),
      colours_(colour_elements(mesh)) {
  const bool whole = scope.whole_mesh();
  if (!whole && !platens_.empty())
    throw std::runtime_error(
        "rigid_platen: a part of a partitioned mesh cannot pose platens of its own (the caller "
        "poses the whole mesh's: AssemblyScope::platens)");
  for (Index e = 0; e < static_cast<Index>(mesh.tets.size()); ++e)
    if (whole || scope.element_owned[static_cast<std::size_t>(e)]) elements_.push_back(e);
  if (!whole) {
    for (std::vector<Index>& colour : colours_)
      std::erase_if(colour,
                    [&](Index e) { return !scope.element_owned[static_cast<std::size_t>(e)]; });
    std::erase_if(colours_, [](const std::vector<Index>& c) { return c.empty(); });
  }
  // Face loads go to the rows of owned nodes only (row → node: u rows 3n + c, p rows by vertex).
  auto row_owned = [&](Index row) {
    if (whole) return true;
    const Index node = row < pattern_.num_u() ? row / 3 : row - pattern_.num_u();
    return scope.node_owned[static_cast<std::size_t>(node)] != 0;
  };
  // Reference geometry per element and quadrature point; GLS coefficients.
  const QuadratureRule rule = tet_quadrature(config.quadrature_points);
  for (const QuadraturePoint& qp : rule.points) point_p2_.push_back(p2_values(qp.xi));
  geometry_.resize(mesh.tets.size());
  const bool one_point_gls = config.stabilisation.gls_quadrature == GlsQuadrature::OnePoint;
  if (one_point_gls) gls_point_.resize(mesh.tets.size());
  const QuadratureRule centroid_rule = tet_quadrature(1);
  std::vector<PointGeometry> centroid;
  const AnyStabilisation stabilisation = make_stabilisation(config.stabilisation.type);
  const bool sized = describe(stabilisation).sized_by_element;
  stabilisation_.resize(mesh.tets.size());
  const StabilisationContext context = stabilisation_context(config.stabilisation, config.time.dt);
  // Material regions: each mesh region with a [[region]] entry gets its own laws; the others
  // use [material] (laws_[0]).
  std::vector<int> region_law(mesh.region_names.size(), 0);
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r)
    for (const RegionConfig& entry : config.regions)
      if (entry.name == mesh.region_names[r]) {
        region_law[r] = static_cast<int>(laws_.size());
        laws_.push_back(make_material_laws(entry.material));
      }
  for (const RegionConfig& entry : config.regions)
    if (mesh.find_region(entry.name) < 0)
      throw std::runtime_error("region '" + entry.name + "': the mesh has no region of that name");
  if (laws_.size() > 1) {
    element_law_.resize(mesh.tets.size());
    for (std::size_t e = 0; e < mesh.tets.size(); ++e)
      element_law_[e] = region_law[static_cast<std::size_t>(mesh.region_of(static_cast<Index>(e)))];
  }
  // Scales of the whole problem (Dirichlet rows, solution scales, stiffness and conductance
  // scales): the largest H_A and the largest k(1) over the law sets some element uses. A row
  // scale or tolerance scale only needs the magnitude of the largest diagonal entries, which the
  // stiffest and most permeable material sets; with one material these are its H_A and k(1).
  std::vector<char> used(laws_.size(), 0);
  if (element_law_.empty()) {
    used[0] = 1;
  } else if (whole) {
    for (const int l : element_law_) used[static_cast<std::size_t>(l)] = 1;
  } else {
    for (std::size_t r = 0; r < region_law.size(); ++r)
      if (scope.region_used[r]) used[static_cast<std::size_t>(region_law[r])] = 1;
  }
  double HA = 0.0, k_ref = 0.0;
  for (std::size_t l = 0; l < laws_.size(); ++l)
    if (used[l]) {
      HA = std::max(HA, laws_[l].p_wave_modulus());
      k_ref = std::max(k_ref, laws_[l].reference_permeability());
    }
  modulus_ = HA;
  double mean_length = 0.0;
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    Eigen::Matrix<double, 10, 3> X;
    for (int a = 0; a < 10; ++a) X.row(a) = node_vec(mesh, mesh.tets[e][a]).transpose();
    try {
      element_point_geometry(X, rule, geometry_[e]);
      if (one_point_gls) {
        element_point_geometry(X, centroid_rule, centroid);
        gls_point_[e] = centroid.front();
      }
    } catch (const std::domain_error& err) {
      throw std::runtime_error("element " + std::to_string(e) + ": " + err.what());
    }
    const TetCorners x = corners(mesh, mesh.tets[e]);
    mean_length += tet_volume_diameter(x);
    if (sized) {
      const double h = element_length(x, config.stabilisation.length);
      // Each element's own material (c_e from its k(1), β from its H_A).
      const MaterialLaws& laws = laws_of(static_cast<Index>(e));
      stabilisation_.set(
          e, element_coefficients(stabilisation, config.stabilisation.scale * h * h, laws, context),
          laws);
    }
  }
  stabilisation_.finish();  // a term no element has is absent (has_gls(), ...)
  mean_length /= static_cast<double>(std::max<std::size_t>(1, mesh.tets.size()));
  if (!whole) mean_length = scope.mean_element_length;
  row_scale_u_ = HA * mean_length;
  row_scale_p_ = k_ref * mean_length;

  // Boundary conditions by physical-group name.
  DirichletRows rows_held(pattern_.size());
  const auto label = [&](std::size_t i) { return bc_label(i, config.bcs[i]); };
  auto constrain = [&](std::size_t i, Index dof, double value, const LoadCurve* curve, Index node,
                       int field) {
    rows_held.add(i, {dof, value, curve, node, field}, label, "dof " + std::to_string(dof));
  };
  // Opposite corner of each boundary face's tetrahedron (built on first use) orients normals.
  std::map<std::array<Index, 3>, Index> face_opposite;
  auto opposite_vertex = [&](const Tri6& f) {
    if (face_opposite.empty()) {
      for (const Tet10& t : mesh.tets)
        for (int skip = 0; skip < 4; ++skip) {
          std::array<Index, 3> key{};
          for (int a = 0, m = 0; a < 4; ++a)
            if (a != skip) key[m++] = t[a];
          std::sort(key.begin(), key.end());
          face_opposite[key] = t[skip];
        }
    }
    std::array<Index, 3> key{f[0], f[1], f[2]};
    std::sort(key.begin(), key.end());
    return face_opposite.at(key);
  };
  for (std::size_t i = 0; i < config.bcs.size(); ++i) {
    const BoundaryCondition& bc = config.bcs[i];
    const auto target = detail::resolve_condition(
        i, bc, mesh, curves_, "the mesh has no boundary of that name",
        "only displacement conditions apply to a physical point or curve");
    const Boundary* b = target.boundary;
    const LoadCurve* curve = target.curve;
    const std::set<Index>& nodes = target.nodes;
    const std::set<Index>& vertices = target.vertices;
    switch (bc.type) {
      case BcType::Displacement:
      case BcType::Symmetry: {
        const bool symmetry = bc.type == BcType::Symmetry;
        const int axis = symmetry ? plane_axis(mesh, *b, bc_label(i, bc)) : bc.component;
        std::vector<Index>& held = held_rows_[bc.boundary];
        for (Index n : nodes) {
          const Index dof = pattern_.u_dof(n, axis);
          constrain(i, dof, symmetry ? 0.0 : bc.value, symmetry ? nullptr : curve, n,
                    symmetry ? kHeldAtZero : axis);
          held.push_back(dof);
        }
        break;
      }
      case BcType::Pressure:
        for (Index v : vertices)
          constrain(i, pattern_.p_dof(v), bc.value, curve, v, kPressureField);
        break;
      case BcType::Flux:
      case BcType::Traction:
      case BcType::NormalTraction: {
        std::map<Index, double> load;
        for (const Tri6& f : b->faces) {
          Eigen::Matrix<double, 6, 3> X;
          for (int a = 0; a < 6; ++a) X.row(a) = node_vec(mesh, f[a]).transpose();
          if (bc.type == BcType::Flux) {
            // R_p += ∫ g q̄ dA
            const Eigen::Vector3d q = face_p1_integrals(X);
            for (int c = 0; c < 3; ++c) load[pattern_.p_dof(f[c])] += q(c);
          } else {
            // R_u −= ∫ f · t̄ dA (nominal, dead load)
            Eigen::Matrix<double, 6, 3> r;
            if (bc.type == BcType::Traction) {
              const Vec3 t(bc.vector[0], bc.vector[1], bc.vector[2]);
              r = -face_p2_integrals(X) * t.transpose();
            } else {
              const Vec3 inward = node_vec(mesh, opposite_vertex(f)) - X.row(0).transpose();
              // t̄ = −value N: −∫ N_a t̄ dA = value ∫ N_a N dA (value applied below)
              r = face_normal_integrals(X, inward);
            }
            for (int a = 0; a < 6; ++a)
              for (int c = 0; c < 3; ++c) load[pattern_.u_dof(f[a], c)] += r(a, c);
          }
        }
        NodalLoad nl{{}, bc.type == BcType::Traction ? 1.0 : bc.value, curve};
        for (const auto& entry : load)
          if (row_owned(entry.first)) nl.entries.push_back(entry);
        nodal_loads_.push_back(std::move(nl));
        break;
      }
      case BcType::RigidPlaten:  // platens_, or the caller's (scope.platens): reaction rows
        if (scope.platens) {
          std::vector<Index>& held = held_rows_[bc.boundary];
          for (Index n : nodes) held.push_back(pattern_.u_dof(n, bc.component));
        }
        break;
    }
  }
  dirichlet_ = std::move(rows_held.rows());
  dirichlet_held_ = std::move(rows_held.constrained());
  constrained_ = platens_.tie(dirichlet_held_, pattern_, row_scale_u_, config.bcs, held_rows_);
  const auto [lower, upper] = whole ? bounding_box(mesh) : std::pair{scope.lower, scope.upper};
  const Vec3 extent(upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]);
  solution_scales_ = data_scales(extent, config, modulus_);
  if (!platens_.empty())
    platens_.raise_solution_scales(config, modulus_, extent.data(), solution_scales_);
  if (scope.platens)
    scope.platens->raise_solution_scales(config, modulus_, extent.data(), solution_scales_);
  for (auto& [name, rows] : held_rows_) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  }

  // Body force and fluid source formulas of the case, with their exact t-derivatives.
  const auto& bf = config.loads.body_force;
  const Expression& source = config.loads.fluid_source;
  if (!(bf[0].is_zero() && bf[1].is_zero() && bf[2].is_zero() && source.is_zero())) {
    check_load_formulas(config, 0.0);
    check_load_formulas(config, config.time.t_end);
  }
  if (!(bf[0].is_zero() && bf[1].is_zero() && bf[2].is_zero())) {
    using V = Expression::Variable;
    auto field = [](std::array<Expression, 3> f) {
      return [f](const Vec3& X, double t) {
        return Vec3(f[0](X(0), X(1), X(2), t), f[1](X(0), X(1), X(2), t),
                    f[2](X(0), X(1), X(2), t));
      };
    };
    set_body_force(field(bf),
                   field({bf[0].derivative(V::T), bf[1].derivative(V::T), bf[2].derivative(V::T)}));
  }
  if (!source.is_zero()) {
    auto field = [](Expression f) {
      return [f](const Vec3& X, double t) { return f(X(0), X(1), X(2), t); };
    };
    set_fluid_source(field(source), field(source.derivative(Expression::Variable::T)));
  }
}

void BiphasicProblem::check_load_formulas(const Config& config, double t) const {
  const auto& loads = config.loads;
  for (const Index e : elements_)
    for (std::size_t q = 0; q < point_p2_.size(); ++q) {
      const Vec3 X = point_position(e, q);
      for (int c = 0; c < 4; ++c) {
        const Expression& f = c < 3 ? loads.body_force[c] : loads.fluid_source;
        const double v = f(X(0), X(1), X(2), t);
        if (std::isfinite(v)) continue;
        std::ostringstream msg;
        msg << (c < 3 ? std::string("body_force.") + "xyz"[c] : std::string("fluid_source.value"))
            << " = \"" << f.text() << "\" is "
            << (std::isnan(v) ? "NaN"
                : v > 0       ? "+inf"
                              : "-inf")
            << " at X = (" << X(0) << ", " << X(1) << ", " << X(2) << ") mm, t = " << t
            << " s (a quadrature point of element " << e << ")";
        throw std::runtime_error(msg.str());
      }
    }
}

Vec3 BiphasicProblem::point_position(Index e, std::size_t q) const {
  Vec3 X = Vec3::Zero();
  for (int a = 0; a < 10; ++a) X += point_p2_[q](a) * node_vec(mesh_, mesh_.tets[e][a]);
  return X;
}

void BiphasicProblem::set_body_force(VectorField b, VectorField rate) {
  loads_.b = std::move(b);
  loads_.b_rate = loads_.b ? std::move(rate) : VectorField{};
  load_cache_.clear();
}

void BiphasicProblem::set_fluid_source(ScalarField s, ScalarField rate) {
  loads_.s = std::move(s);
  loads_.s_rate = loads_.s ? std::move(rate) : ScalarField{};
  load_cache_.clear();
}

void BiphasicProblem::set_dirichlet_fields(VectorField u, ScalarField p, VectorField u_rate,
                                           ScalarField p_rate) {
  dirichlet_fields_.u = std::move(u);
  dirichlet_fields_.u_rate = dirichlet_fields_.u ? std::move(u_rate) : VectorField{};
  dirichlet_fields_.p = std::move(p);
  dirichlet_fields_.p_rate = dirichlet_fields_.p ? std::move(p_rate) : ScalarField{};
}

double BiphasicProblem::dirichlet_value(const Dirichlet& d, double t) const {
  const DirichletFields& f = dirichlet_fields_;
  if (d.field >= 0 && d.field < 3 && f.u) return f.u(node_vec(mesh_, d.node), t)(d.field);
  if (d.field == kPressureField && f.p) return f.p(node_vec(mesh_, d.node), t);
  return d.value * curve_value(d.curve, t);
}

double BiphasicProblem::dirichlet_rate(const Dirichlet& d, double t) const {
  const DirichletFields& f = dirichlet_fields_;
  const Vec3 X = node_vec(mesh_, d.node);
  if (d.field >= 0 && d.field < 3 && f.u)
    return (f.u_rate ? f.u_rate(X, t) : central_rate(f.u, X, t))(d.field);
  if (d.field == kPressureField && f.p) return f.p_rate ? f.p_rate(X, t) : central_rate(f.p, X, t);
  return d.curve ? d.value * d.curve->slope(t) : 0.0;
}

void BiphasicProblem::add_volume_loads(double t, bool rate, double* out) const {
  const VolumeLoads& L = loads_;
  if (!L.b && !L.s) return;
  for (const Index e : elements_) {
    const Tet10& tet = mesh_.tets[static_cast<std::size_t>(e)];
    for (std::size_t q = 0; q < point_p2_.size(); ++q) {
      const PointGeometry& g = geometry_[static_cast<std::size_t>(e)][q];
      const Vec3 X = point_position(e, q);
      if (L.b) {
        const Vec3 b = !rate ? L.b(X, t) : L.b_rate ? L.b_rate(X, t) : central_rate(L.b, X, t);
        for (int a = 0; a < 10; ++a)
          for (int i = 0; i < 3; ++i)
            out[pattern_.u_dof(tet[a], i)] -= g.weight * point_p2_[q](a) * b(i);
      }
      if (L.s) {
        const double s = !rate ? L.s(X, t) : L.s_rate ? L.s_rate(X, t) : central_rate(L.s, X, t);
        for (int c = 0; c < 4; ++c) out[pattern_.p_dof(tet[c])] -= g.weight * g.Np(c) * s;
      }
    }
  }
}

std::vector<double> BiphasicProblem::breakpoints() const { return detail::curve_kinks(curves_); }

void BiphasicProblem::apply_dirichlet(double t, double* y, double* ydot) const {
  for (const Dirichlet& d : dirichlet_) {
    y[d.dof] = dirichlet_value(d, t);
    if (ydot) ydot[d.dof] = dirichlet_rate(d, t);
  }
  platens_.apply(y, ydot);
}

void BiphasicProblem::gather(Index e, const double* y, const double* ydot, ElementVector& ye,
                             ElementVector& ydote) const {
  const Tet10& tet = mesh_.tets[e];
  for (int s = 0; s < kElementDofs; ++s) {
    const Index g = pattern_.global_dof(tet, s);
    ye(s) = y[g];
    ydote(s) = ydot[g];
  }
}

void BiphasicProblem::element(Index e, const double* y, const double* ydot, bool with_jacobian,
                              ElementOutput& out) const {
  ElementVector ye, ydote;
  gather(e, y, ydot, ye, ydote);
  const ElementCoefficients c =
      stabilisation_.coefficients(static_cast<std::size_t>(e), volume_rate_dt_);
  const MaterialLaws& laws = laws_of(e);
  try {
    std::visit(
        [&](const auto& solid, const auto& permeability) {
          biphasic_element(geometry_[e], solid, permeability, c, ye, ydote, with_jacobian, out,
                           gls_point_.empty() ? nullptr : &gls_point_[e]);
        },
        laws.solid, laws.permeability);
  } catch (const std::domain_error& err) {
    throw InvertedElement("element " + std::to_string(e) + ": " + err.what());
  }
}

template <class Work>
void BiphasicProblem::for_each_element(bool with_jacobian, const double* y, const double* ydot,
                                       Work&& work) {
  // The first exception of any thread, rethrown after the loop (none may leave an OpenMP
  // region: that would end the program in std::terminate).
  std::exception_ptr failure;
  static const int threads = worker_threads();
  for (const std::vector<Index>& colour : colours_) {
    const auto count = static_cast<std::ptrdiff_t>(colour.size());
#pragma omp parallel num_threads(threads)
    {
      ElementOutput out;
#pragma omp for schedule(static)
      for (std::ptrdiff_t i = 0; i < count; ++i) {
        const Index e = colour[i];
        try {
          element(e, y, ydot, with_jacobian, out);
          work(e, out);
        } catch (...) {
#pragma omp critical(biphasic_assembly_failure)
          if (!failure) failure = std::current_exception();
        }
      }
    }
    if (failure) std::rethrow_exception(failure);
  }
}

void BiphasicProblem::assemble(double t, const double* y, const double* ydot, double* F) {
  // Each thread adds its share of the elements into its own vector; the vectors are summed
  // into F. Two barriers per residual, where the coloured loop of the Jacobian needs one per
  // colour.
  static const int threads = worker_threads();
  const auto n = static_cast<std::ptrdiff_t>(size());
  const auto num_elements = static_cast<std::ptrdiff_t>(elements_.size());
  thread_residuals_.resize(static_cast<std::size_t>(threads));
  std::exception_ptr failure;  // the first of any thread, rethrown after the parallel region
#pragma omp parallel num_threads(threads)
  {
    const int me = omp_get_thread_num();
    const int team = omp_get_num_threads();
    std::vector<double>& mine = thread_residuals_[static_cast<std::size_t>(me)];
    mine.assign(static_cast<std::size_t>(n), 0.0);
    ElementOutput out;
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < num_elements; ++i) {
      try {
        const Index e = elements_[static_cast<std::size_t>(i)];
        element(e, y, ydot, false, out);
        const Tet10& tet = mesh_.tets[static_cast<std::size_t>(e)];
        for (int s = 0; s < kElementDofs; ++s) mine[pattern_.global_dof(tet, s)] += out.residual(s);
      } catch (...) {
#pragma omp critical(biphasic_assembly_failure)
        if (!failure) failure = std::current_exception();
      }
    }
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      double sum = 0.0;
      for (int k = 0; k < team; ++k) sum += thread_residuals_[static_cast<std::size_t>(k)][i];
      F[i] = sum;
    }
  }
  if (failure) std::rethrow_exception(failure);
  for (const NodalLoad& l : nodal_loads_) {
    const double scale = l.value * curve_value(l.curve, t);
    for (const auto& [row, amount] : l.entries) F[row] += scale * amount;
  }
  if (loads_.b || loads_.s) {
    // The volume loads do not depend on y: computed once per time, reused by the Newton
    // iterations at that time.
    if (load_cache_.empty() || load_cache_t_ != t) {
      load_cache_.assign(size(), 0.0);
      add_volume_loads(t, false, load_cache_.data());
      load_cache_t_ = t;
    }
    for (Index i = 0; i < size(); ++i) F[i] += load_cache_[i];
  }
}

std::vector<std::array<double, 3>> BiphasicProblem::reactions(
    const std::vector<std::string>& boundaries, double t, const double* y, const double* ydot) {
  const auto rows = detail::reaction_rows(held_rows_, boundaries, "boundary");
  std::vector<double> F(static_cast<std::size_t>(size()));
  assemble(t, y, ydot, F.data());
  return detail::sum_reactions(rows, F, 3);
}

std::vector<std::string> BiphasicProblem::reaction_labels(
    const std::vector<std::string>& boundaries) {
  std::vector<std::string> labels = boundaries;
  if (boundaries.size() >= 2) labels.push_back(kReactionTotal);
  return labels;
}

BiphasicProblem::FluidRates BiphasicProblem::fluid_rates(double t, const double* y,
                                                         const double* ydot) {
  std::vector<double> F(size());
  assemble(t, y, ydot, F.data());  // also refreshes load_cache_ for t
  FluidRates out;
  for (const Dirichlet& d : dirichlet_)
    if (d.dof >= num_u()) out.drained -= F[d.dof];
  for (const NodalLoad& l : nodal_loads_) {
    const double scale = l.value * curve_value(l.curve, t);
    for (const auto& [row, amount] : l.entries)
      if (row >= num_u()) out.prescribed += scale * amount;  // R_p += ∫ g q̄ dA
  }
  if (loads_.s)
    for (Index i = num_u(); i < size(); ++i) out.source -= load_cache_[i];  // R_p −= ∫ g s dX
  return out;
}

double BiphasicProblem::volume_change(const double* y) const {
  double sum = 0.0;
  for (const Index e : elements_) {
    Eigen::Matrix<double, 3, 10> u;
    for (int a = 0; a < 10; ++a)
      for (int i = 0; i < 3; ++i) u(i, a) = y[pattern_.u_dof(mesh_.tets[e][a], i)];
    for (const PointGeometry& g : geometry_[e]) {
      // J − 1 without cancellation: det(I + H) − 1 = tr H + ½((tr H)² − tr H²) + det H.
      const Mat3 H = u * g.dN;
      const double tr = H.trace();
      sum += g.weight * (tr + 0.5 * (tr * tr - (H * H).trace()) + H.determinant());
    }
  }
  return sum;
}

void BiphasicProblem::set_conservative_volume_rate(double dt) {
  volume_rate_dt_ = detail::checked_volume_rate_dt(dt);
}

void BiphasicProblem::residual(double t, const double* y, const double* ydot, double* F) {
  const auto t0 = Clock::now();
  assemble(t, y, ydot, F);
  platens_.residual(t, y, F);
  for (const Dirichlet& d : dirichlet_)
    F[d.dof] = dirichlet_scale(d) * (y[d.dof] - dirichlet_value(d, t));
  ++stats_.residual_evaluations;
  stats_.residual_seconds += seconds_since(t0);
}

std::pair<double, double> BiphasicProblem::field_norms(const double* F) const {
  return detail::free_row_norms(F, constrained_, num_u());
}

void BiphasicProblem::time_derivative(double t, double* dFdt) const {
  std::fill(dFdt, dFdt + size(), 0.0);
  for (const NodalLoad& l : nodal_loads_) {
    if (!l.curve) continue;
    const double rate = l.value * l.curve->slope(t);
    for (const auto& [row, amount] : l.entries) dFdt[row] += rate * amount;
  }
  add_volume_loads(t, true, dFdt);
  platens_.time_derivative(t, dFdt);
  // Every Dirichlet row, also those without a curve: loads on their nodes do not reach them.
  for (const Dirichlet& d : dirichlet_) dFdt[d.dof] = -dirichlet_scale(d) * dirichlet_rate(d, t);
}

void BiphasicProblem::jacobian(double /*t*/, const double* y, const double* ydot, double cj,
                               double* values, double* rate_values) {
  const auto t0 = Clock::now();
  std::fill(values, values + pattern_.nnz(), 0.0);
  if (rate_values) std::fill(rate_values, rate_values + pattern_.nnz(), 0.0);
  for_each_element(true, y, ydot, [&](Index e, const ElementOutput& out) {
    pattern_.scatter(e, mesh_.tets[e], out.dfdy, out.dfdydot, cj, dirichlet_held_, values);
    if (rate_values)
      pattern_.scatter(e, mesh_.tets[e], out.dfdydot, out.dfdydot, 0.0, dirichlet_held_,
                       rate_values);
  });
  platens_.jacobian(values, rate_values);
  for (const Dirichlet& d : dirichlet_) values[pattern_.find(d.dof, d.dof)] = dirichlet_scale(d);
  ++stats_.jacobian_evaluations;
  stats_.jacobian_seconds += seconds_since(t0);
}

double BiphasicProblem::gls_time_scale() const {
  // min_e c_e / H_A(e), each element with its own material's H_A.
  double time = 0.0;
  if (!has_gls()) return 0.0;
  for (const Index e : elements_) {
    const double ce = gls_coefficient(e);
    if (!(ce > 0.0)) continue;
    const double te = ce / laws_of(e).p_wave_modulus();
    if (time == 0.0 || te < time) time = te;
  }
  return time;
}

void BiphasicProblem::pressure_schur_term(double cj, double cj_gls,
                                          std::vector<PressureEntry>& out) const {
  out.reserve(out.size() + 16 * elements_.size());
  for (const Index e : elements_) {
    // Each element's own H_A: the div–div stiffness its pressure modes see.
    const double modulus = laws_of(e).p_wave_modulus();
    double volume = 0.0;
    for (const PointGeometry& g : geometry_[static_cast<std::size_t>(e)]) volume += g.weight;
    const double w = cj / (modulus + cj_gls * gls_coefficient(e));
    const Tet10& tet = mesh_.tets[static_cast<std::size_t>(e)];
    // P1 mass matrix of a tetrahedron: V/20 (1 + δ_ab).
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        out.push_back({tet[a], tet[b], w * volume / 20.0 * (a == b ? 2.0 : 1.0)});
  }
}

SaddlePointStructure BiphasicProblem::saddle_point_structure(
    std::function<std::pair<double, double>()> shifts) const {
  SaddlePointStructure s;
  s.num_u = num_u();
  s.constrained = constrained_;
  s.schur_term = [this, shifts = std::move(shifts)](std::vector<PressureEntry>& out) {
    const auto [cj, cj_gls] = shifts();
    pressure_schur_term(cj, cj_gls, out);
  };
  return s;
}

}  // namespace biphasic
