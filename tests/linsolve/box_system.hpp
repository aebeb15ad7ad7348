// The small system the linear-solver tests factorise or iterate on: a 3×2×2 box mesh, bottom
// fixed axially, two symmetry planes, drained top.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic::test {

inline Mesh solver_box_mesh() { return box_mesh({3, 2, 2}, {1.5, 1.0, 1.0}); }

inline Config solver_box_config(std::string stabilisation) {
  Config cfg;
  cfg.stabilisation.type = stabilisation;
  cfg.bcs = {{BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Symmetry, "x0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 0.0, {}, ""}};
  return cfg;
}

/// A reproducible solution vector, entries uniform in [−1, 1].
inline std::vector<double> random_unknowns(Index n) {
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = d(gen);
  return v;
}

/// The box problem's Jacobian at rest with ẏ-shift cj in a SUNSparseMatrix, the right-hand
/// side b = A x_exact of a reproducible random solution, and a vector x for the solver's answer;
/// the SUNDIALS objects are freed on destruction (destroy the linear solver first).
struct BoxSystem {
  BoxSystem(std::string stabilisation, double cj)
      : mesh(solver_box_mesh()), config(solver_box_config(stabilisation)), problem(mesh, config) {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
    const Index n = problem.size();
    std::vector<double> y(n, 0.0), ydot(n, 0.0);
    A = problem.pattern().new_matrix(ctx);
    problem.jacobian(0.0, y.data(), ydot.data(), cj, SUNSparseMatrix_Data(A));
    exact = random_unknowns(n);
    x = N_VNew_Serial(n, ctx);
    b = N_VNew_Serial(n, ctx);
    update_rhs();
  }
  ~BoxSystem() {
    N_VDestroy(x);
    N_VDestroy(b);
    SUNMatDestroy(A);
    SUNContext_Free(&ctx);
  }
  BoxSystem(const BoxSystem&) = delete;
  BoxSystem& operator=(const BoxSystem&) = delete;

  /// b = A x_exact again, after A was changed.
  void update_rhs() {
    N_Vector xe = N_VMake_Serial(problem.size(), exact.data(), ctx);
    if (SUNMatMatvec(A, xe, b) != 0) throw std::runtime_error("SUNMatMatvec failed");
    N_VDestroy(xe);
  }
  /// max_i |x_i − x_exact_i|.
  double max_error() const {
    double err = 0.0;
    for (Index i = 0; i < problem.size(); ++i)
      err = std::max(err, std::abs(NV_Ith_S(x, i) - exact[i]));
    return err;
  }

  Mesh mesh;
  Config config;
  BiphasicProblem problem;
  SUNContext ctx = nullptr;
  SUNMatrix A = nullptr;
  std::vector<double> exact;
  N_Vector x = nullptr, b = nullptr;
};

}  // namespace biphasic::test
