// MUMPS called directly on several processes, for the memory and speed PETSc's interface to it
// cannot give here: the fill-reducing order computed from the mesh (this MUMPS build has no
// METIS, and PETSc passes no order of the caller's), and single-precision factors refined in
// double precision as in one process (PETSc's MUMPS is real double only). docs/parallel.md.
#pragma once

#include <mpi.h>
#include <sundials/sundials_context.h>

#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/linsolve/linear_solver_config.hpp"
#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// LU of the distributed Jacobian (a PETSc AIJ matrix wrapped by wrap_petsc_matrix) by the
/// parallel MUMPS on `comm`:
/// - each process hands MUMPS its owned rows (distributed assembled input, ICNTL(18) = 3);
///   the analysis runs once, on process 0, in the order `order` (order[k] = the unknown
///   eliminated k-th, in the rank-major numbering; needed on process 0 only, elsewhere
///   ignored) or, if it is empty, in MUMPS' PORD order;
/// - each set-up refactorises; the right-hand side is gathered on process 0 and the solution
///   scattered back (centralised, ICNTL(20) = ICNTL(21) = 0);
/// - `precision` = Mixed: single-precision factors, each solution refined in double precision
///   to the one-process solver's targets (componentwise backward error ≤ 1e-6, relative
///   residual ≤ 1e-4), falling back to double-precision factors on the same schedule;
/// - `out_of_core_directory` not empty: each process writes its factors to files there
///   (MUMPS' out-of-core factorisation) and reads them back at each solve.
/// Vectors are N_Vector_Parallel over the owned range. Collective in every call.
LinearSolverPtr make_distributed_mumps_solver(MPI_Comm comm, FactorPrecision precision,
                                              std::vector<Index> order, SUNContext ctx,
                                              LinearSolverStats* stats,
                                              std::string out_of_core_directory = {});

}  // namespace biphasic
