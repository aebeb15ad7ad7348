// The semidiscrete biphasic system F(t, y, ẏ) = 0 of a two-dimensional model (plane strain or
// axisymmetric) on a P2/P1 triangle mesh: the SemidiscreteSystem both time integrators drive,
// the counterpart of BiphasicProblem for a SectionMesh (docs/two_dimensional_models.md).
//
// Unknowns: y = (u of every node, 2n + c with c = 0 for x or r and 1 for y or z; then p of
// every vertex). Boundary conditions come from the case's [[boundary]] entries by curve name
// (or physical point): displacement (component 0 or 1), symmetry (a straight curve normal to
// x/r or y/z), pressure, flux, traction (vector (t₀, t₁)) and normal traction. Axisymmetric
// models hold u_r = 0 at every node on the axis R = 0 themselves (the field is regular there
// only then). Forces are per mm of thickness in plane strain [N/mm] and over the full circle
// when axisymmetric [N]; volume rates likewise [mm²/s] or [mm³/s].
#pragma once

#include <array>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/assembly/sparsity.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/material/material_laws.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/assembly_scope.hpp"
#include "biphasic/physics/biphasic_model.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/dirichlet_rows.hpp"
#include "biphasic/physics/element_stabilisation.hpp"
#include "biphasic/physics/rigid_platen.hpp"
#include "biphasic/physics/section_element.hpp"
#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

/// The section model of a two-dimensional ModelKind; throws std::invalid_argument for the
/// three-dimensional one.
inline SectionModel section_model(ModelKind kind) {
  if (kind == ModelKind::Axisymmetric) return SectionModel::Axisymmetric;
  if (kind == ModelKind::PlaneStrain) return SectionModel::PlaneStrain;
  throw std::invalid_argument("section_model: the three-dimensional model has no section");
}

/// Mean depth of the measure over the mesh [mm]: Σ measure / Σ area, 1 in plane strain, 2πR̄
/// axisymmetric (R̄ the area-weighted mean radius). What a momentum row's diagonal scales with.
double section_mean_depth(const SectionMesh& mesh, SectionModel model);

class SectionProblem final : public BiphasicModel {
 public:
  /// Resolves the boundary conditions by name, builds the geometry and the pattern, and takes
  /// the body force and fluid source formulas of config.loads (of X = (x, y, 0) or (r, z, 0);
  /// body_force.z must be zero). Throws std::runtime_error naming the boundary condition or
  /// the element on inconsistent input. With a `scope`, the mesh is one part's view of a
  /// partitioned mesh and the problem assembles that part's share (physics/assembly_scope.hpp),
  /// as BiphasicProblem does.
  SectionProblem(const SectionMesh& mesh, SectionModel model, const Config& config,
                 AssemblyScope scope = {});
  /// The problem keeps a reference to its mesh: a temporary mesh would dangle.
  SectionProblem(SectionMesh&&, SectionModel, const Config&, AssemblyScope = {}) = delete;

  /// Body force b(X, t) [N/mm³] with X = (x, y, 0): the momentum rows gain −∫Ω₀ f·b dX (its
  /// third component is ignored). `rate` = ∂b/∂t (central differences without it).
  void set_body_force(VectorField b, VectorField rate = {});
  /// Fluid source s(X, t) [1/s]: the mass rows gain −∫Ω₀ g s dX.
  void set_fluid_source(ScalarField s, ScalarField rate = {});
  /// Dirichlet data from fields instead of value · curve(t), as BiphasicProblem's.
  void set_dirichlet_fields(VectorField u, ScalarField p, VectorField u_rate = {},
                            ScalarField p_rate = {});
  void set_conservative_volume_rate(double dt) override;

  const SectionMesh& mesh() const { return mesh_; }
  SectionModel model() const { return model_; }
  const SparsityPattern& pattern() const override { return pattern_; }
  /// The rigid platens under a prescribed force (physics/rigid_platen.hpp).
  const RigidPlatens& platens() const override { return platens_; }
  const std::vector<char>& constrained() const override { return constrained_; }

  void residual(double t, const double* y, const double* ydot, double* F) override;
  std::pair<double, double> field_norms(const double* F) const override;
  void time_derivative(double t, double* dFdt) const override;
  void jacobian(double t, const double* y, const double* ydot, double cj, double* values,
                double* rate_values = nullptr) override;
  void apply_dirichlet(double t, double* y, double* ydot) const override;
  std::vector<double> breakpoints() const override;

  /// The quadrature-point geometry of triangle e.
  const std::vector<SectionPointGeometry>& point_geometry(Index e) const { return geometry_[e]; }
  /// The material laws of triangle e (its region's [[region]] entry, or [material]).
  const MaterialLaws& laws_of(Index e) const override {
    return laws_[element_law_.empty() ? 0 : static_cast<std::size_t>(element_law_[e])];
  }
  /// The element kernel's output for triangle e at the global state.
  void element(Index e, const double* y, const double* ydot, bool with_jacobian,
               SectionElementOutput& out) const;

  /// Reaction forces at (t, y, ẏ), as BiphasicProblem::reactions: per named curve (or point)
  /// the sum of the momentum residual over the rows its displacement and symmetry conditions
  /// fix, components (x or r, y or z, 0); then the total over the union if two or more names.
  /// Axisymmetric: the force on the full circle [N] (the r component of a closed ring sums to
  /// zero physically; it is the net radial line load × 2πR). Plane strain: per mm [N/mm].
  std::vector<std::array<double, 3>> reactions(const std::vector<std::string>& boundaries, double t,
                                               const double* y, const double* ydot) override;
  /// Fluid rates as BiphasicProblem::fluid_rates.
  FluidRates fluid_rates(double t, const double* y, const double* ydot) override;
  /// ∫Ω₀ (J − 1) dX, the body's volume change [mm³] (per mm in plane strain).
  double volume_change(const double* y) const override;
  Index num_elements() const override { return static_cast<Index>(mesh_.triangles.size()); }

  double gls_coefficient(Index e) const override {
    return stabilisation_.gls_coefficient(static_cast<std::size_t>(e));
  }
  double flux_perturbation(Index e) const {
    return stabilisation_.flux_perturbation(static_cast<std::size_t>(e));
  }
  /// As BiphasicProblem::pressure_schur_term, with the P1 triangle mass matrices of the measure.
  void pressure_schur_term(double cj, double cj_gls, std::vector<PressureEntry>& out) const;
  SaddlePointStructure saddle_point_structure(
      std::function<std::pair<double, double>()> shifts) const override;

  double oedometric_modulus() const { return modulus_; }
  bool has_gls() const override { return stabilisation_.has_gls(); }
  bool has_flux_perturbation() const override { return stabilisation_.has_flux_perturbation(); }
  double gls_time_scale() const override;
  std::pair<double, double> solution_scales() const override { return solution_scales_; }
  AssemblyStats& stats() override { return stats_; }
  /// H_A × the mean depth of the measure (1 mm, or 2πR̄ axisymmetric) [N/mm]: the size of a
  /// momentum row's diagonal.
  double stiffness_scale() const override { return row_scale_u_; }
  /// k(1) × the mean depth [mm³/(s MPa)].
  double conductance_scale() const override { return row_scale_p_; }

 private:
  using Dirichlet = DirichletRow;
  struct NodalLoad {
    std::vector<std::pair<Index, double>> entries;  ///< (row, amount) added to F
    double value;
    const LoadCurve* curve;
  };
  void assemble(double t, const double* y, const double* ydot, double* F);
  void add_volume_loads(double t, bool rate, double* out) const;
  Vec3 point_position(Index e, std::size_t q) const;
  Vec3 node_position(Index n) const { return {mesh_.nodes[n][0], mesh_.nodes[n][1], 0.0}; }
  double curve_value(const LoadCurve* c, double t) const { return c ? c->value(t) : 1.0; }
  double dirichlet_value(const Dirichlet& d, double t) const;
  double dirichlet_rate(const Dirichlet& d, double t) const;
  double dirichlet_scale(const Dirichlet& d) const {
    return d.dof < num_u() ? row_scale_u_ : row_scale_p_;
  }

  const SectionMesh& mesh_;
  SectionModel model_;
  std::map<std::string, LoadCurve> curves_;
  std::vector<MaterialLaws> laws_;
  std::vector<int> element_law_;
  double modulus_ = 0.0;
  double volume_rate_dt_ = 0.0;
  std::vector<std::vector<SectionPointGeometry>> geometry_;
  std::vector<Index> elements_;  ///< the triangles assembled here (all, or a part's own)
  ElementStabilisation stabilisation_;
  RigidPlatens platens_;  ///< before pattern_: the pattern holds their couplings
  SparsityPattern pattern_;
  std::vector<Dirichlet> dirichlet_;
  std::vector<char> dirichlet_held_;  ///< the Dirichlet rows' unknowns (not assembled)
  std::vector<char> constrained_;     ///< Dirichlet and platen-tied unknowns
  std::map<std::string, std::vector<Index>> held_rows_;
  std::vector<NodalLoad> nodal_loads_;
  VectorField body_force_, body_force_rate_;
  ScalarField source_, source_rate_;
  VectorField dirichlet_u_, dirichlet_u_rate_;
  ScalarField dirichlet_p_, dirichlet_p_rate_;
  std::pair<double, double> solution_scales_{0.0, 0.0};
  double row_scale_u_ = 1.0, row_scale_p_ = 1.0;
  AssemblyStats stats_;
};

}  // namespace biphasic
