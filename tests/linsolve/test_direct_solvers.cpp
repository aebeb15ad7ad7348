// Each sparse direct solver behind the SUNLinearSolver interface solves the assembled P2/P1
// system to round-off with each ordering (MUMPS also with single-precision factors and
// refinement) and reuses its analysis across setups; backward Euler gives the same answer
// whichever solver is chosen.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "../common/factor_files.hpp"
#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/study/paper_scene.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "box_system.hpp"

namespace biphasic {
namespace {

struct SolverChoice {
  LinearSolverType type;
  Ordering ordering;
  FactorPrecision precision = FactorPrecision::Double;

  LinearSolverConfig config() const {
    LinearSolverConfig c;
    c.type = type;
    c.ordering = ordering;
    c.precision = precision;
    return c;
  }
};
class DirectSolver : public ::testing::TestWithParam<SolverChoice> {};

std::string choice_name(const SolverChoice& c) {
  const char* type[] = {"klu", "umfpack", "mumps"};
  std::string name = std::string(type[static_cast<int>(c.type)]) + "_" + to_string(c.ordering);
  if (c.type == LinearSolverType::Mumps) name += "_" + to_string(c.precision);
  return name;
}

/// max_i |b − A x|_i / (|A| |x| + |b|)_i.
double componentwise_backward_error(SUNMatrix A, N_Vector x, N_Vector b) {
  const sunindextype n = SUNSparseMatrix_Columns(A);
  std::vector<double> r(N_VGetArrayPointer(b), N_VGetArrayPointer(b) + n), s(n);
  for (sunindextype i = 0; i < n; ++i) s[i] = std::abs(r[i]);
  for (sunindextype j = 0; j < n; ++j)
    for (sunindextype q = SUNSparseMatrix_IndexPointers(A)[j];
         q < SUNSparseMatrix_IndexPointers(A)[j + 1]; ++q) {
      const double t = SUNSparseMatrix_Data(A)[q] * NV_Ith_S(x, j);
      r[SUNSparseMatrix_IndexValues(A)[q]] -= t;
      s[SUNSparseMatrix_IndexValues(A)[q]] += std::abs(t);
    }
  double omega = 0.0;
  for (sunindextype i = 0; i < n; ++i) omega = std::max(omega, std::abs(r[i]) / s[i]);
  return omega;
}

TEST_P(DirectSolver, SolvesAssembledSystem) {
  test::BoxSystem sys("gls", 1.0 / 6.4);
  LinearSolverStats stats;
  LinearSolverPtr ls = make_linear_solver(GetParam().config(), sys.ctx, &stats);
  for (int round = 0; round < 2; ++round) {
    ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ls.get(), sys.A, sys.x, sys.b, 0.0), SUNLS_SUCCESS);
    const double err = sys.max_error();
    if (GetParam().precision == FactorPrecision::Double) {
      EXPECT_LT(err, 1e-8) << "round " << round;
    } else {
      // Refined to a componentwise backward error of 1e-6; the forward error is at most the
      // condition number times that.
      EXPECT_LE(componentwise_backward_error(sys.A, sys.x, sys.b), 1e-6) << "round " << round;
      EXPECT_LT(err, 1e-4) << "round " << round;
    }
  }
  EXPECT_EQ(stats.analyses, 1);
  EXPECT_EQ(stats.factorizations, 2);
  EXPECT_EQ(stats.precision_fallbacks, 0);
  if (GetParam().type == LinearSolverType::Klu) {
    EXPECT_EQ(stats.refactorizations, 1);
  }
  EXPECT_GT(stats.fill, 1.0);
}

const SolverChoice kChoices[] = {
    {LinearSolverType::Klu, Ordering::Amd},
    {LinearSolverType::Klu, Ordering::Colamd},
    {LinearSolverType::Klu, Ordering::Metis},
    {LinearSolverType::Umfpack, Ordering::Amd},
    {LinearSolverType::Umfpack, Ordering::Metis},
    {LinearSolverType::Mumps, Ordering::Amd},
    {LinearSolverType::Mumps, Ordering::Metis},
    {LinearSolverType::Mumps, Ordering::Amd, FactorPrecision::Mixed},
    {LinearSolverType::Mumps, Ordering::Metis, FactorPrecision::Mixed}};

INSTANTIATE_TEST_SUITE_P(All, DirectSolver, ::testing::ValuesIn(kChoices),
                         [](const auto& param_info) { return choice_name(param_info.param); });

// Rows with a diagonal entry only (the box's Dirichlet rows) leave MUMPS's factorisation: the
// solution is unchanged, and a later matrix in which such a row is coupled is analysed again.
TEST(MumpsDecoupledRows, SameSolutionAndAnalysedAgainWhenARowIsCoupledLater) {
  for (const FactorPrecision precision : {FactorPrecision::Double, FactorPrecision::Mixed}) {
    test::BoxSystem sys("gls", 1.0 / 6.4);
    const Index n = sys.problem.size();
    const sunindextype* Ap = SUNSparseMatrix_IndexPointers(sys.A);
    const sunindextype* Ai = SUNSparseMatrix_IndexValues(sys.A);
    double* a = SUNSparseMatrix_Data(sys.A);
    // A decoupled row (only its diagonal is non-zero) and an off-diagonal entry in it.
    std::vector<int> nonzeros(static_cast<std::size_t>(n), 0);
    for (sunindextype q = 0; q < Ap[n]; ++q)
      if (a[q] != 0.0) ++nonzeros[static_cast<std::size_t>(Ai[q])];
    const auto decoupled = std::count(nonzeros.begin(), nonzeros.end(), 1);
    ASSERT_GT(decoupled, 10) << "the box has Dirichlet rows";
    sunindextype coupled_entry = -1;
    for (sunindextype j = 0; j < n && coupled_entry < 0; ++j)
      for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q)
        if (Ai[q] != j && nonzeros[static_cast<std::size_t>(Ai[q])] == 1) {
          coupled_entry = q;
          break;
        }
    ASSERT_GE(coupled_entry, 0);

    LinearSolverStats stats;
    LinearSolverPtr ls = make_linear_solver(
        SolverChoice{LinearSolverType::Mumps, Ordering::Metis, precision}.config(), sys.ctx,
        &stats);
    const double tolerance = precision == FactorPrecision::Double ? 1e-8 : 1e-4;
    ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ls.get(), sys.A, sys.x, sys.b, 0.0), SUNLS_SUCCESS);
    EXPECT_LT(sys.max_error(), tolerance);
    EXPECT_EQ(stats.analyses, 1);

    // Couple the row and solve the new system: analysed again, still exact.
    a[coupled_entry] = 0.5 * a[coupled_entry - 1] + 0.25;
    sys.update_rhs();
    ASSERT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ls.get(), sys.A, sys.x, sys.b, 0.0), SUNLS_SUCCESS);
    EXPECT_LT(sys.max_error(), tolerance) << to_string(precision);
    EXPECT_EQ(stats.analyses, 2) << to_string(precision);
  }
}

// Pressure rows scaled by 1e-50 vanish in single precision: the mixed-precision MUMPS solver
// finds its single-precision factorisation singular, falls back to double-precision factors
// for four factorisations, then tries single precision again; it solves to round-off.
TEST(MumpsMixedPrecision, FallsBackToDoubleWhenSinglePrecisionFails) {
  test::BoxSystem sys("gls", 1.0 / 6.4);
  const Index n = sys.problem.size();
  const sunindextype* Ap = SUNSparseMatrix_IndexPointers(sys.A);
  const sunindextype* Ai = SUNSparseMatrix_IndexValues(sys.A);
  double* a = SUNSparseMatrix_Data(sys.A);
  for (sunindextype j = 0; j < n; ++j)
    for (sunindextype q = Ap[j]; q < Ap[j + 1]; ++q)
      if (Ai[q] >= sys.problem.num_u()) a[q] *= 1e-50;
  sys.update_rhs();

  LinearSolverStats stats;
  LinearSolverPtr ls = make_linear_solver(
      SolverChoice{LinearSolverType::Mumps, Ordering::Metis, FactorPrecision::Mixed}.config(),
      sys.ctx, &stats);
  ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSolve(ls.get(), sys.A, sys.x, sys.b, 0.0), SUNLS_SUCCESS);
  EXPECT_LT(sys.max_error(), 1e-8);
  EXPECT_EQ(stats.precision_fallbacks, 1);
  // The fallback lasts four factorisations (this one and three more); the fifth tries single
  // precision again and falls back again.
  for (int k = 0; k < 3; ++k) ASSERT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
  EXPECT_EQ(stats.precision_fallbacks, 1);
  ASSERT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
  EXPECT_EQ(stats.precision_fallbacks, 2);
  ASSERT_EQ(SUNLinSolSolve(ls.get(), sys.A, sys.x, sys.b, 0.0), SUNLS_SUCCESS);
  EXPECT_LT(sys.max_error(), 1e-8);
}

// Out-of-core MUMPS (linear_solver.out_of_core): while the solver lives its factors are files in
// the folder given, and they are gone when it ends; in double precision the solution is the
// in-memory one to round-off, in mixed precision it meets the same refinement target.
TEST(MumpsOutOfCore, FactorsAreFilesWhileTheSolverLivesAndSolveAsInMemory) {
  test::BoxSystem sys("gls", 1.0 / 6.4);
  const auto n = static_cast<std::size_t>(sys.problem.size());
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("biphasic_ooc_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  auto factor_files = [&] { return test::mumps_factor_files(folder); };
  for (const FactorPrecision precision : {FactorPrecision::Double, FactorPrecision::Mixed}) {
    SCOPED_TRACE(to_string(precision));
    LinearSolverConfig config =
        SolverChoice{LinearSolverType::Mumps, Ordering::Metis, precision}.config();
    auto solve = [&](LinearSolverConfig c, bool expect_files) {
      LinearSolverStats stats;
      LinearSolverPtr ls = make_linear_solver(c, sys.ctx, &stats);
      EXPECT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
      EXPECT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_SUCCESS);
      EXPECT_EQ(factor_files() > 0, expect_files);
      EXPECT_EQ(SUNLinSolSolve(ls.get(), sys.A, sys.x, sys.b, 0.0), SUNLS_SUCCESS);
      if (precision == FactorPrecision::Double)
        EXPECT_LT(sys.max_error(), 1e-8);
      else  // refined to the mixed precision's target
        EXPECT_LE(componentwise_backward_error(sys.A, sys.x, sys.b), 1e-6);
      EXPECT_EQ(stats.precision_fallbacks, 0);
      const double* x = N_VGetArrayPointer(sys.x);
      return std::vector<double>(x, x + n);
    };
    const std::vector<double> in_memory = solve(config, false);
    config.out_of_core = true;
    config.out_of_core_directory = folder.string();
    const std::vector<double> out_of_core = solve(config, true);
    EXPECT_EQ(factor_files(), 0);
    double diff = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      diff = std::max(diff, std::abs(out_of_core[i] - in_memory[i]));
      scale = std::max(scale, std::abs(in_memory[i]));
    }
    EXPECT_GT(scale, 0.0);
    // Double precision: the same factors, rounded in another order. Mixed: each solution
    // meets the refinement target, which leaves differences of its size.
    EXPECT_LT(diff, (precision == FactorPrecision::Double ? 1e-12 : 1e-4) * scale);
  }
  std::filesystem::remove_all(folder);
}

// A factor file MUMPS cannot write (here: its folder is gone, as when a disk fills up) is no
// singular matrix: the set-up fails unrecoverably with the cause, naming the folder, so that the
// integrator stops instead of cutting its step back.
TEST(MumpsOutOfCore, UnwritableFactorFilesStopWithTheCause) {
  test::BoxSystem sys("gls", 1.0 / 6.4);
  for (const FactorPrecision precision : {FactorPrecision::Double, FactorPrecision::Mixed}) {
    SCOPED_TRACE(to_string(precision));
    LinearSolverConfig config =
        SolverChoice{LinearSolverType::Mumps, Ordering::Metis, precision}.config();
    config.out_of_core = true;
    config.out_of_core_directory = "/nonexistent/biphasic_factor_folder";
    LinearSolverStats stats;
    LinearSolverPtr ls = make_linear_solver(config, sys.ctx, &stats);
    ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
    EXPECT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_PACKAGE_FAIL_UNREC);
    EXPECT_NE(stats.last_error.find("out-of-core factor files in "
                                    "/nonexistent/biphasic_factor_folder (INFOG(1) = -90)"),
              std::string::npos)
        << stats.last_error;
  }
}

// A folder without room for the factor files the analysis estimates stops the set-up before
// any is written, naming the folder and the sizes (a disk filling up under the parallel MUMPS's
// asynchronous writer could leave the processes waiting for each other). The full disk is a
// 1 MiB memory file system filled to the last byte, which needs mount privileges: skipped
// without them.
TEST(MumpsOutOfCore, AFolderWithoutRoomStopsBeforeFactorising) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("biphasic_full_disk_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::string mount = "mount -t tmpfs -o size=1M tmpfs " + folder.string() + " 2>/dev/null";
  if (std::system(mount.c_str()) != 0) {
    std::filesystem::remove(folder);
    GTEST_SKIP() << "mounting a small file system needs privileges this user lacks";
  }
  struct Unmount {  // also when an assertion ends the test early
    std::filesystem::path folder;
    ~Unmount() {
      EXPECT_EQ(std::system(("umount " + folder.string()).c_str()), 0);
      std::filesystem::remove_all(folder);
    }
  } unmount{folder};
  {
    std::FILE* fill = std::fopen((folder / "fill").c_str(), "wb");
    ASSERT_NE(fill, nullptr);
    const std::vector<char> block(4096, 0);
    while (std::fwrite(block.data(), 1, block.size(), fill) == block.size()) {
    }
    std::fclose(fill);
  }
  test::BoxSystem sys("gls", 1.0 / 6.4);
  LinearSolverConfig config =
      SolverChoice{LinearSolverType::Mumps, Ordering::Metis, FactorPrecision::Mixed}.config();
  config.out_of_core = true;
  config.out_of_core_directory = folder.string();
  LinearSolverStats stats;
  {
    LinearSolverPtr ls = make_linear_solver(config, sys.ctx, &stats);
    ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
    EXPECT_EQ(SUNLinSolSetup(ls.get(), sys.A), SUNLS_PACKAGE_FAIL_UNREC);
  }
  EXPECT_EQ(stats.factorizations, 0);
  EXPECT_NE(stats.last_error.find("the factor files need about"), std::string::npos)
      << stats.last_error;
  EXPECT_NE(stats.last_error.find("in " + folder.string() + ", which has 0 GB free"),
            std::string::npos)
      << stats.last_error;
}

// The reference loading (k = 1e-3, GLS, 5 steps) on a coarse quarter cylinder: the pressure
// field at t = 32 s agrees to 1e-8 (relative to its maximum) for every solver.
TEST(DirectSolvers, SameAnswerWhicheverSolver) {
  Config cfg = paper_reference_config(3.0);
  const Mesh mesh = generate_quarter_cylinder(cfg.mesh.cylinder);
  std::vector<double> reference;
  for (const SolverChoice& choice : kChoices) {
    cfg.linear_solver = choice.config();
    BiphasicProblem problem(mesh, cfg);
    BackwardEuler integrator(problem, cfg.time, cfg.linear_solver);
    std::vector<double> y(problem.size(), 0.0);
    integrator.run(0.0, y, nullptr);
    const std::vector<double> p(y.begin() + problem.num_u(), y.end());
    if (reference.empty()) {
      reference = p;
      continue;
    }
    double diff = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      diff = std::max(diff, std::abs(p[i] - reference[i]));
      scale = std::max(scale, std::abs(reference[i]));
    }
    EXPECT_GT(scale, 4e-3);
    EXPECT_LT(diff, 1e-8 * scale) << choice_name(choice);
  }
}

}  // namespace
}  // namespace biphasic
