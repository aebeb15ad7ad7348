// IDA's shift-corrected solver on several processes: the counterpart of
// make_shift_corrected_solver (linsolve/linear_solver.hpp) on PETSc matrices and
// N_Vector_Parallel vectors (docs/parallel.md).
#pragma once

#include <petscmat.h>
#include <sundials/sundials_context.h>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

/// Solves A(c) x = b for IDA's current c_j with the factors of A(c_s), the matrix `inner` was
/// last set up with (a SUNMatrix wrapping a PETSc matrix): when c differs from c_s, by PETSc's
/// GMRES (no restart, at most `max_iterations`, from x = 0) on the row-equilibrated system
/// D A(c) x = D b, A(c) = A(c_s) + (c − c_s) R, D = 1 / max_j |A(c_s)_ij|, right-preconditioned
/// by `inner`'s solve, to ‖D (b − A(c) x)‖ ≤ rtol ‖D b‖ — the one-process solver's iteration
/// and test. `rate` is R = ∂F/∂ẏ at the last set-up (filled by the system's Jacobian; not
/// owned). A solve that does not converge is a recoverable failure (IDA sets up a new matrix).
/// Counts shift-corrected solves, their iterations and failures in `stats`.
LinearSolverPtr make_petsc_shift_corrected_solver(MPI_Comm comm, LinearSolverPtr inner,
                                                  const ShiftedMatrixFamily* family, Mat rate,
                                                  SUNContext ctx, LinearSolverStats* stats,
                                                  double rtol, int max_iterations);

}  // namespace biphasic
