// Validated run configuration: what a case file resolves to (units: mm, N, s, MPa).
#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/io/expression.hpp"
#include "biphasic/linsolve/linear_solver_config.hpp"
#include "biphasic/material/material_config.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/stabilisation/stabilisation_config.hpp"
#include "biphasic/time/time_config.hpp"

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

enum class MeshSource { QuarterCylinder, Column, SphereOctant, Section, File };

/// The kinematics of the model (docs/two_dimensional_models.md): the three-dimensional body on
/// a tetrahedral mesh, or a two-dimensional section on a triangle mesh.
enum class ModelKind {
  ThreeDimensional,  ///< tetrahedra, u = (u_x, u_y, u_z)
  PlaneStrain,       ///< triangles in (x, y), u_z = 0, per mm of thickness
  Axisymmetric,      ///< triangles in (r, z) = (x, y), u_θ = 0, over the full circle
};

/// Whether the model is two-dimensional (a section mesh).
inline bool is_two_dimensional(ModelKind m) { return m != ModelKind::ThreeDimensional; }

struct MeshConfig {
  MeshSource source = MeshSource::QuarterCylinder;
  QuarterCylinderSpec cylinder;  ///< also holds write_msh for every gmsh-generated source
  ColumnSpec column;
  SphereOctantSpec sphere_octant;
  SectionRectangleSpec section;         ///< mesh.source = "section" ([mesh.section])
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
  /// The boundary moves as a rigid body along `component` (one unknown: the platen's
  /// displacement) and the total force it exerts on the body along that axis is
  /// value · curve(t) [N] (docs/rigid_platen.md).
  RigidPlaten,
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
  int component = 0;               ///< 0,1,2 = x,y,z (displacement and rigid platen)
  double value = 0.0;              ///< scale of the curve (units by type)
  std::array<double, 3> vector{};  ///< traction vector [MPa] (traction only)
  std::string curve;               ///< load-curve name; empty = constant 1
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
std::string to_string(ModelKind model);
std::string to_string(Ordering ordering);
std::string to_string(FactorPrecision precision);
std::string to_string(FieldQuantity quantity);

struct Config {
  std::string case_file;  ///< path of the case file read
  std::string title;
  ModelKind model = ModelKind::ThreeDimensional;
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
