#include "biphasic/linsolve/linear_solver.hpp"

#include <stdexcept>
#include <utility>

#include "biphasic/assembly/sparsity.hpp"

namespace biphasic {

void LinearSolverDeleter::operator()(_generic_SUNLinearSolver* s) const { SUNLinSolFree(s); }

FillOrder fill_order(const LinearSolverConfig& config, const SparsityPattern& pattern) {
  if (config.ordering != Ordering::Metis || config.type == LinearSolverType::Umfpack ||
      config.type == LinearSolverType::Iterative || config.type == LinearSolverType::SuperluDist)
    return {};
  const std::vector<Index> nodal = pattern.nested_dissection_order();
  return FillOrder(nodal.begin(), nodal.end());
}

LinearSolverPtr make_linear_solver(const LinearSolverConfig& config, SUNContext ctx,
                                   LinearSolverStats* stats, FillOrder order,
                                   const SaddlePointStructure* saddle) {
  switch (config.type) {
    case LinearSolverType::Klu:
      return make_klu_solver(config.ordering, ctx, stats, std::move(order));
    case LinearSolverType::Umfpack:
      return make_umfpack_solver(config.ordering, ctx, stats, std::move(order));
    case LinearSolverType::Mumps:
      return make_mumps_solver(config.ordering, config.precision, ctx, stats, std::move(order),
                               config.factor_folder());
    case LinearSolverType::Iterative:
      if (!saddle)
        throw std::invalid_argument("the iterative linear solver needs the saddle-point structure");
      return make_iterative_solver(config.krylov, *saddle, ctx, stats);
    case LinearSolverType::SuperluDist:
      throw std::invalid_argument(kSuperluDistNeedsProcesses);
  }
  return nullptr;
}

}  // namespace biphasic
