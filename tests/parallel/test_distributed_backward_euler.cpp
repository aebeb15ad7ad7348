// Backward Euler (KINSOL) on the distributed system against the one-process run of the same
// case (UMFPACK): every owned unknown after four steps of a ramped compression with GLS and
// every kind of boundary condition, and the Newton iterations step by step. Solved by the
// parallel MUMPS called directly (double and mixed precision, the mesh's nested-dissection
// order and PORD), by SuperLU_DIST through PETSc, and by FGMRES with the field-split
// preconditioner; on tetrahedra and on the sections of both two-dimensional models.
#include <gtest/gtest.h>
#include <nvector/nvector_parallel.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "../common/box_mesh.hpp"
#include "../common/every_condition.hpp"
#include "../common/factor_files.hpp"
#include "biphasic/parallel/distributed_system.hpp"
#include "biphasic/parallel/petsc_linear_solver.hpp"
#include "biphasic/physics/section_problem.hpp"
#include "biphasic/time/backward_euler.hpp"

namespace biphasic {
namespace {

/// A section rectangle for the two-dimensional models.
SectionMesh section_mesh() {
  SectionRectangleSpec spec;
  spec.width = 1.0;
  spec.height = 1.2;
  spec.nr = 4;
  spec.nz = 5;
  return generate_section_rectangle(spec);
}

BiphasicProblem one_process_problem(const Mesh& mesh, const Config& config) {
  return BiphasicProblem(mesh, config);
}
SectionProblem one_process_problem(const SectionMesh& mesh, const Config& config) {
  return SectionProblem(mesh, section_model(config.model), config);
}

/// expect_same_run on `mesh`; `each_step` (if any) runs after each step of the distributed run.
template <class AnyMesh>
void expect_same_run_on(const AnyMesh& mesh, const Config& config, const LinearSolverConfig& solver,
                        double tolerance, const std::function<void()>& each_step = {}) {
  // One process: UMFPACK (the sequential MUMPS is not part of the MPI build).
  auto whole = one_process_problem(mesh, config);
  LinearSolverConfig serial_solver;
  serial_solver.type = LinearSolverType::Umfpack;
  BackwardEuler serial(whole, config.time, serial_solver);
  std::vector<double> y_serial(static_cast<std::size_t>(whole.size()), 0.0);
  whole.apply_dirichlet(0.0, y_serial.data(), nullptr);
  std::vector<int> iterations_serial;
  serial.run(0.0, y_serial,
             [&](const StepInfo& info, const std::vector<double>&, const std::vector<double>&) {
               iterations_serial.push_back(info.newton_iterations);
             });

  DistributedAssembly assembly(mesh, config, PETSC_COMM_WORLD);
  DistributedSystem system(assembly);
  BackwardEuler parallel(system, config.time, solver);
  std::vector<double> y(static_cast<std::size_t>(system.size()), 0.0);
  system.apply_dirichlet(0.0, y.data(), nullptr);
  std::vector<int> iterations;
  parallel.run(0.0, y,
               [&](const StepInfo& info, const std::vector<double>&, const std::vector<double>&) {
                 iterations.push_back(info.newton_iterations);
                 if (each_step) each_step();
               });
  EXPECT_EQ(iterations, iterations_serial);

  // Owned unknown k is rank-major unknown first_owned() + k.
  const PartitionedNumbering& num = assembly.numbering();
  const std::vector<Index> rank_major = rank_major_of_whole(mesh.num_vertices, num);
  std::vector<Index> serial_of(rank_major.size());
  for (std::size_t i = 0; i < rank_major.size(); ++i)
    serial_of[static_cast<std::size_t>(rank_major[i])] = static_cast<Index>(i);
  double u_max = 0.0, p_max = 0.0;
  for (Index i = 0; i < whole.size(); ++i)
    (i < whole.num_u() ? u_max : p_max) = std::max(i < whole.num_u() ? u_max : p_max,
                                                   std::abs(y_serial[static_cast<std::size_t>(i)]));
  ASSERT_GT(u_max, 0.0);
  ASSERT_GT(p_max, 0.0);
  for (Index k = 0; k < system.size(); ++k) {
    const Index s = serial_of[static_cast<std::size_t>(assembly.first_owned() + k)];
    const double scale = s < whole.num_u() ? u_max : p_max;
    ASSERT_NEAR(y[static_cast<std::size_t>(k)], y_serial[static_cast<std::size_t>(s)],
                tolerance * scale)
        << "serial unknown " << s;
  }
}

/// Four steps on one process (UMFPACK) and on the distributed system with `solver`: the same
/// Newton iterations and every unknown within `tolerance` of the largest of its field. On the
/// box of tetrahedra for a three-dimensional `config`, else on section_mesh().
void expect_same_run(const Config& config, const LinearSolverConfig& solver, double tolerance,
                     const std::function<void()>& each_step = {}) {
  if (is_two_dimensional(config.model))
    expect_same_run_on(section_mesh(), config, solver, tolerance, each_step);
  else
    expect_same_run_on(test::box_mesh({3, 3, 4}, {1.0, 0.8, 1.2}), config, solver, tolerance,
                       each_step);
}

Config four_steps(const std::string& stabilisation, ModelKind model = ModelKind::ThreeDimensional) {
  Config config =
      is_two_dimensional(model) ? test::every_section_condition(model) : test::every_condition();
  config.stabilisation.type = stabilisation;
  config.time.dt = 0.5;
  config.time.t_end = 2.0;
  return config;
}

TEST(DistributedBackwardEuler, ParallelMumpsMatchesTheOneProcessRun) {
  for (const FactorPrecision precision : {FactorPrecision::Double, FactorPrecision::Mixed})
    for (const Ordering ordering : {Ordering::Metis, Ordering::Amd}) {
      SCOPED_TRACE(precision == FactorPrecision::Double ? "double" : "mixed");
      SCOPED_TRACE(ordering == Ordering::Metis ? "nested dissection of the mesh" : "PORD");
      LinearSolverConfig solver;
      solver.precision = precision;
      solver.ordering = ordering;
      for (const ModelKind model :
           {ModelKind::ThreeDimensional, ModelKind::PlaneStrain, ModelKind::Axisymmetric}) {
        SCOPED_TRACE(to_string(model));
        expect_same_run(four_steps("gls", model), solver, 1e-8);
      }
    }
}

// Out-of-core factors (linear_solver.out_of_core): every process keeps its factors in files in
// the folder given while the run goes on (counted after each step), the run is the in-memory
// one's to 1e-8, and no file is left when the solver ends.
TEST(DistributedBackwardEuler, OutOfCoreParallelMumpsMatchesTheOneProcessRun) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  long id = static_cast<long>(getpid());
  MPI_Bcast(&id, 1, MPI_LONG, 0, PETSC_COMM_WORLD);
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("biphasic_ooc_test_" + std::to_string(id));
  if (rank == 0) std::filesystem::create_directories(folder);
  MPI_Barrier(PETSC_COMM_WORLD);
  auto factor_files = [&] { return test::mumps_factor_files(folder); };
  for (const FactorPrecision precision : {FactorPrecision::Double, FactorPrecision::Mixed}) {
    SCOPED_TRACE(precision == FactorPrecision::Double ? "double" : "mixed");
    LinearSolverConfig solver;
    solver.precision = precision;
    solver.out_of_core = true;
    solver.out_of_core_directory = folder.string();
    int fewest = -1;
    expect_same_run(four_steps("gls"), solver, 1e-8, [&] {
      const int now = factor_files();
      fewest = fewest < 0 ? now : std::min(fewest, now);
    });
    EXPECT_GE(fewest, size);  // every process's factors, on this one machine
    MPI_Barrier(PETSC_COMM_WORLD);
    EXPECT_EQ(factor_files(), 0);
  }
  MPI_Barrier(PETSC_COMM_WORLD);
  if (rank == 0) std::filesystem::remove_all(folder);
}

TEST(DistributedBackwardEuler, SuperluDistMatchesTheOneProcessRun) {
  for (const char* stabilisation : {"none", "gls"}) {
    SCOPED_TRACE(stabilisation);
    LinearSolverConfig solver;
    solver.type = LinearSolverType::SuperluDist;
    expect_same_run(four_steps(stabilisation), solver, 1e-8);
    expect_same_run(four_steps(stabilisation, ModelKind::Axisymmetric), solver, 1e-8);
  }
}

TEST(DistributedBackwardEuler, FieldSplitFgmresMatchesTheOneProcessRun) {
  for (const char* stabilisation : {"none", "flux_perturbation"}) {
    SCOPED_TRACE(stabilisation);
    LinearSolverConfig solver;
    solver.type = LinearSolverType::Iterative;
    solver.krylov.rtol = 1e-10;
    for (const ModelKind model :
         {ModelKind::ThreeDimensional, ModelKind::PlaneStrain, ModelKind::Axisymmetric}) {
      SCOPED_TRACE(to_string(model));
      expect_same_run(four_steps(stabilisation, model), solver, 1e-7);
    }
  }
}

// The mixed-precision parallel MUMPS falls back to double precision when its single-precision
// factorisation fails, as one process does (test_direct_solvers.cpp): the pressure rows of the
// box problem's Jacobian scaled by 1e-50 vanish in single precision, so the first set-up falls
// back, reading the matrix again in double precision, and the solve is exact to 1e-8.
TEST(DistributedMumps, FallsBackToDoubleWhenSinglePrecisionFails) {
  const Mesh mesh = test::box_mesh({3, 3, 4}, {1.0, 0.8, 1.2});
  const Config config = four_steps("gls");
  DistributedAssembly assembly(mesh, config, PETSC_COMM_WORLD);
  DistributedSystem system(assembly);
  SUNContext ctx = nullptr;
  ASSERT_EQ(SUNContext_Create(nullptr, &ctx), 0);
  {
    SUNMatrix A = system.new_jacobian_matrix(ctx);
    const auto n = static_cast<std::size_t>(system.size());
    std::vector<double> y(n, 0.0), ydot(n, 0.0);
    system.apply_dirichlet(0.5, y.data(), ydot.data());
    system.jacobian_into(0.5, y.data(), ydot.data(), 2.0, A);
    Mat J = petsc_matrix(A);
    // Rows scaled: 1 for the displacements, 1e-50 for the pressures.
    Vec scale = assembly.new_vector();
    PetscScalar* s = nullptr;
    VecGetArray(scale, &s);
    for (Index i = 0; i < system.size(); ++i) s[i] = i < system.num_u() ? 1.0 : 1e-50;
    VecRestoreArray(scale, &s);
    MatDiagonalScale(J, scale, nullptr);
    // b = J x for a known x.
    N_Vector x = system.new_vector(ctx), b = system.new_vector(ctx), exact = system.new_vector(ctx);
    for (Index i = 0; i < system.size(); ++i)
      NV_Ith_P(exact, i) = std::sin(1.0 + static_cast<double>(assembly.first_owned() + i));
    Vec xv = nullptr, bv = nullptr;
    VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, static_cast<PetscInt>(system.size()),
                          PETSC_DETERMINE, NV_DATA_P(exact), &xv);
    VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, static_cast<PetscInt>(system.size()),
                          PETSC_DETERMINE, NV_DATA_P(b), &bv);
    MatMult(J, xv, bv);

    LinearSolverStats stats;
    LinearSolverConfig solver;
    solver.precision = FactorPrecision::Mixed;
    LinearSolverPtr ls = system.new_linear_solver(solver, ctx, &stats, nullptr);
    ASSERT_EQ(SUNLinSolInitialize(ls.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ls.get(), A), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ls.get(), A, x, b, 0.0), SUNLS_SUCCESS);
    EXPECT_EQ(stats.precision_fallbacks, 1);
    double error = 0.0, largest = 0.0;
    for (Index i = 0; i < system.size(); ++i) {
      error = std::max(error, std::abs(NV_Ith_P(x, i) - NV_Ith_P(exact, i)));
      largest = std::max(largest, std::abs(NV_Ith_P(exact, i)));
    }
    MPI_Allreduce(MPI_IN_PLACE, &error, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
    EXPECT_LT(error, 1e-8 * largest);
    ls.reset();
    VecDestroy(&xv);
    VecDestroy(&bv);
    VecDestroy(&scale);
    for (N_Vector v : {x, b, exact}) N_VDestroy(v);
    SUNMatDestroy(A);
  }
  SUNContext_Free(&ctx);
}

}  // namespace
}  // namespace biphasic
