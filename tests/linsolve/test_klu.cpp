// KLU behind the SUNLinearSolver interface solves the assembled P2/P1 system to round-off,
// with every ordering, and reuses its analysis across setups.
#include <gtest/gtest.h>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <random>

#include "../common/box_mesh.hpp"
#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic {
namespace {

class Klu : public ::testing::TestWithParam<Ordering> {};

TEST_P(Klu, SolvesAssembledSystem) {
  const Mesh mesh = test::box_mesh({3, 2, 2}, {1.5, 1.0, 1.0});
  Config cfg;
  cfg.stabilisation.type = Stabilisation::Gls;
  cfg.bcs = {{BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Symmetry, "x0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 0.0, {}, ""}};
  BiphasicProblem problem(mesh, cfg);
  const Index n = problem.size();
  std::vector<double> y(n, 0.0), ydot(n, 0.0);
  SUNContext ctx;
  ASSERT_EQ(SUNContext_Create(nullptr, &ctx), 0);
  SUNMatrix A = SUNSparseMatrix(n, n, problem.pattern().nnz(), CSC_MAT, ctx);
  std::copy(problem.pattern().colptr().begin(), problem.pattern().colptr().end(),
            SUNSparseMatrix_IndexPointers(A));
  std::copy(problem.pattern().rowind().begin(), problem.pattern().rowind().end(),
            SUNSparseMatrix_IndexValues(A));
  problem.jacobian(0.0, y.data(), ydot.data(), 1.0 / 6.4, SUNSparseMatrix_Data(A));

  LinearSolverStats stats;
  LinearSolverPtr ls = make_klu_solver(GetParam(), ctx, &stats);
  N_Vector x = N_VNew_Serial(n, ctx), b = N_VNew_Serial(n, ctx), r = N_VNew_Serial(n, ctx);
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> exact(n);
  for (auto& v : exact) v = d(gen);
  N_Vector xe = N_VMake_Serial(n, exact.data(), ctx);
  ASSERT_EQ(SUNMatMatvec(A, xe, b), 0);
  for (int round = 0; round < 2; ++round) {
    ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ls.get(), A), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ls.get(), A, x, b, 0.0), SUNLS_SUCCESS);
    double err = 0.0;
    for (Index i = 0; i < n; ++i) err = std::max(err, std::abs(NV_Ith_S(x, i) - exact[i]));
    EXPECT_LT(err, 1e-8) << "round " << round;
  }
  EXPECT_EQ(stats.analyses, 1);
  EXPECT_EQ(stats.factorizations, 2);
  EXPECT_EQ(stats.refactorizations, 1);
  EXPECT_GT(stats.fill, 1.0);
  for (N_Vector v : {x, b, r, xe}) N_VDestroy(v);
  SUNMatDestroy(A);
  ls.reset();
  SUNContext_Free(&ctx);
}

INSTANTIATE_TEST_SUITE_P(Orderings, Klu,
                         ::testing::Values(Ordering::Amd, Ordering::Colamd, Ordering::Metis),
                         [](const auto& param_info) { return to_string(param_info.param); });

}  // namespace
}  // namespace biphasic
