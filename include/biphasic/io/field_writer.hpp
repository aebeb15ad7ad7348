// Time-series output of the nodal fields to HDF5 with an XDMF index for ParaView/VisIt.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// For every edge node of `mesh` (mesh index num_vertices + k, stored at position k) the two
/// vertices of the edge it sits on, smaller index first. Built from the tetrahedra; throws
/// std::runtime_error if a tetrahedron has a corner or edge slot outside its node range, if an
/// edge node is shared by two different edges, or if an edge node belongs to no tetrahedron.
std::vector<std::array<Index, 2>> edge_node_vertices(const Mesh& mesh);

/// The same for a section mesh, built from its triangles (same checks, "triangle" in the
/// messages).
std::vector<std::array<Index, 2>> edge_node_vertices(const SectionMesh& mesh);

/// A section displacement (2 entries per node, u[2n+c] [mm]) as a three-dimensional one (3 per
/// node, the third 0): what the field files and the probes' displacement() take.
std::vector<double> displacement_in_3d(const std::vector<double>& u2);

/// The P1 pressure [MPa] given on the vertices evaluated at every P2 node: vertices keep their
/// value, an edge node gets the mean of its edge's two vertices. `edges` comes from
/// edge_node_vertices(); `p_vertices` must have one entry per vertex.
std::vector<double> pressure_at_nodes(const std::vector<std::array<Index, 2>>& edges,
                                      const std::vector<double>& p_vertices);

/// A field with one value, vector or tensor per cell (tetrahedron or triangle; XDMF
/// Center="Cell").
struct CellFieldSpec {
  std::string name;  ///< HDF5 group /fields/<name> and XDMF attribute name
  /// 1 Scalar, 3 Vector (x, y, z), 6 Tensor6 (xx, xy, xz, yy, yz, zz), 9 Tensor (row by row:
  /// xx, xy, xz, yx, yy, yz, zx, zy, zz)
  int components = 1;
  std::string units;  ///< the datasets' `units` attribute ("-" if dimensionless)
};

/// What a FieldWriter writes at every output: the nodal displacement and pressure (each
/// optional) and any cell fields, in this order.
struct FieldLayout {
  bool displacement = true;
  bool pressure = true;  ///< /fields/pressure and /fields/pressure_vertices
  std::vector<CellFieldSpec> cells;
};

/// Rows [first, first + count) of a dataset.
struct RowRange {
  Index first = 0;
  Index count = 0;
};

/// One process's part in a field file that several processes write together through parallel
/// HDF5: the rows of the node, vertex and cell datasets it writes, and the HDF5 property lists
/// (hid_t) that make the file's opening and the writes collective (H5Pset_fapl_mpio,
/// H5Pset_dxpl_mpio). The process with `writes_index` set (exactly one) writes the XDMF index,
/// the scalar datasets and the output times. Every process constructs its writer with its own
/// share and calls write_rows() at the same outputs; the ranges of all processes together
/// cover every row once.
struct FieldFileShare {
  std::int64_t file_access = 0;  ///< H5P_FILE_ACCESS list (0 is H5P_DEFAULT)
  std::int64_t transfer = 0;     ///< H5P_DATASET_XFER list (0 is H5P_DEFAULT)
  bool writes_index = true;
  RowRange nodes;
  RowRange vertices;
  RowRange cells;
};

/// Writes the fields of a run to `<directory>/<stem>.h5` and keeps `<directory>/<stem>.xdmf`
/// (XDMF 3 temporal collection, Tetrahedron_10 cells of a Mesh, Triangle_6 cells of a
/// SectionMesh) up to date.
///
/// HDF5 layout:
///   /mesh/coordinates               N×3 double [mm] (a section's nodes at z = 0)
///   /mesh/topology                  E×10 int64 (Tetrahedron_10 node order), or E×6 for a
///                                   section (Triangle_6: corners, then edges 01, 12, 20)
///   /mesh/vertex_count              scalar int64 (the first vertex_count nodes are corners)
///   /fields/times                   extensible 1-D double [s], one entry per output
///   /fields/displacement/<i>        N×3 double [mm] (section: third 0) (layout.displacement)
///   /fields/pressure/<i>            N double [MPa], P1 pressure evaluated on all P2 nodes
///   /fields/pressure_vertices/<i>   num_vertices double [MPa]          (both: layout.pressure)
///   /fields/<cell field>/<i>        E×components double (E double for a scalar)
/// Every field dataset carries a `time` attribute [s] and a `units` attribute.
///
/// After each write() the HDF5 file is flushed and the XDMF file is replaced atomically (written
/// to a temporary and renamed), so a run killed between outputs leaves a readable pair. Paths
/// inside the XDMF file are relative to its folder. Any existing files of the same name are
/// replaced.
class FieldWriter {
 public:
  /// Creates `directory` if needed and writes the mesh. Throws std::runtime_error on failure,
  /// and std::invalid_argument for a cell field named like another field (or "times"), with a
  /// name that is empty or holds '/', or with other than 1, 3 or 6 components.
  FieldWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
              FieldLayout layout = {});
  /// Continues the files an earlier run of the same mesh left in `directory` (a restart):
  /// outputs at times after `keep_until` [s] are deleted, later writes append. Throws
  /// std::runtime_error if the file is missing, unreadable or of another mesh.
  FieldWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
              double keep_until, FieldLayout layout = {});
  /// New files for a two-dimensional model's section mesh (Triangle_6 cells, z = 0); as the
  /// constructor from a Mesh otherwise.
  FieldWriter(const std::string& directory, const std::string& stem, const SectionMesh& mesh,
              FieldLayout layout = {});
  /// Continues the files of an earlier run on the same section mesh (as the Mesh variant; a
  /// file of another mesh, a tetrahedral one included, is refused).
  FieldWriter(const std::string& directory, const std::string& stem, const SectionMesh& mesh,
              double keep_until, FieldLayout layout = {});
  /// One process's writer of a file that several write together (`share`); new files, or with
  /// `keep_until` the continued files of an earlier run (as above). Collective: every process
  /// sharing the file calls it.
  FieldWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
              FieldLayout layout, const FieldFileShare& share, std::optional<double> keep_until);
  FieldWriter(const std::string& directory, const std::string& stem, const SectionMesh& mesh,
              FieldLayout layout, const FieldFileShare& share, std::optional<double> keep_until);
  ~FieldWriter();
  FieldWriter(const FieldWriter&) = delete;
  FieldWriter& operator=(const FieldWriter&) = delete;

  /// Appends output number num_outputs() at time `t` [s]. `u` is node-major, size 3·num_nodes
  /// (u[3n+c], mm), or for a section mesh 2·num_nodes (u[2n+c], the model's unknowns; written
  /// with a third component 0); `p_vertices` has one pressure per vertex [MPa] (each read only if
  /// the layout writes it). `cells` holds the layout's cell fields in its order, element-major
  /// (value[components·e + c]).
  void write(double t, const std::vector<double>& u, const std::vector<double>& p_vertices,
             const std::vector<std::vector<double>>& cells = {});

  /// write() for a writer constructed with a share: this process's rows only. `u_rows` holds
  /// the share's nodes (u_components values each, as write()'s u), `p_node_rows` the pressure
  /// [MPa] at the share's nodes (pressure_at_nodes), `p_vertex_rows` at its vertices, and each
  /// of `cell_rows` the layout's cell field on the share's cells. Collective.
  void write_rows(double t, const std::vector<double>& u_rows,
                  const std::vector<double>& p_node_rows, const std::vector<double>& p_vertex_rows,
                  const std::vector<std::vector<double>>& cell_rows);

  std::size_t num_outputs() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }  ///< output times [s]
  const std::string& h5_path() const { return h5_path_; }
  const std::string& xdmf_path() const { return xdmf_path_; }
  const FieldLayout& layout() const { return layout_; }

 private:
  void write_xdmf() const;
  /// The HDF5 groups below /fields that the layout writes into.
  std::vector<std::string> groups() const;
  /// The constructors' work for either kind of mesh (new files, or a restart).
  /// The counts and paths of `mesh`; the share's ranges checked, or all rows if not shared.
  template <class AnyMesh>
  void take_mesh(const std::string& directory, const AnyMesh& mesh);
  template <class AnyMesh>
  void create(const std::string& directory, const AnyMesh& mesh);
  template <class AnyMesh>
  void reopen(const std::string& directory, const AnyMesh& mesh, double keep_until);
  /// reopen() with `keep_until`, else create().
  template <class AnyMesh>
  void open(const std::string& directory, const AnyMesh& mesh, std::optional<double> keep_until);

  std::string stem_;
  std::string h5_path_;
  std::string xdmf_path_;
  std::int64_t file_ = -1;  ///< HDF5 file handle (hid_t)
  Index num_nodes_ = 0;
  Index num_vertices_ = 0;
  Index num_cells_ = 0;
  int nodes_per_cell_ = 10;                       ///< 10 (Tetrahedron_10) or 6 (Triangle_6)
  int u_components_ = 3;                          ///< entries per node of write()'s u
  std::string topology_type_ = "Tetrahedron_10";  ///< XDMF TopologyType
  std::vector<std::array<Index, 2>> edges_;       ///< edge node → vertex pair
  std::vector<double> times_;
  FieldLayout layout_;
  FieldFileShare rows_;  ///< the rows this process writes (all of them unless shared_)
  bool shared_ = false;  ///< several processes write the file, each its share
};

}  // namespace biphasic
