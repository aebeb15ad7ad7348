// Validated run configuration: what a case file resolves to (units: mm, N, s, MPa).
#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/io/expression.hpp"
#include "biphasic/material/material_config.hpp"
#include "biphasic/physics/stabilisation/stabilisation_config.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace biphasic {

/// Piecewise-linear load curve: points (t [s], value [-]) with increasing t; constant
/// extrapolation outside the first and last point.
struct LoadCurve {
  std::vector<std::pair<double, double>> points;
  double value(double t) const;
  double slope(double t) const;  ///< right derivative d value/dt [1/s]
  /// Times where the slope changes (breakpoints), counting the constant extrapolation: for
  /// [[0,0],[32,1]] this is {0, 32}; a point inside a straight stretch is not a kink.
  std::vector<double> kinks() const;
};

enum class MeshSource { QuarterCylinder, Column, SphereOctant, File };

struct MeshConfig {
  MeshSource source = MeshSource::QuarterCylinder;
  QuarterCylinderSpec cylinder;  ///< also holds write_msh for every gmsh-generated source
  ColumnSpec column;
  SphereOctantSpec sphere_octant;
  std::string file;                     ///< .msh path (resolved relative to the case file's folder)
  bool ignore_memory_estimate = false;  ///< run even if the size guard expects too little memory
};

/// A [[region]] entry: the material of the mesh region `name` (a physical volume of a .msh
/// file, or a region of the generated column). Keys the entry omits are inherited from
/// [material]; mesh regions without an entry use [material] itself.
struct RegionConfig {
  std::string name;
  MaterialConfig material;
};

enum class BcType {
  Displacement,    ///< u·e_component = value · curve(t) [mm]
  Symmetry,        ///< zero normal displacement on an axis-aligned plane
  Pressure,        ///< p = value · curve(t) [MPa]
  Flux,            ///< outward normal flux q̄ = value · curve(t) [mm/s]
  Traction,        ///< nominal (dead) traction vector · curve(t) [MPa]
  NormalTraction,  ///< nominal traction −value · curve(t) · N (reference normal) [MPa]
};

/// Volume loads given as formulas of the reference position X = (x, y, z) [mm] and time t [s],
/// per unit reference volume. The momentum rows gain −∫Ω₀ f·b dX and the mass rows −∫Ω₀ g s dX,
/// i.e. the balances read −Div P = b and J̇ + Div W = s (W = −k J C⁻¹∇₀p, the reference seepage).
struct VolumeLoadConfig {
  std::array<Expression, 3> body_force;  ///< b [N/mm³]; all zero = none
  Expression fluid_source;               ///< s [1/s]; zero = none
};

struct BoundaryCondition {
  BcType type = BcType::Displacement;
  std::string boundary;            ///< physical-group name
  int component = 0;               ///< 0,1,2 = x,y,z (displacement only)
  double value = 0.0;              ///< scale of the curve (units by type)
  std::array<double, 3> vector{};  ///< traction vector [MPa] (traction only)
  std::string curve;               ///< load-curve name; empty = constant 1
};

/// BackwardEuler: fixed step (the paper's). Bdf: IDA, orders 1–time.bdf.max_order.
/// AdaptiveBackwardEuler: IDA at order 1 (error-controlled backward Euler, time.bdf settings).
enum class Integrator { BackwardEuler, Bdf, AdaptiveBackwardEuler };
/// Whether the integrator runs on IDA (variable step, outputs by interpolation).
inline bool uses_ida(Integrator i) { return i != Integrator::BackwardEuler; }
/// How backward Euler discretises J̇ (in the mass rows and the GLS term). Incremental:
/// J F⁻ᵀ:∇₀(u − uₙ)/Δt (the paper's u̇ = Δu/Δt in div v). Conservative: (J − Jₙ)/Δt, so the
/// discrete fluid volume balance holds exactly. BDF always uses J F⁻ᵀ:∇₀u̇.
enum class VolumeRate { Incremental, Conservative };

struct NewtonConfig {
  int max_iterations = 25;
  /// Converged when, per field, ‖R_f‖_∞ ≤ max(rtol_f ‖R_f⁰‖_∞, atol_f), R_f⁰ = the residual at
  /// the step's predictor.
  double rtol_displacement = 1e-8;   ///< momentum rows [-]
  double rtol_pressure = 1e-8;       ///< mass rows [-]
  double atol_displacement = 1e-12;  ///< momentum rows [N]
  double atol_pressure = 1e-15;      ///< mass rows [mm³/s]
  int max_setup_calls = 10;          ///< Newton iterations between Jacobian refreshes (1 = full)
  bool reuse_across_steps = true;    ///< keep the factorisation from the previous step
  /// Backward Euler: successive halvings of the step after a failed Newton solve, down to
  /// time.dt / 2^max_cutbacks (0 = a failure stops the run).
  int max_cutbacks = 4;
};

/// Variable-order, variable-step BDF (SUNDIALS IDA). Defaults chosen by measurement
/// (docs/integrators.md).
struct BdfConfig {
  double rtol = 1e-4;  ///< relative tolerance of the local error test [-]
  /// Absolute tolerances [mm], [MPa]; 0 = rtol times the solution's own scale (the largest
  /// prescribed displacement; H_A times the applied strain, or the prescribed pressure or
  /// traction), see BiphasicProblem::solution_scales.
  double atol_displacement = 0.0;
  double atol_pressure = 0.0;
  int max_order = 5;  ///< 1–5
  /// First step [s] (also after a restart when restart_from_last_step is off); 0 = 1 % of the
  /// first output interval (or of the time to the first load-curve kink if shorter).
  double initial_step = 0.0;
  double max_step = 0.0;    ///< [s]; 0 = unlimited
  long max_steps = 100000;  ///< internal steps allowed between two outputs
  double max_growth = 2.0;  ///< largest step-size ratio between steps (IDASetEtaMax) [-]
  /// Relative change of c_j = α/h that forces a new factorisation (IDASetDeltaCjLSetup): with
  /// shift_correction, 0.9 (c_j may drift by a factor 19 on one factorisation).
  double delta_cj = 0.9;
  /// Solve with the current c_j on the last factorisation (GMRES preconditioned by it) instead
  /// of IDA's scaled stale-c_j correction, so that the Newton iteration sees the exact matrix.
  bool shift_correction = true;
  /// After a load-curve kink, start from the last accepted step instead of a fresh estimate.
  bool restart_from_last_step = true;
  /// End an internal step on every output time, so that outputs are step values (y, ẏ with
  /// F = 0) rather than interpolated: with GLS the reactions depend on ẏ.
  bool stop_at_outputs = true;
  bool step_log = false;  ///< write steps.csv (t, h, order) of every internal step
};

struct TimeConfig {
  Integrator integrator = Integrator::BackwardEuler;
  double t_end = 32.0;  ///< [s]
  double dt = 6.4;      ///< backward Euler step; output interval of BDF [s]
  VolumeRate volume_rate = VolumeRate::Incremental;  ///< backward Euler only
  NewtonConfig newton;
  BdfConfig bdf;
};

/// Klu, Umfpack, Mumps: sparse direct. Iterative: SUNDIALS FGMRES with a block-triangular
/// preconditioner (BoomerAMG on the displacement block, a pressure Schur-complement
/// approximation), for meshes where a factorisation runs out of time or memory.
enum class LinearSolverType { Klu, Umfpack, Mumps, Iterative };
enum class Ordering { Amd, Colamd, Metis };
/// Arithmetic of MUMPS' factors. Mixed: single-precision LU (half the memory, about twice the
/// speed), each solve refined in double precision until its componentwise backward error
/// max_i |b − A x|_i / (|A| |x| + |b|)_i ≤ 1e-6 and its relative residual
/// ‖b − A x‖∞ / ‖b‖∞ ≤ 1e-4; a factorisation or refinement that fails falls back to double
/// precision for the next few factorisations.
enum class FactorPrecision { Double, Mixed };

/// Default: MUMPS with METIS ordering, the fastest of the three on the paper's meshes
/// (docs/performance.md).
/// Settings of the iterative solver (ignored by the direct ones).
struct KrylovConfig {
  /// Stop when the residual's 2-norm falls below rtol times the right-hand side's. Tight by
  /// default, so that the Newton iteration converges as with a direct solver.
  double rtol = 1e-8;
  int max_iterations = 500;    ///< FGMRES iterations per solve (restarts included)
  int restart = 100;           ///< Krylov vectors kept before a restart
  double amg_threshold = 0.5;  ///< BoomerAMG strong-connection threshold [-]
  int amg_cycles = 1;          ///< V-cycles per application to the displacement block
  /// > 0: the displacement block is solved by inner GMRES + AMG to this relative residual
  /// (needed when the GLS term dominates the block: c_j c_e ≫ λ + 2μ); 0: V-cycles only.
  double block_rtol = 0.0;
};

struct LinearSolverConfig {
  LinearSolverType type = LinearSolverType::Mumps;
  Ordering ordering = Ordering::Metis;
  FactorPrecision precision = FactorPrecision::Mixed;  ///< MUMPS only
  KrylovConfig krylov;
};

/// A named probe line ([[probe]]), written to probe_<name>.csv.
struct ProbeConfig {
  std::string name;               ///< letters, digits, '_' and '-'
  std::array<double, 3> start{};  ///< [mm]
  std::array<double, 3> end{};    ///< [mm]
  /// 0: the mesh nodes on the line when it runs along the mesh, else 101 points; n >= 2: n
  /// evenly spaced points, interpolated by the shape functions.
  int points = 0;
};

/// What the field output (fields.h5, fields.xdmf; docs/output_fields.md) can hold, in the order
/// it is written.
enum class FieldQuantity {
  Displacement,     ///< u on the P2 nodes [mm]
  Pressure,         ///< p on the vertices and interpolated on every P2 node [MPa]
  Stress,           ///< total Cauchy stress σ = σ_eff − p I, per element [MPa]
  EffectiveStress,  ///< effective Cauchy stress σ_eff = J⁻¹ P_eff Fᵀ, per element [MPa]
  J,                ///< volume ratio J = det F, per element
  Flux,             ///< Darcy flux w = −k(J) ∇ₓp relative to the solid, per element [mm/s]
  Permeability,     ///< k(J), per element [mm⁴ N⁻¹ s⁻¹]
};

/// The field quantities of `output.fields = true`, the default: displacement and pressure.
inline std::vector<FieldQuantity> default_field_quantities() {
  return {FieldQuantity::Displacement, FieldQuantity::Pressure};
}

struct OutputConfig {
  std::array<double, 3> line_start{0.0, 0.0, 0.0};  ///< probe line [mm]
  std::array<double, 3> line_end{0.0, 0.0, 8.0};
  int line_points = 0;  ///< sampling of the probe line, as ProbeConfig::points
  int every = 1;        ///< write outputs every n steps (and always the last)
  /// Quantities of the HDF5/XDMF field output, distinct and in FieldQuantity order; empty = no
  /// field files.
  std::vector<FieldQuantity> fields = default_field_quantities();
  bool line = true;  ///< probe line: line.csv and the oscillation measures
  /// Boundaries whose reaction forces are written (reactions.csv and the summary): the force
  /// their displacement and symmetry conditions exert on the body [N].
  std::vector<std::string> reactions;
  std::vector<ProbeConfig> probes;  ///< [[probe]] entries
};

/// Opt-ins for what the checks before the first step refuse (docs/constraints.md).
struct ConstraintsConfig {
  /// Run although the displacement conditions leave rigid-body modes free: the applied loads
  /// must then balance exactly, and the linear solvers see a singular matrix.
  bool allow_free_rigid_modes = false;
  /// Accept distinct nodes at the same place (a deliberate crack or contact-free interface).
  bool allow_coincident_nodes = false;
};

/// Case-file names of enumerators ("displacement", "metis", …).
std::string to_string(BcType type);
std::string to_string(Ordering ordering);
std::string to_string(FactorPrecision precision);
std::string to_string(FieldQuantity quantity);

struct Config {
  std::string case_file;  ///< path of the case file read
  std::string title;
  MeshConfig mesh;
  MaterialConfig material;
  std::vector<RegionConfig> regions;  ///< [[region]] entries, in file order
  std::map<std::string, LoadCurve> curves;
  std::vector<BoundaryCondition> bcs;
  VolumeLoadConfig loads;
  StabilisationConfig stabilisation;
  int quadrature_points = 4;  ///< 1, 4 (paper), 5, 8, 27, 64, 125
  TimeConfig time;
  LinearSolverConfig linear_solver;
  OutputConfig output;
  ConstraintsConfig constraints;
};

}  // namespace biphasic
