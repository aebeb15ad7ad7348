// Sparse direct linear solvers behind SUNDIALS' SUNLinearSolver interface, so that KINSOL
// (backward Euler) and IDA (BDF) use them alike. Matrices are SUNSparseMatrix (CSC) with a
// pattern fixed for the whole run: symbolic analysis is done once per solver.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "biphasic/linsolve/linear_solver_config.hpp"

namespace biphasic {

/// Work done by a linear solver (accumulated over the run) [s].
struct LinearSolverStats {
  long analyses = 0;          ///< symbolic analyses (ordering)
  long factorizations = 0;    ///< numeric factorisations, including refactorisations
  long refactorizations = 0;  ///< of which reused the pivot order
  long solves = 0;
  double analysis_seconds = 0.0;
  double factor_seconds = 0.0;
  double solve_seconds = 0.0;
  double fill = 0.0;                ///< nnz(L + U) / nnz(A) of the last factorisation
  long krylov_iterations = 0;       ///< iterative solver: FGMRES iterations over all solves
  long max_krylov_iterations = 0;   ///< iterative solver: most FGMRES iterations of one solve
  long amg_cycles = 0;              ///< iterative solver: AMG V-cycles on the displacement block
  long refinement_steps = 0;        ///< mixed precision: refinement steps over all solves
  long precision_fallbacks = 0;     ///< mixed precision: switches to double-precision factors
  long shift_corrected_solves = 0;  ///< solves at a c_j other than the factorised one
  long shift_correction_iterations = 0;  ///< their GMRES iterations (one old-factor solve each)
  long shift_correction_failures = 0;    ///< of which did not converge (IDA then refactorises)
  /// Message of an exception caught in the last set-up or solve (which then reported an
  /// unrecoverable failure to the integrator); empty after one that did not throw.
  std::string last_error;
};

/// The matrices A(c) = ∂F/∂y + c ∂F/∂ẏ of a time integrator (c = IDA's c_j), as the
/// shift-corrected solver sees them. The integrator fills it at every matrix set-up and keeps
/// it alive as long as the solver.
struct ShiftedMatrixFamily {
  std::vector<double> rate_values;        ///< ∂F/∂ẏ at the last set-up (CSC values)
  double setup_shift = 0.0;               ///< c of the matrix last set up [1/s]
  std::function<double()> current_shift;  ///< c of the system being solved [1/s]
};

/// Runs a set-up or solve of a SUNLinearSolver inside SUNDIALS' C frames, where no exception
/// may pass: one is kept in `stats->last_error` (if stats) and reported as an unrecoverable
/// package failure; otherwise the call's flag.
template <class Call>
int guarded_solver_call(LinearSolverStats* stats, Call&& call) noexcept {
  try {
    return call();
  } catch (const std::exception& e) {
    if (stats) stats->last_error = e.what();
  } catch (...) {
    if (stats) stats->last_error = "an exception of unknown type";
  }
  return SUNLS_PACKAGE_FAIL_UNREC;
}

/// Deleter for SUNLinearSolver handles.
struct LinearSolverDeleter {
  void operator()(_generic_SUNLinearSolver* s) const;
};
using LinearSolverPtr = std::unique_ptr<_generic_SUNLinearSolver, LinearSolverDeleter>;

/// A pivot order given by the caller: order[k] = unknown eliminated k-th (empty: the solver
/// computes its own from the configured ordering).
using FillOrder = std::vector<sunindextype>;

class SparsityPattern;

/// One entry of a matrix on the pressure unknowns (indices counted from the first pressure).
struct PressureEntry {
  sunindextype row, col;
  double value;
};

/// What the iterative solver's block preconditioner needs beyond the matrix: which unknowns
/// are displacements, which rows are Dirichlet rows, and an approximation of the Schur
/// complement's coupling term −A_pu A_uu⁻¹ A_up for the matrix being set up.
struct SaddlePointStructure {
  sunindextype num_u = 0;         ///< unknowns [0, num_u) are displacements, node-major
  int components = 3;             ///< displacement components per node (3, or 2 in 2-D)
  std::vector<char> constrained;  ///< Dirichlet rows (diagonal rows of the matrix)
  /// Appends the coupling term's entries (symmetric, free pressures only) to `out`.
  std::function<void(std::vector<PressureEntry>& out)> schur_term;
};

/// The pivot order to hand to the configured solver for this pattern: with METIS, nested
/// dissection of the node graph (several times cheaper than METIS on the matrix, and as good),
/// except for UMFPACK, whose own METIS ordering suits its strategy better; otherwise empty.
FillOrder fill_order(const LinearSolverConfig& config, const SparsityPattern& pattern);

/// Why linear_solver.type = "superlu_dist" is refused in one process.
inline constexpr const char* kSuperluDistNeedsProcesses =
    "linear_solver.type = \"superlu_dist\" runs under mpirun with several processes only (in "
    "one process: \"mumps\", \"umfpack\", \"klu\" or \"iterative\")";

/// The solver the configuration names. `stats` must outlive the solver. The iterative solver
/// needs `saddle` (and throws std::invalid_argument without it); the direct ones ignore it.
LinearSolverPtr make_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                   LinearSolverStats* stats, FillOrder order = {},
                                   const SaddlePointStructure* saddle = nullptr);

/// Keeps the factors of A(c_s) while c changes: A(c) x = b is solved by GMRES (no restart, at
/// most `max_iterations`, to a relative residual `rtol` in the row-equilibrated 2-norm) on
/// A(c) = A(c_s) + (c − c_s) ∂F/∂ẏ, right-preconditioned by `inner`'s factors of A(c_s); at
/// c = c_s it is `inner`. (IDA's own scaled correction 2/(1 + c/c_s) A(c_s)⁻¹ b, even inside
/// its default window c/c_s ∈ [0.6, 1/0.6], broke tolerance proportionality at order 3.) A solve
/// that does not converge reports a recoverable failure (IDA then sets up a new matrix). Type
/// DIRECT: use with IDASetLinearSolutionScaling(off).
LinearSolverPtr make_shift_corrected_solver(LinearSolverPtr inner,
                                            const ShiftedMatrixFamily* family, SUNContext ctx,
                                            LinearSolverStats* stats, double rtol,
                                            int max_iterations);

/// KLU (SuiteSparse) with AMD, COLAMD or METIS nested-dissection ordering. Unlike SUNDIALS'
/// SUNLinSol_KLU, re-initialisation by KINSol/IDAReInit keeps the symbolic analysis; the
/// pivot order is reused (klu_refactor) until the pivot condition estimate degrades.
LinearSolverPtr make_klu_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                FillOrder order = {});

/// UMFPACK (SuiteSparse multifrontal LU, BLAS-3; fast with OpenBLAS) under its symmetric
/// strategy with AMD or METIS ordering (COLAMD selects the unsymmetric strategy). Symbolic
/// analysis once; a numeric factorisation at each setup.
LinearSolverPtr make_umfpack_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                    FillOrder order = {});

/// MUMPS (sequential build; multifrontal LU, BLAS-3) with AMD or METIS ordering (COLAMD maps
/// to MUMPS' AMF). Analysis once; a numeric factorisation at each setup. Mixed precision:
/// single-precision factors, solutions refined in double precision to a componentwise
/// backward error ≤ 1e-6 and a relative residual ≤ 1e-4, falling back to double-precision
/// factors when that fails. Rows with only a diagonal entry (Dirichlet rows) are solved
/// directly and kept out of the factorisation. `out_of_core_directory` not empty: the factors
/// are written to files there as they are computed and read back at each solve (MUMPS'
/// out-of-core factorisation), for problems whose factors do not fit in memory.
LinearSolverPtr make_mumps_solver(Ordering ordering, FactorPrecision precision, SUNContext ctx,
                                  LinearSolverStats* stats, FillOrder order = {},
                                  std::string out_of_core_directory = {});

/// Right-preconditioned FGMRES (SUNDIALS SPFGMR) on the whole system, solved to
/// `config.rtol` so that Newton sees an exact solve, with the block upper-triangular
/// preconditioner P = [Ã_uu A_up; 0 S̃]: Ã_uu⁻¹ = BoomerAMG V-cycles on the displacement block
/// (hypre, 3 functions per node), S̃ = A_pp + Schur coupling term from `saddle`, factorised
/// by sparse Cholesky (LDLᵀ). Counts a preconditioner set-up as a factorisation.
LinearSolverPtr make_iterative_solver(const KrylovConfig& config, SaddlePointStructure saddle,
                                      SUNContext ctx, LinearSolverStats* stats);

}  // namespace biphasic
