#include "biphasic/time/semidiscrete_system.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>

namespace biphasic {

N_Vector SemidiscreteSystem::new_vector(SUNContext ctx) const { return N_VNew_Serial(size(), ctx); }

double SemidiscreteSystem::max_norm(const double* v) const {
  double m = 0.0;
  for (Index i = 0; i < size(); ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

SUNMatrix SemidiscreteSystem::new_jacobian_matrix(SUNContext ctx) const {
  return pattern().new_matrix(ctx);
}

void SemidiscreteSystem::jacobian_into(double t, const double* y, const double* ydot, double cj,
                                       SUNMatrix J, double* rate_values) {
  // KINSOL and IDA zero the index arrays with the values before every Jacobian call.
  pattern().restore_into(J);
  jacobian(t, y, ydot, cj, SUNSparseMatrix_Data(J), rate_values);
}

LinearSolverPtr SemidiscreteSystem::new_linear_solver(const LinearSolverConfig& config,
                                                      SUNContext ctx, LinearSolverStats* stats,
                                                      const SaddlePointStructure* saddle) const {
  return make_linear_solver(config, ctx, stats, fill_order(config, pattern()), saddle);
}

LinearSolverPtr SemidiscreteSystem::new_shift_corrected_solver(LinearSolverPtr inner,
                                                               ShiftedMatrixFamily* family,
                                                               SUNContext ctx,
                                                               LinearSolverStats* stats,
                                                               double rtol, int max_iterations) {
  family->rate_values.assign(static_cast<std::size_t>(pattern().nnz()), 0.0);
  return make_shift_corrected_solver(std::move(inner), family, ctx, stats, rtol, max_iterations);
}

}  // namespace biphasic
