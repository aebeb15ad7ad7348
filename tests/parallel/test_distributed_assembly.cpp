// The distributed assembly on 1, 2 or 3 MPI processes (ctest label mpi): the residual, ∂F/∂t
// and Jacobian (dF/dy + c_j dF/dẏ and dF/dẏ) assembled into PETSc objects, row by row against
// the one-process problem of the whole mesh (every process computes that independently), the
// ghost exchange against the whole-mesh state, the Dirichlet values and constrained flags, and a
// failure on one process reaching all; each with every condition, and with the displaced face a
// rigid platen instead (its force row summed across the processes, its tie rows).
#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/box_mesh.hpp"
#include "../common/every_condition.hpp"
#include "biphasic/parallel/collective_failure.hpp"
#include "biphasic/parallel/distributed_assembly.hpp"

namespace biphasic {
namespace {

/// every_condition(), with `platen` also a rigid platen along y on y1 under a ramped force: a
/// face the parts share, whose nodes carry a traction and a flux and meet displacement,
/// symmetry and drained faces.
Config test_config(bool platen) {
  Config cfg = test::every_condition();
  if (platen) cfg.bcs.push_back({BcType::RigidPlaten, "y1", 1, -0.02, {}, "ramp"});
  return cfg;
}

class DistributedAssemblyTest : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    mesh_ = test::box_mesh({3, 3, 4}, {1.0, 0.8, 1.2});
    config_ = test_config(GetParam());
    whole_ = std::make_unique<BiphasicProblem>(mesh_, config_);
    dist_ = std::make_unique<DistributedAssembly>(mesh_, config_, PETSC_COMM_WORLD);
    // Serial unknown of each rank-major unknown.
    const PartitionedNumbering& num = dist_->numbering();
    const std::vector<Index> rank_major = rank_major_of_whole(mesh_.num_vertices, num);
    serial_of_.assign(static_cast<std::size_t>(num.size()), -1);
    for (std::size_t i = 0; i < rank_major.size(); ++i)
      serial_of_[static_cast<std::size_t>(rank_major[i])] = static_cast<Index>(i);
    // The same random state on every process, Dirichlet values set.
    test::random_state(*whole_, kTime, 3, y_, ydot_);
    y_vec_ = owned_copy(y_);
    ydot_vec_ = owned_copy(ydot_);
  }
  void TearDown() override {
    VecDestroy(&y_vec_);
    VecDestroy(&ydot_vec_);
  }

  /// A distributed vector holding the owned entries of a serial-layout vector.
  Vec owned_copy(const std::vector<double>& serial) {
    Vec v = dist_->new_vector();
    PetscScalar* a = nullptr;
    VecGetArray(v, &a);
    for (Index k = 0; k < dist_->owned_size(); ++k)
      a[k] = serial[static_cast<std::size_t>(serial_of(dist_->first_owned() + k))];
    VecRestoreArray(v, &a);
    return v;
  }
  Index serial_of(Index global) const { return serial_of_[static_cast<std::size_t>(global)]; }

  static constexpr double kTime = 1.3;
  Mesh mesh_;
  Config config_;
  std::unique_ptr<BiphasicProblem> whole_;
  std::unique_ptr<DistributedAssembly> dist_;
  std::vector<Index> serial_of_;
  std::vector<double> y_, ydot_;
  Vec y_vec_ = nullptr, ydot_vec_ = nullptr;
};

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST_P(DistributedAssemblyTest, GhostExchangeGivesEveryLocalUnknownItsValue) {
  std::vector<double> local;
  dist_->to_local(y_vec_, local);
  const SubdomainDofs& dofs = dist_->dofs();
  for (Index i = 0; i < dofs.size(); ++i)
    ASSERT_EQ(local[static_cast<std::size_t>(i)],
              y_[static_cast<std::size_t>(serial_of(dofs.global(i)))]);
}

TEST_P(DistributedAssemblyTest, ResidualAndTimeDerivativeMatchTheWholeMesh) {
  const auto n = static_cast<std::size_t>(whole_->size());
  std::vector<double> F(n), dFdt(n);
  whole_->residual(kTime, y_.data(), ydot_.data(), F.data());
  whole_->time_derivative(kTime, dFdt.data());
  Vec Fv = dist_->new_vector(), dv = dist_->new_vector();
  dist_->residual(kTime, y_vec_, ydot_vec_, Fv);
  dist_->time_derivative(kTime, dv);
  const PetscScalar* a = nullptr;
  const PetscScalar* b = nullptr;
  VecGetArrayRead(Fv, &a);
  VecGetArrayRead(dv, &b);
  for (Index k = 0; k < dist_->owned_size(); ++k) {
    const auto s = static_cast<std::size_t>(serial_of(dist_->first_owned() + k));
    ASSERT_NEAR(a[k], F[s], 1e-12 * max_abs(F)) << "serial row " << s;
    ASSERT_NEAR(b[k], dFdt[s], 1e-12 * max_abs(dFdt)) << "serial row " << s;
  }
  VecRestoreArrayRead(Fv, &a);
  VecRestoreArrayRead(dv, &b);
  VecDestroy(&Fv);
  VecDestroy(&dv);
}

TEST_P(DistributedAssemblyTest, JacobianMatchesTheWholeMesh) {
  const double cj = 2.5;
  const SparsityPattern& pattern = whole_->pattern();
  std::vector<double> values(static_cast<std::size_t>(pattern.nnz())), rates(values.size());
  whole_->jacobian(kTime, y_.data(), ydot_.data(), cj, values.data(), rates.data());
  Mat J = dist_->new_matrix(), R = dist_->new_matrix();
  // Twice: the second assembly must replace the first's values, not add to them.
  dist_->jacobian(kTime, y_vec_, ydot_vec_, cj, J, R);
  dist_->jacobian(kTime, y_vec_, ydot_vec_, cj, J, R);
  for (auto [matrix, serial] : {std::pair{J, &values}, std::pair{R, &rates}}) {
    const double scale = max_abs(*serial);
    // Rows of the whole matrix, by serial row: column → value.
    std::vector<std::map<Index, double>> rows(static_cast<std::size_t>(pattern.size()));
    for (Index j = 0; j < pattern.size(); ++j)
      for (Index k = pattern.colptr()[static_cast<std::size_t>(j)];
           k < pattern.colptr()[static_cast<std::size_t>(j) + 1]; ++k)
        rows[static_cast<std::size_t>(pattern.rowind()[static_cast<std::size_t>(k)])][j] =
            (*serial)[static_cast<std::size_t>(k)];
    for (Index k = 0; k < dist_->owned_size(); ++k) {
      const auto row = static_cast<PetscInt>(dist_->first_owned() + k);
      const std::map<Index, double>& expected = rows[static_cast<std::size_t>(serial_of(row))];
      PetscInt ncols = 0;
      const PetscInt* cols = nullptr;
      const PetscScalar* vals = nullptr;
      MatGetRow(matrix, row, &ncols, &cols, &vals);
      std::map<Index, double> got;
      for (PetscInt c = 0; c < ncols; ++c) got[serial_of(cols[c])] = vals[c];
      MatRestoreRow(matrix, row, &ncols, &cols, &vals);
      const char* which = matrix == J ? "dF/dy + cj dF/dydot" : "dF/dydot";
      for (const auto& [col, v] : expected) {
        const auto it = got.find(col);
        ASSERT_NEAR(it == got.end() ? 0.0 : it->second, v, 1e-12 * scale)
            << which << ", serial entry (" << serial_of(row) << ", " << col << ")";
      }
      for (const auto& [col, v] : got)
        if (!expected.count(col)) {
          ASSERT_EQ(v, 0.0) << which << ", outside the pattern: " << col;
        }
    }
  }
  MatDestroy(&J);
  MatDestroy(&R);
}

TEST_P(DistributedAssemblyTest, PlatenIsTheWholeMeshsOne) {
  // The master, unknowns and area of the one-process platen; the tied unknowns constrained.
  const RigidPlatens& mine = dist_->platens().platens();
  const RigidPlatens& serial = whole_->platens();
  ASSERT_EQ(mine.platens().size(), serial.platens().size());
  ASSERT_EQ(mine.empty(), !GetParam());
  for (std::size_t k = 0; k < mine.platens().size(); ++k) {
    EXPECT_EQ(mine.platens()[k].master, serial.platens()[k].master);
    EXPECT_EQ(mine.platens()[k].dofs, serial.platens()[k].dofs);
    EXPECT_EQ(mine.platens()[k].area, serial.platens()[k].area);
  }
  const std::vector<char>& tied = dist_->platens().tied();
  if (GetParam()) {
    // The platen spans the parts: its force row sums rows of several processes.
    int here = std::count(tied.begin(), tied.end(), 1) > 0 ? 1 : 0, owners = 0, size = 1;
    MPI_Allreduce(&here, &owners, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    EXPECT_GE(owners, std::min(size, 2)) << "processes owning tied unknowns";
  }
  const std::vector<char>& local = dist_->local_problem().constrained();
  for (Index k = 0; k < dist_->owned_size(); ++k) {
    const auto s = static_cast<std::size_t>(serial_of(dist_->first_owned() + k));
    const Index l = dist_->dofs().owned()[static_cast<std::size_t>(k)];
    const bool constrained = local[static_cast<std::size_t>(l)] != 0 ||
                             (!tied.empty() && tied[static_cast<std::size_t>(k)] != 0);
    EXPECT_EQ(constrained, whole_->constrained()[s] != 0) << "serial unknown " << s;
  }
}

TEST_P(DistributedAssemblyTest, DirichletValuesMatchTheWholeMesh) {
  // Free entries 9 (a platen's master too, so its tied entries become 9), rates 0.5.
  const auto n = static_cast<std::size_t>(whole_->size());
  std::vector<double> ys(n, 9.0), ydots(n, 0.5);
  whole_->apply_dirichlet(kTime, ys.data(), ydots.data());
  Vec y = dist_->new_vector(), ydot = dist_->new_vector();
  VecSet(y, 9.0);
  VecSet(ydot, 0.5);
  dist_->apply_dirichlet(kTime, y, ydot);
  const PetscScalar* a = nullptr;
  const PetscScalar* b = nullptr;
  VecGetArrayRead(y, &a);
  VecGetArrayRead(ydot, &b);
  for (Index k = 0; k < dist_->owned_size(); ++k) {
    const auto s = static_cast<std::size_t>(serial_of(dist_->first_owned() + k));
    EXPECT_EQ(a[k], ys[s]) << "serial unknown " << s;
    EXPECT_EQ(b[k], ydots[s]) << "serial rate " << s;
  }
  VecRestoreArrayRead(y, &a);
  VecRestoreArrayRead(ydot, &b);
  VecDestroy(&y);
  VecDestroy(&ydot);
}

INSTANTIATE_TEST_SUITE_P(Conditions, DistributedAssemblyTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return param.param ? "RigidPlaten" : "EveryCondition";
                         });

TEST(DistributedPlatens, AHeldPlatenNodeIsRefusedAsInOneProcess) {
  // z1 held along y meets the platen on y1 along y: the edge's nodes cannot move with it.
  const Mesh mesh = test::box_mesh({3, 3, 4}, {1.0, 0.8, 1.2});
  Config cfg = test_config(true);
  cfg.bcs.push_back({BcType::Displacement, "z1", 1, 0.0, {}, ""});
  std::string serial;
  try {
    BiphasicProblem whole(mesh, cfg);
  } catch (const std::runtime_error& e) {
    serial = e.what();
  }
  ASSERT_NE(serial.find("is also held along the platen's component"), std::string::npos) << serial;
  try {
    DistributedAssembly dist(mesh, cfg, PETSC_COMM_WORLD);
    FAIL() << "no refusal";
  } catch (const std::invalid_argument& e) {  // bad input on every process, worded alike
    EXPECT_EQ(std::string(e.what()), serial);
  }
}

TEST(CollectiveFailure, AFailureOnTheLastProcessReachesEveryProcess) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  try {
    run_collectively(PETSC_COMM_WORLD, [&] {
      if (rank == size - 1) throw InvertedElement("element 7: det F = -0.1");
    });
    FAIL() << "no exception on process " << rank;
  } catch (const InvertedElement& e) {
    const std::string expected =
        (size > 1 ? "process " + std::to_string(size - 1) + ": " : std::string()) +
        "element 7: det F = -0.1";
    EXPECT_EQ(std::string(e.what()), expected);
  }
  EXPECT_NO_THROW(run_collectively(PETSC_COMM_WORLD, [] {}));
  // Bad input stays bad input (exit status 1), whichever process found it.
  EXPECT_THROW(run_collectively(PETSC_COMM_WORLD,
                                [&] {
                                  if (rank == 0) throw std::invalid_argument("key = value");
                                }),
               std::invalid_argument);
}

}  // namespace
}  // namespace biphasic
