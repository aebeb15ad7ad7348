// PETSc matrices and solvers behind SUNDIALS' interfaces, so that KINSOL (backward Euler) and
// IDA (BDF) solve through PETSc when the system is distributed (docs/parallel.md).
#pragma once

#include <petscksp.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

/// A SUNMatrix (SUNMATRIX_CUSTOM) that owns the PETSc matrix A; SUNMatZero leaves the values
/// (each assembly replaces them all).
SUNMatrix wrap_petsc_matrix(Mat A, SUNContext ctx);
/// The PETSc matrix of a SUNMatrix made by wrap_petsc_matrix.
Mat petsc_matrix(SUNMatrix M);

/// A direct solver over a PETSc KSP on `comm`: LU factorisation by the parallel MUMPS
/// (ordering PORD, the best this MUMPS build has without METIS), one solve per right-hand
/// side; the KSP takes PETSc options with the prefix "biphasic_" (e.g.
/// -biphasic_mat_mumps_icntl_14 40), so any other KSP/PC can be chosen at run time. The
/// symbolic analysis is done once; each set-up refactorises. Vectors are N_Vector_Parallel
/// whose local arrays are the owned entries. Counts set-ups as factorisations in `stats`.
LinearSolverPtr make_petsc_direct_solver(MPI_Comm comm, SUNContext ctx, LinearSolverStats* stats);

}  // namespace biphasic
