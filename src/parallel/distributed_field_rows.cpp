#include "biphasic/parallel/distributed_field_rows.hpp"

#include <hdf5.h>

#include <numeric>
#include <stdexcept>
#include <string>

#include "biphasic/parallel/petsc_check.hpp"

namespace biphasic {

RowRange block_rows(Index total, int rank, int size) {
  const Index first = total * rank / size;
  const Index end = total * (rank + 1) / size;
  return {first, end - first};
}

namespace {

/// A global index list as PETSc's (the assembly has checked that the unknowns fit its 32 bits).
IS index_set(MPI_Comm comm, const std::vector<PetscInt>& indices, int block = 1) {
  IS is = nullptr;
  petsc_check(block == 1 ? ISCreateGeneral(comm, static_cast<PetscInt>(indices.size()),
                                           indices.data(), PETSC_COPY_VALUES, &is)
                         : ISCreateBlock(comm, block, static_cast<PetscInt>(indices.size()),
                                         indices.data(), PETSC_COPY_VALUES, &is),
              "ISCreate");
  return is;
}

}  // namespace

DistributedFieldRows::DistributedFieldRows(MPI_Comm comm, const PartitionedNumbering& numbering,
                                           Index num_vertices,
                                           const std::vector<std::array<Index, 2>>& edges,
                                           Index num_cells, const std::vector<Index>& owned_cells)
    : comm_(comm), d_(numbering.components), num_cells_(num_cells), owned_cells_(owned_cells) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto num_nodes = static_cast<Index>(numbering.u_base.size());
  if (static_cast<Index>(edges.size()) != num_nodes - num_vertices)
    throw std::logic_error("DistributedFieldRows: " + std::to_string(edges.size()) +
                           " edge nodes for " + std::to_string(num_nodes - num_vertices));
  const Index owned_unknowns = numbering.offset[static_cast<std::size_t>(rank) + 1] -
                               numbering.offset[static_cast<std::size_t>(rank)];
  share_.writes_index = rank == 0;
  share_.nodes = block_rows(num_nodes, rank, size);
  share_.vertices = block_rows(num_vertices, rank, size);
  share_.cells = block_rows(num_cells, rank, size);

  // The node scatter's sources, in the order of its local target: the displacements of the node
  // rows, the one or two vertex pressures of each node row, the pressures of the vertex rows.
  std::vector<PetscInt> from;
  const RowRange& nodes = share_.nodes;
  for (Index n = nodes.first; n < nodes.first + nodes.count; ++n)
    for (int c = 0; c < d_; ++c)
      from.push_back(static_cast<PetscInt>(numbering.u_base[static_cast<std::size_t>(n)] + c));
  for (Index n = nodes.first; n < nodes.first + nodes.count; ++n) {
    if (n < num_vertices) {
      node_sources_.push_back(1);
      from.push_back(static_cast<PetscInt>(numbering.p_index[static_cast<std::size_t>(n)]));
    } else {
      node_sources_.push_back(2);
      for (Index v : edges[static_cast<std::size_t>(n - num_vertices)])
        from.push_back(static_cast<PetscInt>(numbering.p_index[static_cast<std::size_t>(v)]));
    }
  }
  const RowRange& vertices = share_.vertices;
  for (Index v = vertices.first; v < vertices.first + vertices.count; ++v)
    from.push_back(static_cast<PetscInt>(numbering.p_index[static_cast<std::size_t>(v)]));
  petsc_check(VecCreateMPIWithArray(comm, 1, static_cast<PetscInt>(owned_unknowns),
                                    static_cast<PetscInt>(numbering.size()), nullptr, &nodes_.from),
              "VecCreateMPIWithArray");
  petsc_check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(from.size()), &nodes_.to),
              "VecCreateSeq");
  IS is = index_set(PETSC_COMM_SELF, from);
  petsc_check(VecScatterCreate(nodes_.from, is, nodes_.to, nullptr, &nodes_.scatter),
              "VecScatterCreate");
  ISDestroy(&is);

  // MPI-IO for the file, collective transfers.
  share_.file_access = H5Pcreate(H5P_FILE_ACCESS);
  share_.transfer = H5Pcreate(H5P_DATASET_XFER);
  if (share_.file_access < 0 || share_.transfer < 0 ||
      H5Pset_fapl_mpio(share_.file_access, comm, MPI_INFO_NULL) < 0 ||
      H5Pset_dxpl_mpio(share_.transfer, H5FD_MPIO_COLLECTIVE) < 0) {
    if (share_.file_access >= 0) H5Pclose(share_.file_access);
    if (share_.transfer >= 0) H5Pclose(share_.transfer);
    destroy(nodes_);
    throw std::runtime_error("HDF5: cannot set up MPI-IO for the field file");
  }
}

DistributedFieldRows::~DistributedFieldRows() {
  H5Pclose(share_.file_access);
  H5Pclose(share_.transfer);
  destroy(nodes_);
  for (auto& [width, s] : cells_) destroy(s);
}

void DistributedFieldRows::destroy(Scatter& s) {
  if (s.scatter) VecScatterDestroy(&s.scatter);
  if (s.from) VecDestroy(&s.from);
  if (s.to) VecDestroy(&s.to);
}

void DistributedFieldRows::apply(const Scatter& s, const double* from) {
  petsc_check(VecPlaceArray(s.from, from), "VecPlaceArray");
  petsc_check(VecScatterBegin(s.scatter, s.from, s.to, INSERT_VALUES, SCATTER_FORWARD),
              "VecScatterBegin");
  petsc_check(VecScatterEnd(s.scatter, s.from, s.to, INSERT_VALUES, SCATTER_FORWARD),
              "VecScatterEnd");
  VecResetArray(s.from);
}

void DistributedFieldRows::node_rows(const double* owned, std::vector<double>& u,
                                     std::vector<double>& p_nodes,
                                     std::vector<double>& p_vertices) const {
  apply(nodes_, owned);
  const PetscScalar* values = nullptr;
  petsc_check(VecGetArrayRead(nodes_.to, &values), "VecGetArrayRead");
  const auto rows = static_cast<std::size_t>(share_.nodes.count);
  const PetscScalar* at = values;
  u.assign(at, at + static_cast<std::size_t>(d_) * rows);
  at += static_cast<std::size_t>(d_) * rows;
  p_nodes.resize(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    p_nodes[k] = node_sources_[k] == 1 ? at[0] : 0.5 * (at[0] + at[1]);
    at += node_sources_[k];
  }
  p_vertices.assign(at, at + share_.vertices.count);
  VecRestoreArrayRead(nodes_.to, &values);
}

const DistributedFieldRows::Scatter& DistributedFieldRows::cell_scatter(int width) const {
  auto found = cells_.find(width);
  if (found != cells_.end()) return found->second;
  Scatter s;
  const auto owned = static_cast<PetscInt>(owned_cells_.size());
  petsc_check(VecCreateMPIWithArray(comm_, width, width * owned,
                                    static_cast<PetscInt>(width * num_cells_), nullptr, &s.from),
              "VecCreateMPIWithArray");
  petsc_check(VecCreateMPI(comm_, static_cast<PetscInt>(width * share_.cells.count),
                           static_cast<PetscInt>(width * num_cells_), &s.to),
              "VecCreateMPI");
  // Each own cell goes from its rank-major place (after those of the lower ranks) to its place
  // in the whole mesh's order.
  PetscInt first = 0;
  petsc_check(VecGetOwnershipRange(s.from, &first, nullptr), "VecGetOwnershipRange");
  std::vector<PetscInt> from(owned_cells_.size()), to(owned_cells_.size());
  std::iota(from.begin(), from.end(), first / width);
  for (std::size_t k = 0; k < owned_cells_.size(); ++k)
    to[k] = static_cast<PetscInt>(owned_cells_[k]);
  IS is_from = index_set(comm_, from, width), is_to = index_set(comm_, to, width);
  petsc_check(VecScatterCreate(s.from, is_from, s.to, is_to, &s.scatter), "VecScatterCreate");
  ISDestroy(&is_from);
  ISDestroy(&is_to);
  return cells_.emplace(width, s).first->second;
}

std::vector<double> DistributedFieldRows::cell_rows(const std::vector<double>& owned_values,
                                                    int width) const {
  if (owned_values.size() != owned_cells_.size() * static_cast<std::size_t>(width))
    throw std::logic_error("DistributedFieldRows: " + std::to_string(owned_values.size()) +
                           " cell values for " + std::to_string(owned_cells_.size()) +
                           " own cells of width " + std::to_string(width));
  const Scatter& s = cell_scatter(width);
  apply(s, owned_values.data());
  const PetscScalar* values = nullptr;
  petsc_check(VecGetArrayRead(s.to, &values), "VecGetArrayRead");
  std::vector<double> rows(values, values + width * share_.cells.count);
  VecRestoreArrayRead(s.to, &values);
  return rows;
}

}  // namespace biphasic
