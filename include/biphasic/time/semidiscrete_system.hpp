// What the time integrators ask of a model: the semidiscrete system F(t, y, ẏ) = 0 of
// docs/formulation.md, with its Jacobian dF/dy + c_j dF/dẏ in a fixed sparsity pattern.
//
// Backward Euler (KINSOL), BDF (IDA) and the consistent start see a model only through this
// interface. BiphasicProblem (the 3-D Taylor–Hood tetrahedra) implements it; another
// discretisation (a 2-D kernel, a distributed assembly) implements the same calls. The
// calls are coarse (one per residual or Jacobian evaluation), so the virtual dispatch costs
// nothing measurable.
//
// Unknowns: y = (u, p), the num_u() displacement unknowns first (3 per node), then the
// pressures. Rows fixed by Dirichlet conditions (constrained()) read s·(y_i − ḡ_i(t)) = 0 with a
// row scale s. Units: momentum rows N, mass rows mm³/s, u mm, p MPa, t s.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "biphasic/assembly/sparsity.hpp"
#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/time/entrywise_matrices.hpp"

namespace biphasic {

/// Counters and timings of the residual/Jacobian evaluations [s].
struct AssemblyStats {
  long residual_evaluations = 0;
  long jacobian_evaluations = 0;
  double residual_seconds = 0.0;
  double jacobian_seconds = 0.0;
};

/// A state the model cannot evaluate but a smaller step may avoid: an element inverted
/// (det F ≤ 0) or a material law outside its range (J ≤ φ₀ of a porous permeability law).
/// The integrators treat it as recoverable (cut-back, step reduction); the message names the
/// element and the cause.
struct InvertedElement : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class SemidiscreteSystem {
 public:
  virtual ~SemidiscreteSystem() = default;

  // ---- unknowns and pattern ----------------------------------------------------------------
  /// The Jacobian's fixed CSC pattern (also the number of unknowns). A system distributed over
  /// processes has none (its matrix is PETSc's) and throws std::logic_error.
  virtual const SparsityPattern& pattern() const = 0;
  /// Unknowns of this process: all of them in one process, the owned range under MPI (whose
  /// displacements again come first).
  virtual Index size() const { return pattern().size(); }
  virtual Index num_u() const { return pattern().num_u(); }
  /// Unknowns fixed by Dirichlet conditions (1 = fixed), size().
  virtual const std::vector<char>& constrained() const = 0;

  // ---- evaluations ---------------------------------------------------------------------------
  /// F(t, y, ẏ) into F (size()). Throws InvertedElement for a state a smaller step may avoid,
  /// anything else for a failure it cannot.
  virtual void residual(double t, const double* y, const double* ydot, double* F) = 0;
  /// dF/dy + c_j dF/dẏ into the pattern's value array; if `rate_values` is given, dF/dẏ alone
  /// into it from the same pass (zero on Dirichlet rows).
  virtual void jacobian(double t, const double* y, const double* ydot, double cj, double* values,
                        double* rate_values = nullptr) = 0;
  /// ∂F/∂t at fixed (y, ẏ): the rates of the prescribed data (right derivatives at kinks).
  virtual void time_derivative(double t, double* dFdt) const = 0;
  /// Sets the constrained entries of y to ḡ(t) and of ẏ to dḡ/dt (ẏ may be null).
  virtual void apply_dirichlet(double t, double* y, double* ydot) const = 0;
  /// Times where the prescribed data have kinks (sorted, unique) [s]: the integrators stop there.
  virtual std::vector<double> breakpoints() const = 0;
  /// Backward Euler's conservative volume rate: J̇ = (J − Jₙ)/Δt for the step about to be
  /// solved (Δt = dt [s]); dt = 0 restores the incremental J̇ = J F⁻ᵀ:∇₀u̇.
  virtual void set_conservative_volume_rate(double dt) = 0;
  /// Evaluation counters and timings (the integrators read the Jacobian count per step).
  virtual AssemblyStats& stats() = 0;

  // ---- linear algebra of the integrators (defaults: one process, the CSC pattern) ----------
  /// A new SUNDIALS vector of size() entries (serial; parallel under MPI). Caller destroys.
  virtual N_Vector new_vector(SUNContext ctx) const;
  /// A new matrix for dF/dy + c_j dF/dẏ (a SUNSparseMatrix of the pattern). Caller destroys.
  virtual SUNMatrix new_jacobian_matrix(SUNContext ctx) const;
  /// dF/dy + c_j dF/dẏ into J (from new_jacobian_matrix()); dF/dẏ into `rate_values` if given
  /// (the pattern's value layout: one process only).
  virtual void jacobian_into(double t, const double* y, const double* ydot, double cj, SUNMatrix J,
                             double* rate_values = nullptr);
  /// The linear solver `config` names, for matrices from new_jacobian_matrix(); `saddle` is
  /// what the iterative solver needs (the direct ones ignore it). `stats` must outlive it.
  virtual LinearSolverPtr new_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                            LinearSolverStats* stats,
                                            const SaddlePointStructure* saddle) const;

  /// The shift-corrected solver over `inner` (linsolve/linear_solver.hpp,
  /// make_shift_corrected_solver) for this system's matrices; `family` must outlive it. The
  /// default sizes family->rate_values to the pattern (jacobian_into then fills them);
  /// a distributed system keeps dF/dẏ as its own matrix and leaves them empty.
  virtual LinearSolverPtr new_shift_corrected_solver(LinearSolverPtr inner,
                                                     ShiftedMatrixFamily* family, SUNContext ctx,
                                                     LinearSolverStats* stats, double rtol,
                                                     int max_iterations);

  /// The consistent start's matrices (time/entrywise_matrices.hpp) in this system's layout.
  virtual std::unique_ptr<EntrywiseMatrices> entrywise_matrices();

  // ---- scales for tolerances and messages ----------------------------------------------------
  /// ‖F‖_∞ over the free momentum rows [N] and over the free mass rows [mm³/s].
  virtual std::pair<double, double> field_norms(const double* F) const = 0;
  /// ‖v‖_∞ of a vector of size() entries over the whole system: on several processes, where each
  /// holds its owned entries, the largest over all of them, so that every process takes the
  /// same decision from it. Collective there.
  virtual double max_norm(const double* v) const;
  /// Sizes of the solution the data imply [mm], [MPa] (0 where the data say nothing).
  virtual std::pair<double, double> solution_scales() const = 0;
  /// Turns a displacement into a force [N/mm] (oedometric modulus × mean element size).
  virtual double stiffness_scale() const = 0;
  /// Turns a pressure into a volume rate [mm³/(s MPa)] (permeability × mean element size).
  virtual double conductance_scale() const = 0;

  // ---- structure of the DAE ------------------------------------------------------------------
  /// The momentum rows depend on u̇ (the GLS term C u̇, C = ∂F_u/∂u̇ ≠ 0): with it the pressure
  /// is algebraic and may jump at load kinks (docs/formulation.md, consistent start).
  virtual bool has_gls() const = 0;
  /// The mass rows depend on ṗ (the flux perturbation, ∂F_p/∂ṗ ≠ 0): the pressure is then a
  /// differential unknown.
  virtual bool has_flux_perturbation() const = 0;
  /// Smallest relaxation time of the u̇ term, min_e c_e / H_A [s] (0 without it).
  virtual double gls_time_scale() const = 0;
  /// What the iterative solver's block preconditioner needs; `shifts()` returns (c_j, c_j of
  /// the u̇ term) of the matrix being set up. The system must outlive the solver.
  virtual SaddlePointStructure saddle_point_structure(
      std::function<std::pair<double, double>()> shifts) const = 0;
};

}  // namespace biphasic
