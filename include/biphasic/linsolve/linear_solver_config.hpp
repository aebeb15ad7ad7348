// The [linear_solver] section of a case file: which linear solver and its settings
// (linear_solver.hpp builds the solver from them; the case-file schema fills them).
#pragma once

#include <string>

namespace biphasic {

/// Klu, Umfpack, Mumps: sparse direct. Iterative: SUNDIALS FGMRES with a block-triangular
/// preconditioner (BoomerAMG on the displacement block, a pressure Schur-complement
/// approximation), for meshes where a factorisation runs out of time or memory. SuperluDist:
/// sparse direct through PETSc, on several processes only (docs/parallel.md).
enum class LinearSolverType { Klu, Umfpack, Mumps, Iterative, SuperluDist };
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
  /// MUMPS only: factors written to files in `out_of_core_directory` as they are computed and
  /// read back at each solve, so that memory holds only the fronts being worked on.
  bool out_of_core = false;
  /// Where the out-of-core factors go; the case file sets it ($TMPDIR, else /tmp, by default).
  std::string out_of_core_directory;
  KrylovConfig krylov;

  /// The folder MUMPS is to write its factors to: empty when they stay in memory.
  std::string factor_folder() const { return out_of_core ? out_of_core_directory : std::string(); }
};

}  // namespace biphasic
