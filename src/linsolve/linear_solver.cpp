#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic {

void LinearSolverDeleter::operator()(_generic_SUNLinearSolver* s) const { SUNLinSolFree(s); }

std::string ordering_name(Ordering o) {
  switch (o) {
    case Ordering::Amd:
      return "amd";
    case Ordering::Colamd:
      return "colamd";
    case Ordering::Metis:
      return "metis";
  }
  return "?";
}

LinearSolverPtr make_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                   LinearSolverStats* stats) {
  switch (config.type) {
    case LinearSolverType::Klu:
      return make_klu_solver(config.ordering, ctx, stats);
  }
  return nullptr;
}

}  // namespace biphasic
