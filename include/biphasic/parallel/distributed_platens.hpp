// Rigid platens on a mesh split among MPI processes (docs/rigid_platen.md, docs/parallel.md).
//
// The platens are found on the whole mesh, which every process holds (RigidPlatens): each has
// the master unknown u_m, the unknowns and the area of the one-process run. A part assembles the
// platen rows as ordinary momentum rows (AssemblyScope::platens), PETSc sums the parts, and this
// class then poses the platen rows on the owned rows of the summed system as one process does:
//
//   tie rows      F_i = s · (u_i − u_m)                   every platen unknown i ≠ m
//   force row     F_m = Σ_{i ∈ platen} F_i − P(t)         [N]
//
// with s the Dirichlet row scale [N/mm] and P(t) = value · curve(t) [N]. Each process sums its
// owned F_i; one MPI_Allreduce gives every process the sums and u_m. In the matrices
// (dF/dy + c_j dF/dẏ and dF/dẏ), every entry (i, j) a part contributes to a tie row i is
// contributed as (m, j) instead, where PETSc's COO assembly adds it to the other parts'
// entries of the force row; the owner of row i adds (i, i) = s and (i, m) = −s (0 in dF/dẏ: a
// tie row has no rate).
#pragma once

#include <mpi.h>
#include <petscvec.h>

#include <map>
#include <string>
#include <vector>

#include "biphasic/assembly/subdomain_dofs.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/mesh/partition.hpp"
#include "biphasic/physics/rigid_platen.hpp"

namespace biphasic {

/// A matrix entry of fixed value that a process adds to the summed matrix: whole-system row and
/// column, its value in dF/dy + c_j dF/dẏ (0 in dF/dẏ).
struct FixedEntry {
  Index row, col;
  double constant;
};

class DistributedPlatens {
 public:
  /// The rigid_platen conditions of `config` on the whole mesh `mesh` (the same on every
  /// process); throws as RigidPlatens does. Not yet bound: bind() before use.
  DistributedPlatens(const Mesh& mesh, const Config& config);
  /// The same on the whole section of a two-dimensional model.
  DistributedPlatens(const SectionMesh& mesh, bool axisymmetric, const Config& config);
  DistributedPlatens(const DistributedPlatens&) = delete;
  DistributedPlatens& operator=(const DistributedPlatens&) = delete;

  bool empty() const { return platens_.empty(); }
  /// The platens of the whole mesh, unknowns in the one-process layout (u of node n at d·n + c,
  /// d = 3 or 2 components).
  const RigidPlatens& platens() const { return platens_; }

  /// Binds the platens to this process's part: `dofs` and `held` (the Dirichlet flags of the
  /// part's problem) of the part, `row_scale` = s [N/mm]. Collective. Throws
  /// std::invalid_argument, alike on every process and worded as in one process, if a
  /// Dirichlet condition holds a platen unknown.
  void bind(const PartitionedNumbering& numbering, const SubdomainDofs& dofs,
            const std::vector<char>& held, double row_scale,
            const std::vector<BoundaryCondition>& bcs, MPI_Comm comm);

  /// Per owned unknown: tied to its platen's master (a constrained, algebraic row).
  const std::vector<char>& tied() const { return tied_; }
  /// s [N/mm].
  double row_scale() const { return row_scale_; }
  /// The row a local row's entries go to in the summed matrix: a tied row's go to its platen's
  /// force row (the master's unknown in the whole system); −1 for any other row (its own).
  Index force_row(Index local_row) const {
    return platens_.empty() ? -1 : master_of_local_[static_cast<std::size_t>(local_row)];
  }
  /// The entries the owned tie rows add: (i, i) = s and (i, m) = −s, rows and columns in the
  /// whole system.
  std::vector<FixedEntry> tie_entries() const;

  /// The platen rows of the summed residual F [N] (owned layout; F_i on every row before).
  /// Collective.
  void residual(double t, Vec y, Vec F) const;
  /// ∂F/∂t on the platen rows from the summed ∂F_i/∂t: the force row −dP/dt plus the sum,
  /// tie rows 0. Collective.
  void time_derivative(double t, Vec dFdt) const;
  /// Sets the tied owned entries of y (and ẏ unless null) to their master's value. Collective.
  void apply(Vec y, Vec ydot) const;

 private:
  /// Per platen, its master's value in each vector (every process gets them).
  std::vector<double> master_values(const std::vector<Vec>& vectors) const;
  struct Part {
    Index master = 0;          ///< whole-system unknown of u_m
    Index owned_master = -1;   ///< its owned offset here, or −1
    std::vector<Index> owned;  ///< owned offsets of the platen's unknowns (master included)
    std::vector<Index> ties;   ///< owned offsets of its tie rows
  };
  std::map<std::string, LoadCurve> curves_;  ///< platens_ points into it
  RigidPlatens platens_;
  std::vector<Part> parts_;
  std::vector<Index> master_of_local_;  ///< per local unknown: its platen's u_m if tied, else −1
  std::vector<char> tied_;
  Index first_owned_ = 0;
  double row_scale_ = 1.0;
  MPI_Comm comm_ = MPI_COMM_NULL;
};

}  // namespace biphasic
