// Sparse direct linear solvers behind SUNDIALS' SUNLinearSolver interface, so that KINSOL
// (backward Euler) and IDA (BDF) use them alike. Matrices are SUNSparseMatrix (CSC) with a
// pattern fixed for the whole run: symbolic analysis is done once per solver.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <memory>
#include <string>
#include <vector>

#include "biphasic/io/config.hpp"

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
  double fill = 0.0;  ///< nnz(L + U) / nnz(A) of the last factorisation
};

/// Deleter for SUNLinearSolver handles.
struct LinearSolverDeleter {
  void operator()(_generic_SUNLinearSolver* s) const;
};
using LinearSolverPtr = std::unique_ptr<_generic_SUNLinearSolver, LinearSolverDeleter>;

/// A pivot order given by the caller: order[k] = unknown eliminated k-th (empty: the solver
/// computes its own from the configured ordering).
using FillOrder = std::vector<sunindextype>;

class SparsityPattern;

/// The pivot order to hand to the configured solver for this pattern: with METIS, nested
/// dissection of the node graph (several times cheaper than METIS on the matrix, and as good),
/// except for UMFPACK, whose own METIS ordering suits its strategy better; otherwise empty.
FillOrder fill_order(const LinearSolverConfig& config, const SparsityPattern& pattern);

/// The solver the configuration names. `stats` must outlive the solver.
LinearSolverPtr make_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                   LinearSolverStats* stats, FillOrder order = {});

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
/// to MUMPS' AMF). Analysis once; a numeric factorisation at each setup.
LinearSolverPtr make_mumps_solver(Ordering ordering, SUNContext ctx, LinearSolverStats* stats,
                                  FillOrder order = {});

}  // namespace biphasic
