// One fields.h5 written by all processes (parallel HDF5): each process writes a contiguous block
// of the node, vertex and cell rows, whatever it owns, and PETSc scatters bring the values of the
// distributed state to the process whose block holds them. No process holds a whole field.
#pragma once

#include <mpi.h>
#include <petscvec.h>

#include <array>
#include <map>
#include <vector>

#include "biphasic/io/field_writer.hpp"
#include "biphasic/mesh/partition.hpp"

namespace biphasic {

/// Rows [first, first + count) of `total` rows that process `rank` of `size` writes: the rows
/// split into contiguous blocks in process order, of sizes that differ by one at most.
RowRange block_rows(Index total, int rank, int size);

/// This process's rows of a field file and the scatters that fill them. Collective: every
/// process of `comm` constructs it and calls its members in the same order.
class DistributedFieldRows {
 public:
  /// `numbering`: the rank-major unknowns (d displacements per node, one pressure per vertex);
  /// `edges`: the two vertices of each edge node (edge_node_vertices); `owned_cells`: the whole
  /// mesh's numbers of this process's own cells, in the order cell_rows() takes their values.
  /// Throws std::runtime_error if HDF5 cannot set up MPI-IO.
  DistributedFieldRows(MPI_Comm comm, const PartitionedNumbering& numbering, Index num_vertices,
                       const std::vector<std::array<Index, 2>>& edges, Index num_cells,
                       const std::vector<Index>& owned_cells);
  ~DistributedFieldRows();
  DistributedFieldRows(const DistributedFieldRows&) = delete;
  DistributedFieldRows& operator=(const DistributedFieldRows&) = delete;

  /// The share this process's FieldWriter takes: its rows, MPI-IO file access, collective
  /// transfers, and process 0 writing the index.
  const FieldFileShare& share() const { return share_; }

  /// From this process's owned unknowns (rank-major, `owned` of the numbering's local size): the
  /// displacement of its nodes (d per node), the pressure at its nodes (the mean of the edge's
  /// vertices at an edge node) and at its vertices [MPa].
  void node_rows(const double* owned, std::vector<double>& u, std::vector<double>& p_nodes,
                 std::vector<double>& p_vertices) const;

  /// From `width` values per own cell (in owned_cells' order), those of this process's cells.
  std::vector<double> cell_rows(const std::vector<double>& owned_values, int width) const;

 private:
  /// A scatter from an MPI vector into a local or MPI vector, with both ends held.
  struct Scatter {
    Vec from = nullptr;
    Vec to = nullptr;
    VecScatter scatter = nullptr;
  };
  static void destroy(Scatter& s);
  /// Scatters the values at `from` (the source's local part) into s.to (collective).
  static void apply(const Scatter& s, const double* from);
  /// The scatter of cell values with `width` values per cell (made on first use).
  const Scatter& cell_scatter(int width) const;

  MPI_Comm comm_;
  FieldFileShare share_;
  int d_ = 3;
  Index num_cells_ = 0;
  std::vector<Index> owned_cells_;
  std::vector<int> node_sources_;  ///< per node row: 1 (a vertex) or 2 (an edge node) pressures
  Scatter nodes_;                  ///< into [u rows, pressures for the node rows, vertex rows]
  mutable std::map<int, Scatter> cells_;
};

}  // namespace biphasic
