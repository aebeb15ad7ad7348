#include "biphasic/parallel/distributed_system.hpp"

#include <nvector/nvector_parallel.h>

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>

#include "../physics/boundary_data.hpp"
#include "biphasic/parallel/collective_failure.hpp"
#include "biphasic/parallel/distributed_mumps_solver.hpp"
#include "biphasic/parallel/petsc_check.hpp"
#include "biphasic/parallel/petsc_linear_solver.hpp"
#include "biphasic/parallel/petsc_shift_corrected_solver.hpp"

namespace biphasic {

namespace {

/// A PETSc vector shown a caller's array for one scope (VecPlaceArray / VecResetArray).
class Placed {
 public:
  Placed(Vec v, const double* a) : v_(v) {
    petsc_check(VecPlaceArray(v_, const_cast<double*>(a)), "VecPlaceArray");
  }
  ~Placed() { VecResetArray(v_); }
  Placed(const Placed&) = delete;
  Placed& operator=(const Placed&) = delete;
  operator Vec() const { return v_; }

 private:
  Vec v_;
};

/// The consistent start's matrices on several processes: each process builds its entries
/// from its own part's dF/dy and dF/dẏ (local CSC arrays), PETSc sums them through the COO
/// interface, and the parallel MUMPS factorises.
class DistributedEntrywiseMatrices final : public EntrywiseMatrices {
 public:
  DistributedEntrywiseMatrices(DistributedSystem& system, DistributedAssembly& assembly)
      : system_(system), assembly_(assembly) {
    BiphasicModel& local = assembly.local_problem();
    const SparsityPattern& pattern = local.pattern();
    a0_.resize(static_cast<std::size_t>(pattern.nnz()));
    r_.resize(a0_.size());
    // Local row and column of every pattern position.
    column_of_.resize(a0_.size());
    for (Index j = 0; j < pattern.size(); ++j)
      for (Index q = pattern.colptr()[static_cast<std::size_t>(j)];
           q < pattern.colptr()[static_cast<std::size_t>(j) + 1]; ++q)
        column_of_[static_cast<std::size_t>(q)] = j;
    values_.resize(static_cast<std::size_t>(assembly.coo_size()));
    if (SUNContext_Create(nullptr, &ctx_) != 0)
      throw std::runtime_error("SUNContext_Create failed");
    petsc_check(VecCreateMPIWithArray(assembly.comm(), 1, static_cast<PetscInt>(system.size()),
                                      static_cast<PetscInt>(assembly.global_size()), nullptr, &x_),
                "VecCreateMPIWithArray");
    petsc_check(VecCreateMPI(assembly.comm(), static_cast<PetscInt>(system.size()),
                             static_cast<PetscInt>(assembly.global_size()), &product_),
                "VecCreateMPI");
  }
  ~DistributedEntrywiseMatrices() override {
    ls_.reset();
    for (SUNMatrix& m : slots_)
      if (m) SUNMatDestroy(m);
    for (N_Vector v : {nx_, nb_})
      if (v) N_VDestroy(v);
    for (Vec* v : {&x_, &product_})
      if (*v) VecDestroy(v);
    SUNContext_Free(&ctx_);
  }

  void evaluate(double t, const double* y, const double* ydot) override {
    std::vector<double> yl, ydl;
    {
      Placed yv(x_, y);
      assembly_.to_local(yv, yl);
    }
    {
      Placed ydv(x_, ydot);
      assembly_.to_local(ydv, ydl);
    }
    run_collectively(assembly_.comm(), [&] {
      assembly_.local_problem().jacobian(t, yl.data(), ydl.data(), 0.0, a0_.data(), r_.data());
    });
  }
  double a0_diagonal(Index i) const override {
    const DistributedPlatens& platens = assembly_.platens();
    if (!platens.empty() && platens.tied()[static_cast<std::size_t>(i)]) return platens.row_scale();
    const Index l = assembly_.dofs().owned()[static_cast<std::size_t>(i)];
    return a0_[static_cast<std::size_t>(assembly_.local_problem().pattern().find(l, l))];
  }
  void build(int slot, const Rule& rule) override {
    SUNMatrix& m = slots_.at(static_cast<std::size_t>(slot));
    if (!m) m = system_.new_jacobian_matrix(ctx_);
    BiphasicModel& local = assembly_.local_problem();
    const Index nu = local.num_u();
    const std::vector<char>& fixed = local.constrained();
    const auto& rows = local.pattern().rowind();
    // The local CSC positions in order (those PETSc ignores get a value all the same), then
    // the platens' tie entries: s or −s in A0, nothing in R. A tie row's entry moved to the force
    // row keeps its own row's kind: a free momentum row.
    const std::size_t nnz = a0_.size();
    for (std::size_t q = 0; q < nnz; ++q) {
      const Index i = rows[q], j = column_of_[q];
      values_[q] = rule(i < nu, j < nu, fixed[static_cast<std::size_t>(i)] != 0, a0_[q], r_[q]);
    }
    const auto& tail = assembly_.tail();
    for (std::size_t k = 0; k < tail.size(); ++k)
      values_[nnz + k] = rule(true, true, true, tail[k].constant, 0.0);
    petsc_check(MatSetValuesCOO(petsc_matrix(m), values_.data(), INSERT_VALUES), "MatSetValuesCOO");
  }
  void residual(int slot, const double* b, const double* x, double* r) const override {
    Placed xv(x_, x);
    petsc_check(MatMult(petsc_matrix(slots_.at(static_cast<std::size_t>(slot))), xv, product_),
                "MatMult");
    const PetscScalar* p = nullptr;
    petsc_check(VecGetArrayRead(product_, &p), "VecGetArrayRead");
    for (Index i = 0; i < system_.size(); ++i) r[i] = b[i] - p[i];
    VecRestoreArrayRead(product_, &p);
  }
  void factorise(int slot, const LinearSolverConfig&, LinearSolverStats* stats) override {
    // Double-precision LU whatever the configured solver, as in one process.
    ls_ = make_distributed_mumps_solver(assembly_.comm(), FactorPrecision::Double,
                                        assembly_.fill_order(), ctx_, stats ? stats : &own_stats_);
    factorised_ = slots_.at(static_cast<std::size_t>(slot));
    nx_ = system_.new_vector(ctx_);
    nb_ = system_.new_vector(ctx_);
    const int flag = SUNLinSolSetup(ls_.get(), factorised_);
    if (flag != 0)
      throw std::runtime_error("the consistent start's regularised system could not be factorised");
  }
  void solve(const double* b, double* x) override {
    std::copy_n(b, system_.size(), N_VGetArrayPointer(nb_));
    if (SUNLinSolSolve(ls_.get(), factorised_, nx_, nb_, 0.0) != 0)
      throw std::runtime_error("the consistent start's regularised system could not be solved");
    std::copy_n(N_VGetArrayPointer(nx_), system_.size(), x);
  }

 private:
  DistributedSystem& system_;
  DistributedAssembly& assembly_;
  std::vector<double> a0_, r_;
  std::vector<Index> column_of_;
  std::vector<PetscScalar> values_;
  std::array<SUNMatrix, 3> slots_{};
  SUNMatrix factorised_ = nullptr;
  SUNContext ctx_ = nullptr;
  LinearSolverPtr ls_;
  LinearSolverStats own_stats_;
  N_Vector nx_ = nullptr, nb_ = nullptr;
  Vec x_ = nullptr;        ///< storage-less, over a caller's owned array
  Vec product_ = nullptr;  ///< M x
};

}  // namespace

std::unique_ptr<EntrywiseMatrices> DistributedSystem::entrywise_matrices() {
  return std::make_unique<DistributedEntrywiseMatrices>(*this, assembly_);
}

DistributedSystem::DistributedSystem(DistributedAssembly& assembly) : assembly_(assembly) {
  int rank = 0;
  MPI_Comm_rank(assembly.comm(), &rank);
  num_u_ = assembly.numbering().components *
           assembly.numbering().owned_nodes[static_cast<std::size_t>(rank)];
  const std::vector<char>& local = assembly.local_problem().constrained();
  for (Index i : assembly.dofs().owned())
    constrained_.push_back(local[static_cast<std::size_t>(i)]);
  // The unknowns tied to a rigid platen's master are constrained as in one process.
  const DistributedPlatens& platens = assembly.platens();
  if (!platens.empty())
    for (std::size_t k = 0; k < constrained_.size(); ++k)
      if (platens.tied()[k]) constrained_[k] = 1;
  for (Vec* v : {&y_, &ydot_, &F_})
    petsc_check(VecCreateMPIWithArray(assembly.comm(), 1, static_cast<PetscInt>(size()),
                                      static_cast<PetscInt>(assembly.global_size()), nullptr, v),
                "VecCreateMPIWithArray");
}

DistributedSystem::~DistributedSystem() {
  for (Vec* v : {&y_, &ydot_, &F_})
    if (*v) VecDestroy(v);
  if (rate_) MatDestroy(&rate_);
}

const SparsityPattern& DistributedSystem::pattern() const {
  throw std::logic_error("a distributed system has no one-process sparsity pattern");
}

void DistributedSystem::residual(double t, const double* y, const double* ydot, double* F) {
  Placed yv(y_, y), ydv(ydot_, ydot), Fv(F_, F);
  assembly_.residual(t, yv, ydv, Fv);
}

void DistributedSystem::jacobian(double, const double*, const double*, double, double*, double*) {
  throw std::logic_error("a distributed system assembles its Jacobian with jacobian_into()");
}

void DistributedSystem::jacobian_into(double t, const double* y, const double* ydot, double cj,
                                      SUNMatrix J, double* rate_values) {
  if (rate_values) throw std::logic_error("a distributed system keeps dF/dydot as its own matrix");
  Placed yv(y_, y), ydv(ydot_, ydot);
  assembly_.jacobian(t, yv, ydv, cj, petsc_matrix(J), rate_);
}

LinearSolverPtr DistributedSystem::new_shift_corrected_solver(LinearSolverPtr inner,
                                                              ShiftedMatrixFamily* family,
                                                              SUNContext ctx,
                                                              LinearSolverStats* stats, double rtol,
                                                              int max_iterations) {
  if (!rate_) rate_ = assembly_.new_matrix();
  family->rate_values.clear();
  return make_petsc_shift_corrected_solver(assembly_.comm(), std::move(inner), family, rate_, ctx,
                                           stats, rtol, max_iterations);
}

void DistributedSystem::time_derivative(double t, double* dFdt) const {
  Placed Fv(F_, dFdt);
  assembly_.time_derivative(t, Fv);
}

void DistributedSystem::apply_dirichlet(double t, double* y, double* ydot) const {
  Placed yv(y_, y);
  if (!ydot) {
    assembly_.apply_dirichlet(t, yv, nullptr);
    return;
  }
  Placed ydv(ydot_, ydot);
  assembly_.apply_dirichlet(t, yv, ydv);
}

std::vector<double> DistributedSystem::breakpoints() const {
  return assembly_.local_problem().breakpoints();
}

void DistributedSystem::set_conservative_volume_rate(double dt) {
  assembly_.local_problem().set_conservative_volume_rate(dt);
}

AssemblyStats& DistributedSystem::stats() { return assembly_.local_problem().stats(); }

N_Vector DistributedSystem::new_vector(SUNContext ctx) const {
  return N_VNew_Parallel(assembly_.comm(), size(), assembly_.global_size(), ctx);
}

SUNMatrix DistributedSystem::new_jacobian_matrix(SUNContext ctx) const {
  return wrap_petsc_matrix(assembly_.new_matrix(), ctx);
}

LinearSolverPtr DistributedSystem::new_linear_solver(const LinearSolverConfig& config,
                                                     SUNContext ctx, LinearSolverStats* stats,
                                                     const SaddlePointStructure* saddle) const {
  if (config.type == LinearSolverType::Mumps)
    return make_distributed_mumps_solver(assembly_.comm(), config.precision, assembly_.fill_order(),
                                         ctx, stats, config.factor_folder());
  if (config.type == LinearSolverType::Iterative) {
    FieldSplitLayout layout;
    layout.owned = size();
    layout.owned_u = num_u_;
    layout.first_owned = assembly_.first_owned();
    const Index d = assembly_.numbering().components;
    layout.components = static_cast<int>(d);
    const auto& owned = assembly_.dofs().owned();
    // Each owned node's coordinates, from its first displacement unknown d·m.
    auto add_coordinates = [&](const auto& nodes) {
      for (Index k = 0; k < num_u_; k += d) {
        const auto& x = nodes[static_cast<std::size_t>(owned[static_cast<std::size_t>(k)] / d)];
        layout.coordinates.insert(layout.coordinates.end(), x.begin(), x.end());
      }
    };
    if (const SectionProblem* section = assembly_.section()) {
      add_coordinates(section->mesh().nodes);
      layout.rigid_body_modes = section->model() == SectionModel::PlaneStrain;
    } else {
      add_coordinates(assembly_.body()->mesh().nodes);
    }
    if (saddle) layout.schur_term = saddle->schur_term;
    return make_petsc_fieldsplit_solver(assembly_.comm(), config.krylov, std::move(layout), ctx,
                                        stats);
  }
  if (config.type == LinearSolverType::SuperluDist)
    return make_superlu_dist_solver(assembly_.comm(), ctx, stats);
  throw std::invalid_argument(kOneProcessSolvers);
}

double DistributedSystem::max_norm(const double* v) const {
  double mine = SemidiscreteSystem::max_norm(v), largest = 0.0;
  MPI_Allreduce(&mine, &largest, 1, MPI_DOUBLE, MPI_MAX, assembly_.comm());
  return largest;
}

std::pair<double, double> DistributedSystem::field_norms(const double* F) const {
  const auto [ru, rp] = detail::free_row_norms(F, constrained_, num_u_);
  double local[2] = {ru, rp};
  double global[2] = {0.0, 0.0};
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, assembly_.comm());
  return {global[0], global[1]};
}

std::pair<double, double> DistributedSystem::solution_scales() const {
  return assembly_.local_problem().solution_scales();
}
double DistributedSystem::stiffness_scale() const {
  return assembly_.local_problem().stiffness_scale();
}
double DistributedSystem::conductance_scale() const {
  return assembly_.local_problem().conductance_scale();
}
bool DistributedSystem::has_gls() const { return assembly_.local_problem().has_gls(); }
bool DistributedSystem::has_flux_perturbation() const {
  return assembly_.local_problem().has_flux_perturbation();
}

double DistributedSystem::gls_time_scale() const {
  // The smallest positive value over the processes (0: no process has the term).
  const double mine = assembly_.local_problem().gls_time_scale();
  double smallest = 0.0;
  const double candidate = mine > 0.0 ? mine : 1e300;
  MPI_Allreduce(&candidate, &smallest, 1, MPI_DOUBLE, MPI_MIN, assembly_.comm());
  return smallest == 1e300 ? 0.0 : smallest;
}

SaddlePointStructure DistributedSystem::saddle_point_structure(
    std::function<std::pair<double, double>()> shifts) const {
  // The owned range's layout, and the Schur coupling term of this process's elements indexed
  // in the pressure block (owned pressures of process 0, then 1, ...), Dirichlet pressures out.
  const PartitionedNumbering& num = assembly_.numbering();
  const auto parts = num.owned_vertices.size();
  std::vector<Index> block_start(parts + 1, 0);
  for (std::size_t r = 0; r < parts; ++r)
    block_start[r + 1] = block_start[r] + num.owned_vertices[r];
  BiphasicModel& local = assembly_.local_problem();
  const Index local_nu = local.num_u();
  const Index vertices = local.size() - local_nu;
  auto block = std::make_shared<std::vector<Index>>(static_cast<std::size_t>(vertices), -1);
  for (Index v = 0; v < vertices; ++v) {
    const Index i = local_nu + v;
    if (local.constrained()[static_cast<std::size_t>(i)]) continue;
    const Index g = assembly_.dofs().global(i);
    const auto r = static_cast<std::size_t>(
        std::upper_bound(num.offset.begin(), num.offset.end(), g) - num.offset.begin() - 1);
    (*block)[static_cast<std::size_t>(v)] =
        g - num.offset[r] - num.components * num.owned_nodes[r] + block_start[r];
  }
  SaddlePointStructure s;
  s.num_u = num_u_;
  s.components = num.components;
  s.constrained = constrained_;
  // The local problem's own term, by its local vertex numbers.
  s.schur_term = [local_term = local.saddle_point_structure(std::move(shifts)).schur_term,
                  block](std::vector<PressureEntry>& out) {
    std::vector<PressureEntry> mine;
    local_term(mine);
    for (const PressureEntry& e : mine) {
      const Index r = (*block)[static_cast<std::size_t>(e.row)];
      const Index c = (*block)[static_cast<std::size_t>(e.col)];
      if (r >= 0 && c >= 0) out.push_back({r, c, e.value});
    }
  };
  return s;
}

}  // namespace biphasic
