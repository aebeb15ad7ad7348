// The semidiscrete biphasic system F(t, y, ẏ) = 0 on a tetrahedral mesh (docs/formulation.md),
// with its Jacobian dF/dy + c_j dF/dẏ assembled into the fixed CSC pattern: the
// SemidiscreteSystem (time/semidiscrete_system.hpp) that both time integrators drive.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/assembly/sparsity.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/material/material_laws.hpp"
#include "biphasic/physics/assembly_scope.hpp"
#include "biphasic/physics/biphasic_element.hpp"
#include "biphasic/physics/biphasic_model.hpp"
#include "biphasic/physics/dirichlet_rows.hpp"
#include "biphasic/physics/element_stabilisation.hpp"
#include "biphasic/physics/rigid_platen.hpp"
#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

/// A scalar field of the reference position X [mm] and time t [s].
using ScalarField = std::function<double(const Vec3& X, double t)>;
/// A vector field of the reference position X [mm] and time t [s].
using VectorField = std::function<Vec3(const Vec3& X, double t)>;

class BiphasicProblem final : public BiphasicModel {
 public:
  /// Resolves boundary conditions by name, builds the geometry cache and the pattern, and
  /// takes the body force and fluid source formulas of config.loads (checked to be finite at
  /// every quadrature point at t = 0 and t = time.t_end). Throws std::runtime_error naming the
  /// boundary condition or the formula on inconsistent input. With a `scope`, the mesh is one
  /// part's view of a partitioned mesh and the problem assembles that part's share
  /// (physics/assembly_scope.hpp); rigid platens are then posed by the caller on the summed
  /// system (scope.platens), and refused without it.
  BiphasicProblem(const Mesh& mesh, const Config& config, AssemblyScope scope = {});
  /// The problem keeps a reference to its mesh: a temporary mesh would dangle.
  BiphasicProblem(Mesh&&, const Config&, AssemblyScope = {}) = delete;

  /// Body force b(X, t) per unit reference volume [N/mm³]: the momentum rows gain
  /// −∫Ω₀ f·b dX, integrated with the element's quadrature rule. `rate` is ∂b/∂t, used by
  /// time_derivative(); without it, a central difference in t with step 6e-6·max(1, |t|) s.
  /// Replaces the body force of the configuration; an empty `b` removes it. Called
  /// serially, at most once per residual time.
  void set_body_force(VectorField b, VectorField rate = {});
  /// Fluid source s(X, t) per unit reference volume [1/s]: the mass rows gain −∫Ω₀ g s dX
  /// (mass balance J̇ + Div W = s). `rate` as for set_body_force.
  void set_fluid_source(ScalarField s, ScalarField rate = {});
  /// Dirichlet data from fields instead of value · curve(t): an unknown fixed by a
  /// displacement condition takes its component of u(X, t) at its node, one fixed by a
  /// pressure condition p(X, t) at its vertex; symmetry conditions stay 0. Rates (ẏ of
  /// apply_dirichlet, ∂F/∂t) from `u_rate`, `p_rate`, or central differences as above. Empty
  /// fields restore value · curve(t) for that kind.
  void set_dirichlet_fields(VectorField u, ScalarField p, VectorField u_rate = {},
                            ScalarField p_rate = {});

  /// Backward Euler's conservative volume rate: from now on J̇ = (J − Jₙ)/Δt with
  /// uₙ = u − Δt u̇ in the mass rows and the GLS term (Δt = `dt` [s], the step about to be
  /// solved); `dt` = 0 restores J̇ = J F⁻ᵀ:∇₀u̇. Throws std::invalid_argument if dt < 0.
  void set_conservative_volume_rate(double dt) override;

  const Mesh& mesh() const { return mesh_; }
  const SparsityPattern& pattern() const override { return pattern_; }
  /// Unknowns fixed by Dirichlet conditions (their rows read s·(y_i − ḡ_i(t)) = 0) and tied to
  /// a rigid platen (s·(u_i − u_m) = 0).
  const std::vector<char>& constrained() const override { return constrained_; }
  /// The rigid platens under a prescribed force (physics/rigid_platen.hpp).
  const RigidPlatens& platens() const override { return platens_; }

  /// F(t, y, ẏ): momentum rows [N], mass rows [mm³/s], Dirichlet rows s·(y − ḡ(t)).
  void residual(double t, const double* y, const double* ydot, double* F) override;
  /// ‖F‖_∞ over the free momentum rows [N] and over the free mass rows [mm³/s].
  std::pair<double, double> field_norms(const double* F) const override;
  /// ∂F/∂t at fixed (y, ẏ): the rates of the boundary values and loads (right derivatives of
  /// the load curves at t), body force and fluid source included.
  void time_derivative(double t, double* dFdt) const override;
  /// dF/dy + c_j dF/dẏ into the pattern's value array (size nnz); if `rate_values` is given,
  /// dF/dẏ alone into it (same pattern; zero on Dirichlet rows) from the same element pass.
  void jacobian(double t, const double* y, const double* ydot, double cj, double* values,
                double* rate_values = nullptr) override;
  /// The quadrature-point geometry of element e (reference configuration).
  const std::vector<PointGeometry>& point_geometry(Index e) const { return geometry_[e]; }
  /// The material laws of element e: those of its mesh region's [[region]] entry, or of
  /// [material] (docs/model_layer.md, *Regions*).
  const MaterialLaws& laws_of(Index e) const override {
    return laws_[element_law_.empty() ? 0 : static_cast<std::size_t>(element_law_[e])];
  }
  /// The distinct law sets in use (one per mesh region with its own material, [material] first).
  const std::vector<MaterialLaws>& all_laws() const { return laws_; }
  /// The element kernel's output for element e at the global state (for tests).
  void element(Index e, const double* y, const double* ydot, bool with_jacobian,
               ElementOutput& out) const;

  /// Reaction forces [N] at (t, y, ẏ): for each named boundary (or physical point or curve),
  /// the force its displacement and symmetry conditions exert on the body, i.e. the sum over
  /// its nodes of the momentum residual (internal force minus applied loads) on the
  /// displacement rows that those conditions fix, component by component. A row fixed by
  /// conditions on two boundaries (an edge node) counts in the reaction of each. With two or
  /// more names, one more entry follows: the total over the union of their rows, each row
  /// once (not the sum of the entries before it, which counts shared rows twice); labelled as
  /// by reaction_labels(). Throws std::invalid_argument for a name with no displacement or
  /// symmetry condition.
  std::vector<std::array<double, 3>> reactions(const std::vector<std::string>& boundaries, double t,
                                               const double* y, const double* ydot) override;
  /// Label of the total in reactions().
  static constexpr const char* kReactionTotal = "total";
  /// The labels of reactions()' entries: the names, then kReactionTotal if there are two or
  /// more.
  static std::vector<std::string> reaction_labels(const std::vector<std::string>& boundaries);

  using FluidRates = biphasic::FluidRates;
  /// Summing all mass rows (Σ g = 1 removes the Darcy term): at a converged state (free mass
  /// rows ≈ 0) ∫Ω₀ J̇ dX = source − drained − prescribed.
  FluidRates fluid_rates(double t, const double* y, const double* ydot) override;
  /// ∫Ω₀ (J − 1) dX [mm³]: the body's volume change from the reference configuration, with
  /// the element quadrature rule.
  double volume_change(const double* y) const override;
  Index num_elements() const override { return static_cast<Index>(mesh_.tets.size()); }

  /// Sets the constrained entries of y to ḡ(t) and of ẏ to dḡ/dt (ẏ may be null).
  void apply_dirichlet(double t, double* y, double* ydot) const override;
  /// Load-curve kinks of every boundary condition (sorted, unique) [s].
  std::vector<double> breakpoints() const override;
  /// c_e = scale · h_e² / (4k) of element e (0 without GLS) [MPa s].
  double gls_coefficient(Index e) const override {
    return stabilisation_.gls_coefficient(static_cast<std::size_t>(e));
  }
  /// β = scale · h_e² / (4 H_A) of the flux perturbation (0 without it) [mm⁴ N⁻¹].
  double flux_perturbation(Index e) const {
    return stabilisation_.flux_perturbation(static_cast<std::size_t>(e));
  }

  /// Approximation of the Schur-complement coupling −A_pu A_uu⁻¹ A_up of a matrix
  /// dF/dy + c_j dF/dẏ whose displacement rows carry the GLS term with shift `cj_gls`:
  /// element P1 mass matrices (reference volume) times c_j / (λ + 2μ + cj_gls c_e), i.e. the
  /// div–div stiffness of the displacement block seen by a pressure mode [mm³ MPa⁻¹ s⁻¹].
  /// Entries by pressure index (vertex), Dirichlet pressures included.
  void pressure_schur_term(double cj, double cj_gls, std::vector<PressureEntry>& out) const;
  /// The structure the iterative solver needs; `shifts()` returns (c_j, cj_gls) of the matrix
  /// being set up. The problem must outlive the solver.
  SaddlePointStructure saddle_point_structure(
      std::function<std::pair<double, double>()> shifts) const override;

  /// Oedometric modulus H_A of the solid law at small strain (λ + 2μ for Neo-Hookean) [MPa]; with
  /// several regions the largest of their H_A (the stiffest material sets the force scale).
  double oedometric_modulus() const { return modulus_; }
  bool has_gls() const override { return stabilisation_.has_gls(); }
  bool has_flux_perturbation() const override { return stabilisation_.has_flux_perturbation(); }
  /// Smallest GLS relaxation time min_e c_e / H_A over the elements [s] (0 without GLS).
  double gls_time_scale() const override;
  /// Sizes of the solution the data imply over the run [mm], [MPa]: the largest prescribed
  /// displacement or the traction's strain σ/H_A over the body's extent; the largest prescribed
  /// pressure, traction, or H_A times a prescribed strain (displacement over the body's
  /// extent along its component). 0 where the data say nothing.
  std::pair<double, double> solution_scales() const override { return solution_scales_; }

  AssemblyStats& stats() override { return stats_; }
  /// Stiffness scale H_A · (mean element size) [N/mm]: turns a displacement into a force, e.g.
  /// to compare a momentum residual with a displacement tolerance.
  double stiffness_scale() const override { return row_scale_u_; }
  /// Conductance scale k · (mean element size) [mm³/(s MPa)]: turns a pressure into a mass
  /// residual (a volume rate).
  double conductance_scale() const override { return row_scale_p_; }

 private:
  using Dirichlet = DirichletRow;
  struct VolumeLoads {
    VectorField b, b_rate;
    ScalarField s, s_rate;
  };
  struct DirichletFields {
    VectorField u, u_rate;
    ScalarField p, p_rate;
  };
  struct NodalLoad {
    std::vector<std::pair<Index, double>> entries;  ///< (row, amount) added to F
    double value;
    const LoadCurve* curve;
  };
  /// Element residuals and applied loads into F (size n), Dirichlet rows not replaced.
  void assemble(double t, const double* y, const double* ydot, double* F);
  void gather(Index e, const double* y, const double* ydot, ElementVector& ye,
              ElementVector& ydote) const;
  /// Runs work(e, out) over all elements, colour by colour, in parallel within a colour
  /// (OpenMP). An InvertedElement thrown by any element is rethrown after the loop.
  template <class Work>
  void for_each_element(bool with_jacobian, const double* y, const double* ydot, Work&& work);
  double curve_value(const LoadCurve* c, double t) const { return c ? c->value(t) : 1.0; }
  double dirichlet_value(const Dirichlet& d, double t) const;
  double dirichlet_rate(const Dirichlet& d, double t) const;
  double dirichlet_scale(const Dirichlet& d) const {
    return d.dof < num_u() ? row_scale_u_ : row_scale_p_;
  }
  /// Adds −∫Ω₀ f·b dX and −∫Ω₀ g s dX at time t (or their t-derivatives) to `out`.
  void add_volume_loads(double t, bool rate, double* out) const;
  /// Throws std::runtime_error if a formula of `config.loads` is not finite at a quadrature
  /// point at time t.
  void check_load_formulas(const Config& config, double t) const;
  Vec3 point_position(Index e, std::size_t q) const;

  const Mesh& mesh_;
  /// The elements assembled here: all of them, or a part's own (AssemblyScope).
  std::vector<Index> elements_;
  std::map<std::string, LoadCurve> curves_;
  /// Law sets: [material]'s first, then one per [[region]] entry used by the mesh.
  std::vector<MaterialLaws> laws_;
  /// Per element, its index into laws_; empty when every element uses laws_[0].
  std::vector<int> element_law_;
  double modulus_ = 0.0;         ///< largest H_A over laws_ [MPa]
  double volume_rate_dt_ = 0.0;  ///< ElementCoefficients::volume_rate_dt [s]
  std::vector<std::vector<PointGeometry>> geometry_;
  std::vector<PointGeometry> gls_point_;  ///< per element: the GLS term's centroid (one_point)
  std::vector<Eigen::Matrix<double, 10, 1>> point_p2_;  ///< P2 values at the rule's points
  RigidPlatens platens_;  ///< before pattern_: the pattern holds their couplings
  VolumeLoads loads_;
  DirichletFields dirichlet_fields_;
  std::vector<double> load_cache_;  ///< add_volume_loads at load_cache_t_ (empty = stale)
  double load_cache_t_ = 0.0;
  ElementStabilisation stabilisation_;
  SparsityPattern pattern_;
  std::vector<std::vector<Index>> colours_;  ///< elements sharing no node, per colour
  /// Per-thread residual accumulators: the residual loop runs over all elements at once (two
  /// barriers instead of one per colour, which matters when a core is shared or stolen).
  std::vector<std::vector<double>> thread_residuals_;
  std::vector<Dirichlet> dirichlet_;
  std::vector<char> dirichlet_held_;  ///< the Dirichlet rows' unknowns (not assembled)
  std::vector<char> constrained_;     ///< Dirichlet and platen-tied unknowns
  /// Displacement rows fixed by each boundary's own displacement, symmetry and rigid-platen
  /// conditions.
  std::map<std::string, std::vector<Index>> held_rows_;
  std::vector<NodalLoad> nodal_loads_;
  std::pair<double, double> solution_scales_{0.0, 0.0};
  double row_scale_u_ = 1.0;  ///< Dirichlet row scale on displacement rows [N/mm]
  double row_scale_p_ = 1.0;  ///< Dirichlet row scale on pressure rows [mm³/(s MPa)]
  AssemblyStats stats_;
};

}  // namespace biphasic
