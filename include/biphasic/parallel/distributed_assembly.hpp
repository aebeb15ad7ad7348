// The biphasic system of a mesh split among MPI processes, assembled into PETSc vectors and
// matrices (docs/parallel.md).
//
// Every process holds the whole mesh (mesh 4: 6 MB, against 365 MB for its Jacobian), partitions it
// the same way (METIS on process 0, broadcast), and builds the problem of its own part
// (mesh/partition.hpp, physics/assembly_scope.hpp): a BiphasicProblem on tetrahedra, a
// SectionProblem on the triangles of a two-dimensional model. The unknowns are numbered rank-major:
// each process owns one contiguous range, displacements interlaced per node. A residual or Jacobian
// is assembled by each process on its own elements with the one-process element kernels; PETSc adds
// the parts' contributions (a reverse scatter for the residual, the COO interface for the matrix,
// whose pattern is set once). Rigid platens are then posed on the summed rows
// (parallel/distributed_platens.hpp).
#pragma once

#include <petscmat.h>
#include <petscvec.h>

#include <memory>
#include <vector>

#include "biphasic/assembly/subdomain_dofs.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/mesh/partition.hpp"
#include "biphasic/parallel/distributed_platens.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {

class DistributedAssembly {
 public:
  /// `mesh` is the whole mesh, the same on every process of `comm` (the object need not outlive
  /// the assembly). Collective. Throws std::runtime_error naming the process on a failure of
  /// its part (a bad boundary condition is reported by every process alike).
  DistributedAssembly(const Mesh& mesh, const Config& config, MPI_Comm comm);
  /// The same for the section of a two-dimensional model (config.model plane strain or
  /// axisymmetric).
  DistributedAssembly(const SectionMesh& mesh, const Config& config, MPI_Comm comm);
  ~DistributedAssembly();
  DistributedAssembly(const DistributedAssembly&) = delete;
  DistributedAssembly& operator=(const DistributedAssembly&) = delete;

  MPI_Comm comm() const { return comm_; }
  /// Unknowns of the whole system, and those this process owns (the range starting at
  /// first_owned()).
  Index global_size() const { return numbering_.size(); }
  Index owned_size() const { return static_cast<Index>(dofs_->owned().size()); }
  Index first_owned() const { return dofs_->first_owned(); }
  /// The rank-major numbering of the whole mesh's unknowns.
  const PartitionedNumbering& numbering() const { return numbering_; }
  /// This process's part of the mesh against the whole.
  const SubdomainMap& subdomain() const { return *map_; }
  /// This process's problem on its part of the mesh.
  BiphasicModel& local_problem() { return *problem_; }
  /// The same as a tetrahedral problem (null for a two-dimensional model).
  const BiphasicProblem* body() const { return body_; }
  /// The same as a section problem (null for a three-dimensional model).
  const SectionProblem* section() const { return section_; }
  const SubdomainDofs& dofs() const { return *dofs_; }
  /// The rigid platens of the whole mesh, posed on the summed system.
  const DistributedPlatens& platens() const { return *platens_; }
  /// The matrix entries this process hands PETSc's COO interface: every position of the local
  /// problem's CSC pattern, in its order (those that do not contribute with row and column −1,
  /// which PETSc ignores), then the platens' tie entries. The values of a matrix are therefore
  /// the local CSC value array itself, followed by tail() (no copy, no position map), and that
  /// array lives only while a Jacobian is assembled.
  Index coo_size() const { return local_nnz_ + static_cast<Index>(tail_.size()); }
  /// The fixed entries after the CSC positions (the owned tie rows' s and −s).
  const std::vector<FixedEntry>& tail() const { return tail_; }
  /// On process 0 with linear_solver.ordering = "metis": the unknowns in the nested-dissection
  /// order of the whole mesh (mesh/nested_dissection.hpp), for the direct solver; elsewhere
  /// empty.
  const std::vector<Index>& fill_order() const { return fill_order_; }

  /// A new vector with the owned layout (the caller destroys it).
  Vec new_vector() const;
  /// A new matrix holding the Jacobian's pattern (AIJ, preallocated; the caller destroys it).
  Mat new_matrix() const;

  /// F(t, y, ẏ) of the whole system into F. Collective.
  void residual(double t, Vec y, Vec ydot, Vec F);
  /// dF/dy + c_j dF/dẏ of the whole system into J (a matrix from new_matrix()), and dF/dẏ
  /// into `rate` unless null (another such matrix). Collective.
  void jacobian(double t, Vec y, Vec ydot, double cj, Mat J, Mat rate = nullptr);
  /// ∂F/∂t of the whole system into dFdt. Collective.
  void time_derivative(double t, Vec dFdt);
  /// Sets the constrained entries of y (and of ẏ unless null) to their prescribed values (a
  /// platen's tied entries to its master's). Collective.
  void apply_dirichlet(double t, Vec y, Vec ydot) const;

  /// The local unknowns' values of a global vector (ghosts included), in the local problem's
  /// layout. Collective.
  void to_local(Vec global, std::vector<double>& local);

 private:
  /// Adds the contributing rows of the local vector local_F_ into F (zeroed first). Collective.
  void add_from_local(Vec F);
  /// The COO row and column indices (coo_size() of each; made on each call, for PETSc's
  /// preallocation).
  void coo_indices(std::vector<PetscInt>& rows, std::vector<PetscInt>& cols) const;
  /// The constructors' common part: partition, number, extract part `sub`, make its problem
  /// (make_problem() also makes platens_), and set up the PETSc layout.
  template <class AnyMesh, class Part, class MakeProblem>
  void build(const AnyMesh& mesh, std::size_t num_elements, Part& sub, const Config& config,
             MakeProblem make_problem);

  MPI_Comm comm_;
  int rank_ = 0;
  PartitionedNumbering numbering_;
  Subdomain sub_;                 ///< the part of a tetrahedral mesh
  SectionSubdomain section_sub_;  ///< or of a section
  const SubdomainMap* map_ = nullptr;
  std::unique_ptr<DistributedPlatens> platens_;  ///< before problem_, which sees its platens
  std::unique_ptr<BiphasicModel> problem_;
  const BiphasicProblem* body_ = nullptr;
  const SectionProblem* section_ = nullptr;
  std::unique_ptr<SubdomainDofs> dofs_;
  Index local_nnz_ = 0;           ///< non-zeros of the local problem's pattern
  std::vector<FixedEntry> tail_;  ///< the platens' tie entries
  std::vector<Index> fill_order_;
  VecScatter scatter_ = nullptr;  ///< owned layout → local unknowns (ghosts included)
  Vec local_ = nullptr;           ///< sequential work vector in the local layout
  std::vector<double> y_, ydot_, F_;
};

}  // namespace biphasic
