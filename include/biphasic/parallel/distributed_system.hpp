// The semidiscrete system of a mesh split among MPI processes, as the time integrators see it
// (time/semidiscrete_system.hpp): each process holds the owned range of y, ẏ and F, in the
// rank-major numbering (displacements of its nodes first, then its pressures), as the local
// array of an N_Vector_Parallel; the Jacobian is a PETSc matrix solved through a PETSc KSP
// (docs/parallel.md). Norms and scales are those of the whole system on every process, so every
// process takes the same decisions (cut-backs, step sizes).
#pragma once

#include <memory>
#include <vector>

#include "biphasic/parallel/distributed_assembly.hpp"
#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

/// Why klu and umfpack are refused on several processes.
inline constexpr const char* kOneProcessSolvers =
    "linear_solver.type: \"mumps\", \"superlu_dist\" (sparse direct) and \"iterative\" "
    "(FGMRES with a field-split preconditioner) run on several processes; klu and umfpack on one "
    "only";

class DistributedSystem final : public SemidiscreteSystem {
 public:
  /// `assembly` must outlive the system.
  explicit DistributedSystem(DistributedAssembly& assembly);
  ~DistributedSystem() override;

  /// Throws std::logic_error: a distributed system has no one-process pattern.
  const SparsityPattern& pattern() const override;
  Index size() const override { return assembly_.owned_size(); }
  Index num_u() const override { return num_u_; }
  const std::vector<char>& constrained() const override { return constrained_; }

  void residual(double t, const double* y, const double* ydot, double* F) override;
  /// Throws std::logic_error: the Jacobian goes into a PETSc matrix (jacobian_into()).
  void jacobian(double t, const double* y, const double* ydot, double cj, double* values,
                double* rate_values = nullptr) override;
  void time_derivative(double t, double* dFdt) const override;
  void apply_dirichlet(double t, double* y, double* ydot) const override;
  std::vector<double> breakpoints() const override;
  void set_conservative_volume_rate(double dt) override;
  AssemblyStats& stats() override;

  N_Vector new_vector(SUNContext ctx) const override;
  SUNMatrix new_jacobian_matrix(SUNContext ctx) const override;
  /// dF/dy + c_j dF/dẏ into the PETSc matrix of J, and dF/dẏ into the system's own rate
  /// matrix once new_shift_corrected_solver() has made one; `rate_values` must be null (the
  /// one-process layout).
  void jacobian_into(double t, const double* y, const double* ydot, double cj, SUNMatrix J,
                     double* rate_values = nullptr) override;
  /// The shift-corrected solver on PETSc objects (make_petsc_shift_corrected_solver), with
  /// dF/dẏ kept as a PETSc matrix of the Jacobian's pattern; family->rate_values stay empty.
  LinearSolverPtr new_shift_corrected_solver(LinearSolverPtr inner, ShiftedMatrixFamily* family,
                                             SUNContext ctx, LinearSolverStats* stats, double rtol,
                                             int max_iterations) override;
  /// linear_solver.type = "mumps": the parallel MUMPS called directly, in the configured
  /// precision and (ordering "metis") the mesh's nested-dissection order
  /// (make_distributed_mumps_solver); "superlu_dist": SuperLU_DIST through PETSc; "iterative":
  /// FGMRES with the field-split preconditioner (make_petsc_fieldsplit_solver); klu and umfpack
  /// throw std::invalid_argument naming the key (kOneProcessSolvers).
  LinearSolverPtr new_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                    LinearSolverStats* stats,
                                    const SaddlePointStructure* saddle) const override;

  /// The consistent start's matrices as PETSc matrices, factorised by the parallel MUMPS.
  std::unique_ptr<EntrywiseMatrices> entrywise_matrices() override;

  /// Over the free owned rows of every process.
  std::pair<double, double> field_norms(const double* F) const override;
  double max_norm(const double* v) const override;
  std::pair<double, double> solution_scales() const override;
  double stiffness_scale() const override;
  double conductance_scale() const override;
  bool has_gls() const override;
  bool has_flux_perturbation() const override;
  /// The smallest over the processes.
  double gls_time_scale() const override;
  /// The owned range's layout and the Schur coupling term of this process's elements, indexed
  /// in the pressure block (FieldSplitLayout::schur_term).
  SaddlePointStructure saddle_point_structure(
      std::function<std::pair<double, double>()> shifts) const override;

 private:
  DistributedAssembly& assembly_;
  Index num_u_ = 0;
  std::vector<char> constrained_;
  Vec y_ = nullptr, ydot_ = nullptr, F_ = nullptr;  ///< storage-less, over caller arrays
  Mat rate_ = nullptr;  ///< dF/dẏ at the last Jacobian (with the shift-corrected solver)
};

}  // namespace biphasic
