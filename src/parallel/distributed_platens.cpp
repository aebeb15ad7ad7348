#include "biphasic/parallel/distributed_platens.hpp"

#include <stdexcept>
#include <unordered_map>

#include "biphasic/parallel/petsc_check.hpp"

namespace biphasic {

DistributedPlatens::DistributedPlatens(const Mesh& mesh, const Config& config)
    : curves_(config.curves), platens_(mesh, config, curves_) {}

DistributedPlatens::DistributedPlatens(const SectionMesh& mesh, bool axisymmetric,
                                       const Config& config)
    : curves_(config.curves), platens_(mesh, axisymmetric, config, curves_) {}

void DistributedPlatens::bind(const PartitionedNumbering& numbering, const SubdomainDofs& dofs,
                              const std::vector<char>& held, double row_scale,
                              const std::vector<BoundaryCondition>& bcs, MPI_Comm comm) {
  comm_ = comm;
  row_scale_ = row_scale;
  first_owned_ = dofs.first_owned();
  const auto owned_count = static_cast<Index>(dofs.owned().size());
  tied_.assign(static_cast<std::size_t>(owned_count), 0);
  master_of_local_.assign(static_cast<std::size_t>(dofs.size()), -1);
  parts_.assign(platens_.platens().size(), {});
  if (platens_.empty()) return;
  // Whole-system unknown of a one-process displacement unknown d·n + c.
  const Index d = numbering.components;
  auto whole = [&](Index dof) {
    return numbering.u_base[static_cast<std::size_t>(dof / d)] + dof % d;
  };
  auto owned_offset = [&](Index g) {
    const Index k = g - first_owned_;
    return k >= 0 && k < owned_count ? k : Index{-1};
  };
  // Which platen unknowns a Dirichlet condition holds, from their owners; then the one-process
  // check on the whole mesh, alike on every process.
  std::vector<int> held_here, held_any;
  for (const RigidPlaten& p : platens_.platens())
    for (Index dof : p.dofs) {
      const Index k = owned_offset(whole(dof));
      held_here.push_back(
          k >= 0 && held[static_cast<std::size_t>(dofs.owned()[static_cast<std::size_t>(k)])] ? 1
                                                                                              : 0);
    }
  held_any.resize(held_here.size());
  MPI_Allreduce(held_here.data(), held_any.data(), static_cast<int>(held_here.size()), MPI_INT,
                MPI_MAX, comm);
  std::vector<char> held_whole(static_cast<std::size_t>(d) * numbering.u_base.size(), 0);
  std::size_t at = 0;
  for (const RigidPlaten& p : platens_.platens())
    for (Index dof : p.dofs) held_whole[static_cast<std::size_t>(dof)] = held_any[at++] ? 1 : 0;
  try {
    platens_.check_free(held_whole, numbering.components, bcs);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // bad input: exit status 1, as in one process
  }

  std::unordered_map<Index, Index> master_of;  // whole-system tied unknown → its u_m
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const RigidPlaten& p = platens_.platens()[k];
    Part& part = parts_[k];
    part.master = whole(p.master);
    part.owned_master = owned_offset(part.master);
    for (Index dof : p.dofs) {
      const Index g = whole(dof);
      if (dof != p.master) master_of[g] = part.master;
      const Index o = owned_offset(g);
      if (o < 0) continue;
      part.owned.push_back(o);
      if (dof != p.master) {
        part.ties.push_back(o);
        tied_[static_cast<std::size_t>(o)] = 1;
      }
    }
  }
  for (Index i = 0; i < dofs.size(); ++i) {
    const auto it = master_of.find(dofs.global(i));
    if (it != master_of.end()) master_of_local_[static_cast<std::size_t>(i)] = it->second;
  }
}

std::vector<FixedEntry> DistributedPlatens::tie_entries() const {
  std::vector<FixedEntry> out;
  for (const Part& part : parts_)
    for (Index o : part.ties) {
      const Index i = first_owned_ + o;
      out.push_back({i, i, row_scale_});
      out.push_back({i, part.master, -row_scale_});
    }
  return out;
}

std::vector<double> DistributedPlatens::master_values(const std::vector<Vec>& vectors) const {
  const std::size_t n = parts_.size();
  std::vector<double> mine(n * vectors.size(), 0.0), all(mine.size());
  for (std::size_t v = 0; v < vectors.size(); ++v) {
    const PetscScalar* a = nullptr;
    petsc_check(VecGetArrayRead(vectors[v], &a), "VecGetArrayRead");
    for (std::size_t k = 0; k < n; ++k)
      if (parts_[k].owned_master >= 0) mine[v * n + k] = a[parts_[k].owned_master];
    VecRestoreArrayRead(vectors[v], &a);
  }
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM, comm_);
  return all;
}

void DistributedPlatens::residual(double t, Vec y, Vec F) const {
  if (platens_.empty()) return;
  const std::size_t n = parts_.size();
  // Per platen: the owned part of Σ F_i, and u_m from its owner.
  std::vector<double> mine(2 * n, 0.0), all(2 * n);
  PetscScalar* f = nullptr;
  const PetscScalar* a = nullptr;
  petsc_check(VecGetArray(F, &f), "VecGetArray");
  petsc_check(VecGetArrayRead(y, &a), "VecGetArrayRead");
  for (std::size_t k = 0; k < n; ++k) {
    for (Index o : parts_[k].owned) mine[k] += f[o];
    if (parts_[k].owned_master >= 0) mine[n + k] = a[parts_[k].owned_master];
  }
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM, comm_);
  for (std::size_t k = 0; k < n; ++k) {
    const Part& part = parts_[k];
    for (Index o : part.ties) f[o] = row_scale_ * (a[o] - all[n + k]);
    if (part.owned_master >= 0) f[part.owned_master] = all[k] - platens_.force(k, t);
  }
  VecRestoreArrayRead(y, &a);
  VecRestoreArray(F, &f);
}

void DistributedPlatens::time_derivative(double t, Vec dFdt) const {
  if (platens_.empty()) return;
  const std::size_t n = parts_.size();
  std::vector<double> mine(n, 0.0), all(n);
  PetscScalar* f = nullptr;
  petsc_check(VecGetArray(dFdt, &f), "VecGetArray");
  for (std::size_t k = 0; k < n; ++k)
    for (Index o : parts_[k].owned) mine[k] += f[o];
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(n), MPI_DOUBLE, MPI_SUM, comm_);
  for (std::size_t k = 0; k < n; ++k) {
    const Part& part = parts_[k];
    const RigidPlaten& p = platens_.platens()[k];
    for (Index o : part.ties) f[o] = 0.0;
    if (part.owned_master >= 0)
      f[part.owned_master] = all[k] - p.value * (p.curve ? p.curve->slope(t) : 0.0);
  }
  VecRestoreArray(dFdt, &f);
}

void DistributedPlatens::apply(Vec y, Vec ydot) const {
  if (platens_.empty()) return;
  std::vector<Vec> vectors{y};
  if (ydot) vectors.push_back(ydot);
  const std::vector<double> masters = master_values(vectors);
  const std::size_t n = parts_.size();
  for (std::size_t v = 0; v < vectors.size(); ++v) {
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(vectors[v], &a), "VecGetArray");
    for (std::size_t k = 0; k < n; ++k)
      for (Index o : parts_[k].ties) a[o] = masters[v * n + k];
    VecRestoreArray(vectors[v], &a);
  }
}

}  // namespace biphasic
