// PETSc matrices and solvers behind SUNDIALS' interfaces, so that KINSOL (backward Euler) and
// IDA (BDF) solve through PETSc when the system is distributed (docs/parallel.md).
#pragma once

#include <petscksp.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <functional>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// A SUNMatrix (SUNMATRIX_CUSTOM) that owns the PETSc matrix A; SUNMatZero leaves the values
/// (each assembly replaces them all).
SUNMatrix wrap_petsc_matrix(Mat A, SUNContext ctx);
/// The PETSc matrix of a SUNMatrix made by wrap_petsc_matrix.
Mat petsc_matrix(SUNMatrix M);

/// A direct solver over a PETSc KSP on `comm`: LU factorisation by SuperLU_DIST with its
/// METIS column order (on A + Aᵀ) and no row permutation, one solve per right-hand side. The
/// KSP takes PETSc options with the prefix "biphasic_" (e.g.
/// -biphasic_mat_superlu_dist_colperm MMD_AT_PLUS_A), so any other KSP/PC can be chosen at run
/// time. The symbolic analysis is done once; each set-up refactorises. Vectors are
/// N_Vector_Parallel whose local arrays are the owned entries. Counts set-ups as
/// factorisations in `stats`.
LinearSolverPtr make_superlu_dist_solver(MPI_Comm comm, SUNContext ctx, LinearSolverStats* stats);

/// What the field-split preconditioner needs of this process's owned range: how many of its
/// unknowns are displacements (they come first, `components` per node) and those nodes'
/// coordinates [mm] (`components` per node, for the rigid-body modes).
struct FieldSplitLayout {
  Index owned_u = 0, owned = 0, first_owned = 0;
  int components = 3;  ///< displacement components per node: the displacement block's block size
  /// The rigid-body modes (from `coordinates`) as the displacement block's near-null space;
  /// false (an axisymmetric section, whose rigid motions are axial translations only): the
  /// multigrid's default, one constant per component.
  bool rigid_body_modes = true;
  std::vector<double> coordinates;
  /// The Schur coupling term of the matrix being set up (SaddlePointStructure::schur_term),
  /// entries indexed in the pressure block (the owned pressures of process 0, then of process
  /// 1, ...), Dirichlet pressures left out; empty: PETSc's "selfp" approximation instead.
  std::function<void(std::vector<PressureEntry>&)> schur_term;
};

/// Right-preconditioned FGMRES over a PETSc KSP on `comm`, solved to `config.rtol` (so that
/// Newton sees an exact solve) within `config.max_iterations`, restart `config.restart`, with a
/// field-split Schur preconditioner, block upper triangular as the one-process solver's:
/// the displacement block by one V-cycle of hypre's BoomerAMG (block size 3, strong threshold
/// 0.5, HMIS coarsening, ext+i interpolation; measured mesh-independent where PETSc's GAMG was
/// not), the six rigid-body modes attached as near null space for GAMG
/// (-biphasic_fieldsplit_u_pc_type gamg), the Schur complement by the
/// project's approximation S̃ = A_pp + coupling term (as the one-process solver's), or without
/// one PETSc's A_pp − A_pu diag(A_uu)⁻¹ A_up ("selfp"), factorised by MUMPS. Every choice can be
/// changed by PETSc options with the prefix "biphasic_" (e.g. -biphasic_fieldsplit_u_pc_type
/// hypre). Counts Krylov iterations in `stats`; a solve that does not converge is a recoverable
/// failure.
LinearSolverPtr make_petsc_fieldsplit_solver(MPI_Comm comm, const KrylovConfig& config,
                                             FieldSplitLayout layout, SUNContext ctx,
                                             LinearSolverStats* stats);

}  // namespace biphasic
