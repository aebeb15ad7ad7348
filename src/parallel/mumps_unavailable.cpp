// The MPI build links PETSc's parallel MUMPS, whose symbols are those of the sequential MUMPS
// the one-process solver uses: only one of the two may be in a program. Here the one-process
// MUMPS solver is absent and asking for it says so.
#include <stdexcept>
#include <string>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

LinearSolverPtr make_mumps_solver(Ordering, FactorPrecision, SUNContext, LinearSolverStats*,
                                  FillOrder, std::string) {
  throw std::runtime_error(
      "linear_solver.type = \"mumps\": the sequential MUMPS is not part of the MPI build, which "
      "solves through PETSc (docs/parallel.md)");
}

}  // namespace biphasic
