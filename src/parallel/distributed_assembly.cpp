#include "biphasic/parallel/distributed_assembly.hpp"

#include <petscis.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "biphasic/mesh/nested_dissection.hpp"
#include "biphasic/parallel/collective_failure.hpp"
#include "biphasic/parallel/petsc_check.hpp"
#include "biphasic/physics/assembly_scope.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {

namespace {

PetscInt petsc_index(Index i) {
  if (i > std::numeric_limits<PetscInt>::max())
    throw std::runtime_error("PETSc: unknown " + std::to_string(i) +
                             " exceeds this PETSc build's 32-bit indices");
  return static_cast<PetscInt>(i);
}

/// The partition of process 0, broadcast: every process then works on the same split.
template <class AnyMesh>
MeshPartition shared_partition(const AnyMesh& mesh, std::size_t num_elements, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  MeshPartition p;
  int failed = 0;
  std::string message;
  if (rank == 0) {
    try {
      p = partition_mesh(mesh, size);
    } catch (const std::exception& e) {
      failed = 1;
      message = e.what();
    }
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed) throw std::runtime_error(broadcast_string(message, 0, comm));
  p.parts = size;
  p.element_part.resize(num_elements);
  MPI_Bcast(p.element_part.data(), static_cast<int>(p.element_part.size()), MPI_INT, 0, comm);
  assign_node_owners(mesh, p);
  return p;
}

}  // namespace

DistributedAssembly::DistributedAssembly(const Mesh& mesh, const Config& config, MPI_Comm comm)
    : comm_(comm) {
  build(mesh, mesh.tets.size(), sub_, config, [&] {
    platens_ = std::make_unique<DistributedPlatens>(mesh, config);
    AssemblyScope scope = subdomain_scope(mesh, sub_);
    if (!platens_->empty()) scope.platens = &platens_->platens();
    auto problem = std::make_unique<BiphasicProblem>(sub_.mesh, config, std::move(scope));
    body_ = problem.get();
    return problem;
  });
}

DistributedAssembly::DistributedAssembly(const SectionMesh& mesh, const Config& config,
                                         MPI_Comm comm)
    : comm_(comm) {
  const SectionModel model = section_model(config.model);
  build(mesh, mesh.triangles.size(), section_sub_, config, [&] {
    platens_ =
        std::make_unique<DistributedPlatens>(mesh, model == SectionModel::Axisymmetric, config);
    AssemblyScope scope = subdomain_scope(mesh, section_sub_, model);
    if (!platens_->empty()) scope.platens = &platens_->platens();
    auto problem =
        std::make_unique<SectionProblem>(section_sub_.mesh, model, config, std::move(scope));
    section_ = problem.get();
    return problem;
  });
}

template <class AnyMesh, class Part, class MakeProblem>
void DistributedAssembly::build(const AnyMesh& mesh, std::size_t num_elements, Part& sub,
                                const Config& config, MakeProblem make_problem) {
  MPI_Comm_rank(comm_, &rank_);
  const MeshPartition partition = shared_partition(mesh, num_elements, comm_);
  numbering_ = number_unknowns(mesh, partition);
  petsc_index(numbering_.size());
  run_collectively(comm_, [&] {
    sub = extract_subdomain(mesh, partition, rank_);
    map_ = &sub;
    problem_ = make_problem();
    dofs_ = std::make_unique<SubdomainDofs>(sub, numbering_, problem_->pattern(),
                                            problem_->constrained());
  });
  platens_->bind(numbering_, *dofs_, problem_->constrained(), problem_->stiffness_scale(),
                 config.bcs, comm_);
  local_nnz_ = problem_->pattern().nnz();
  tail_ = platens_->tie_entries();
  if (rank_ == 0 && config.linear_solver.ordering == Ordering::Metis) {
    // Each platen's master node last, as one process orders it: its force row is dense over
    // the platen's neighbourhood, and eliminating it early would fill that neighbourhood.
    std::vector<Index> nodes = nested_dissection_node_order(mesh);
    std::vector<Index> masters;
    for (const RigidPlaten& p : platens_->platens().platens()) masters.push_back(p.master_node);
    std::erase_if(nodes, [&](Index n) {
      return std::find(masters.begin(), masters.end(), n) != masters.end();
    });
    nodes.insert(nodes.end(), masters.begin(), masters.end());
    fill_order_ = unknown_order(numbering_, nodes);
  }
  const auto n = static_cast<std::size_t>(problem_->size());
  y_.resize(n);
  ydot_.resize(n);
  F_.resize(n);

  std::vector<PetscInt> global(n);
  for (std::size_t i = 0; i < n; ++i) global[i] = petsc_index(dofs_->global(static_cast<Index>(i)));
  IS from = nullptr;
  petsc_check(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(n), global.data(),
                              PETSC_COPY_VALUES, &from),
              "ISCreateGeneral");
  petsc_check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(n), &local_), "VecCreateSeq");
  Vec layout = new_vector();
  petsc_check(VecScatterCreate(layout, from, local_, nullptr, &scatter_), "VecScatterCreate");
  VecDestroy(&layout);
  ISDestroy(&from);
}

DistributedAssembly::~DistributedAssembly() {
  if (scatter_) VecScatterDestroy(&scatter_);
  if (local_) VecDestroy(&local_);
}

Vec DistributedAssembly::new_vector() const {
  Vec v = nullptr;
  petsc_check(VecCreateMPI(comm_, petsc_index(owned_size()), petsc_index(global_size()), &v),
              "VecCreateMPI");
  return v;
}

Mat DistributedAssembly::new_matrix() const {
  Mat J = nullptr;
  const PetscInt m = petsc_index(owned_size()), N = petsc_index(global_size());
  petsc_check(MatCreate(comm_, &J), "MatCreate");
  petsc_check(MatSetSizes(J, m, m, N, N), "MatSetSizes");
  petsc_check(MatSetType(J, MATAIJ), "MatSetType");
  std::vector<PetscInt> rows, cols;  // PETSc may change them: made for this call
  coo_indices(rows, cols);
  petsc_check(
      MatSetPreallocationCOO(J, static_cast<PetscCount>(rows.size()), rows.data(), cols.data()),
      "MatSetPreallocationCOO");
  return J;
}

void DistributedAssembly::coo_indices(std::vector<PetscInt>& rows,
                                      std::vector<PetscInt>& cols) const {
  const SparsityPattern& pattern = problem_->pattern();
  const auto& colptr = pattern.colptr();
  const auto& rowind = pattern.rowind();
  rows.assign(static_cast<std::size_t>(coo_size()), -1);
  cols.assign(rows.size(), -1);
  for (Index j = 0; j < pattern.size(); ++j)
    for (Index k = colptr[static_cast<std::size_t>(j)]; k < colptr[static_cast<std::size_t>(j) + 1];
         ++k) {
      const Index i = rowind[static_cast<std::size_t>(k)];
      if (!dofs_->contributes(i, j)) continue;
      // A platen's tie row adds its entries to the force row (parallel/distributed_platens.hpp).
      const Index force = platens_->force_row(i);
      rows[static_cast<std::size_t>(k)] = petsc_index(force >= 0 ? force : dofs_->global(i));
      cols[static_cast<std::size_t>(k)] = petsc_index(dofs_->global(j));
    }
  for (std::size_t t = 0; t < tail_.size(); ++t) {
    rows[static_cast<std::size_t>(local_nnz_) + t] = petsc_index(tail_[t].row);
    cols[static_cast<std::size_t>(local_nnz_) + t] = petsc_index(tail_[t].col);
  }
}

void DistributedAssembly::to_local(Vec global, std::vector<double>& local) {
  petsc_check(VecScatterBegin(scatter_, global, local_, INSERT_VALUES, SCATTER_FORWARD),
              "VecScatterBegin");
  petsc_check(VecScatterEnd(scatter_, global, local_, INSERT_VALUES, SCATTER_FORWARD),
              "VecScatterEnd");
  const PetscScalar* a = nullptr;
  petsc_check(VecGetArrayRead(local_, &a), "VecGetArrayRead");
  local.assign(a, a + problem_->size());
  VecRestoreArrayRead(local_, &a);
}

void DistributedAssembly::add_from_local(Vec F) {
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(local_, &a), "VecGetArray");
  for (Index i = 0; i < problem_->size(); ++i)
    a[i] = dofs_->contributes(i) ? F_[static_cast<std::size_t>(i)] : 0.0;
  VecRestoreArray(local_, &a);
  petsc_check(VecSet(F, 0.0), "VecSet");
  petsc_check(VecScatterBegin(scatter_, local_, F, ADD_VALUES, SCATTER_REVERSE), "VecScatterBegin");
  petsc_check(VecScatterEnd(scatter_, local_, F, ADD_VALUES, SCATTER_REVERSE), "VecScatterEnd");
}

void DistributedAssembly::residual(double t, Vec y, Vec ydot, Vec F) {
  to_local(y, y_);
  to_local(ydot, ydot_);
  run_collectively(comm_, [&] { problem_->residual(t, y_.data(), ydot_.data(), F_.data()); });
  add_from_local(F);
  platens_->residual(t, y, F);
}

void DistributedAssembly::time_derivative(double t, Vec dFdt) {
  problem_->time_derivative(t, F_.data());
  add_from_local(dFdt);
  platens_->time_derivative(t, dFdt);
}

void DistributedAssembly::jacobian(double t, Vec y, Vec ydot, double cj, Mat J, Mat rate) {
  to_local(y, y_);
  to_local(ydot, ydot_);
  // The local values live only while they are handed to PETSc: PETSc's matrix holds them
  // from then on, and the factorisation that follows needs the memory. The tail (a platen's tie
  // entries) carries its constants s and −s, and 0 in dF/dẏ; the local problem writes the CSC
  // positions.
  std::vector<double> values(static_cast<std::size_t>(coo_size()), 0.0), rates;
  for (std::size_t k = 0; k < tail_.size(); ++k)
    values[static_cast<std::size_t>(local_nnz_) + k] = tail_[k].constant;
  if (rate) rates.assign(values.size(), 0.0);
  run_collectively(comm_, [&] {
    problem_->jacobian(t, y_.data(), ydot_.data(), cj, values.data(),
                       rate ? rates.data() : nullptr);
  });
  petsc_check(MatSetValuesCOO(J, values.data(), INSERT_VALUES), "MatSetValuesCOO");
  if (rate) petsc_check(MatSetValuesCOO(rate, rates.data(), INSERT_VALUES), "MatSetValuesCOO");
}

void DistributedAssembly::apply_dirichlet(double t, Vec y, Vec ydot) const {
  // The prescribed values of the local unknowns, written into the owned ones.
  std::vector<double> yl(static_cast<std::size_t>(problem_->size()), 0.0), ydl = yl;
  problem_->apply_dirichlet(t, yl.data(), ydl.data());
  const std::vector<char>& fixed = problem_->constrained();
  PetscScalar* a = nullptr;
  PetscScalar* b = nullptr;
  petsc_check(VecGetArray(y, &a), "VecGetArray");
  if (ydot) petsc_check(VecGetArray(ydot, &b), "VecGetArray");
  const auto& owned = dofs_->owned();
  for (std::size_t k = 0; k < owned.size(); ++k) {
    const auto i = static_cast<std::size_t>(owned[k]);
    if (!fixed[i]) continue;
    a[k] = yl[i];
    if (b) b[k] = ydl[i];
  }
  VecRestoreArray(y, &a);
  if (ydot) VecRestoreArray(ydot, &b);
  platens_->apply(y, ydot);
}

}  // namespace biphasic
