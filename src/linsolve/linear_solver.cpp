#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

void LinearSolverDeleter::operator()(_generic_SUNLinearSolver* s) const { SUNLinSolFree(s); }

LinearSolverPtr make_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                   LinearSolverStats* stats) {
  switch (config.type) {
    case LinearSolverType::Klu:
      return make_klu_solver(config.ordering, ctx, stats);
    case LinearSolverType::Umfpack:
      return make_umfpack_solver(config.ordering, ctx, stats);
    case LinearSolverType::Mumps:
      return make_mumps_solver(config.ordering, ctx, stats);
  }
  return nullptr;
}

}  // namespace biphasic
