#include "biphasic/io/field_writer.hpp"

#include "biphasic/io/atomic_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <utility>

namespace biphasic {

static_assert(std::is_same_v<hid_t, std::int64_t>, "FieldWriter stores hid_t as int64");

namespace {

/// edge_node_vertices of cells with `corners` vertices and the edges `table` (local node
/// corners + k on edge table[k]); `what` names a cell in messages.
template <class Cells, class Table>
std::vector<std::array<Index, 2>> edges_of_cells(const Cells& cells, const Table& table,
                                                 int corners, Index nv, Index nn,
                                                 const std::string& what) {
  if (nv < 0 || nv > nn) {
    throw std::runtime_error("mesh: num_vertices = " + std::to_string(nv) + " with " +
                             std::to_string(nn) + " nodes");
  }
  constexpr Index kUnset = -1;
  std::vector<std::array<Index, 2>> edges(static_cast<std::size_t>(nn - nv), {kUnset, kUnset});
  for (std::size_t e = 0; e < cells.size(); ++e) {
    const auto& cell = cells[e];
    for (int c = 0; c < corners; ++c) {
      if (cell[c] < 0 || cell[c] >= nv) {
        throw std::runtime_error("mesh: " + what + " " + std::to_string(e) + " has corner node " +
                                 std::to_string(cell[c]) + ", not a vertex (0.." +
                                 std::to_string(nv - 1) + ")");
      }
    }
    for (std::size_t k = 0; k < table.size(); ++k) {
      const Index n = cell[static_cast<std::size_t>(corners) + k];
      if (n < nv || n >= nn) {
        throw std::runtime_error("mesh: " + what + " " + std::to_string(e) + " has edge node " +
                                 std::to_string(n) + ", not an edge node (" + std::to_string(nv) +
                                 ".." + std::to_string(nn - 1) + ")");
      }
      Index v0 = cell[table[k][0]];
      Index v1 = cell[table[k][1]];
      if (v1 < v0) std::swap(v0, v1);
      auto& slot = edges[static_cast<std::size_t>(n - nv)];
      if (slot[0] == kUnset) {
        slot = {v0, v1};
      } else if (slot[0] != v0 || slot[1] != v1) {
        throw std::runtime_error("mesh: edge node " + std::to_string(n) + " sits on edge (" +
                                 std::to_string(slot[0]) + "," + std::to_string(slot[1]) +
                                 ") and on edge (" + std::to_string(v0) + "," + std::to_string(v1) +
                                 ") in " + what + " " + std::to_string(e));
      }
    }
  }
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (edges[k][0] == kUnset) {
      throw std::runtime_error("mesh: edge node " + std::to_string(nv + static_cast<Index>(k)) +
                               " belongs to no " + what);
    }
  }
  return edges;
}

}  // namespace

std::vector<std::array<Index, 2>> edge_node_vertices(const Mesh& mesh) {
  return edges_of_cells(mesh.tets, kTetEdges, 4, mesh.num_vertices, mesh.num_nodes(),
                        "tetrahedron");
}

std::vector<std::array<Index, 2>> edge_node_vertices(const SectionMesh& mesh) {
  return edges_of_cells(mesh.triangles, kTriEdges, 3, mesh.num_vertices, mesh.num_nodes(),
                        "triangle");
}

std::vector<double> displacement_in_3d(const std::vector<double>& u2) {
  const std::size_t n = u2.size() / 2;
  std::vector<double> u(3 * n, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    u[3 * a] = u2[2 * a];
    u[3 * a + 1] = u2[2 * a + 1];
  }
  return u;
}

std::vector<double> pressure_at_nodes(const std::vector<std::array<Index, 2>>& edges,
                                      const std::vector<double>& p_vertices) {
  std::vector<double> p(p_vertices.size() + edges.size());
  std::copy(p_vertices.begin(), p_vertices.end(), p.begin());
  const auto nv = static_cast<Index>(p_vertices.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto [v0, v1] = edges[k];
    if (v0 < 0 || v1 < 0 || v0 >= nv || v1 >= nv) {
      throw std::runtime_error("pressure_at_nodes: edge (" + std::to_string(v0) + "," +
                               std::to_string(v1) + ") outside the " + std::to_string(nv) +
                               " vertex pressures");
    }
    p[p_vertices.size() + k] =
        0.5 * (p_vertices[static_cast<std::size_t>(v0)] + p_vertices[static_cast<std::size_t>(v1)]);
  }
  return p;
}

namespace {

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class H5Id {
 public:
  H5Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~H5Id() {
    if (id_ >= 0) close_(id_);
  }
  H5Id(H5Id&& other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  H5Id& operator=(H5Id&&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

std::string fmt_double(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// The system's reason for the innermost failure on HDF5's error stack (e.g. "No space left on
/// device" from a failed write), or "" if it records none.
std::string hdf5_cause() {
  std::string cause;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* error, void* data) -> herr_t {
        auto& found = *static_cast<std::string*>(data);
        const std::string desc = error->desc ? error->desc : "";
        const std::string tag = "error message = '";
        const auto start = desc.find(tag);
        if (found.empty() && start != std::string::npos) {
          const auto from = start + tag.size();
          found = desc.substr(from, desc.find('\'', from) - from);
        }
        return 0;
      },
      &cause);
  return cause.empty() ? cause : ": " + cause;
}

/// Helper bound to one open file that turns HDF5 failures into exceptions naming the file.
class H5File {
 public:
  H5File(hid_t file, const std::string& path, hid_t transfer = H5P_DEFAULT)
      : file_(file), path_(path), transfer_(transfer) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("FieldWriter: " + path_ + ": " + what + hdf5_cause());
  }

  void create_group(const std::string& name) const {
    H5Id g(H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail("cannot create group " + name);
  }

  /// Creates a dataset of the given shape and fills rows [rows.first, rows.first + rows.count)
  /// of it from `data` (those rows only, row-major; a scalar dataset is written if rows.count >
  /// 0); returns it for attaching attributes.
  H5Id write_dataset(const std::string& name, hid_t file_type, hid_t mem_type,
                     const std::vector<hsize_t>& dims, const void* data, RowRange rows) const {
    H5Id space(dims.empty() ? H5Screate(H5S_SCALAR)
                            : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
               H5Sclose);
    if (!space.valid()) fail("cannot create dataspace for " + name);
    H5Id set(H5Dcreate2(file_, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                        H5P_DEFAULT),
             H5Dclose);
    if (!set.valid()) fail("cannot create dataset " + name);
    // The memory holds the selected rows alone, with the dataset's other extents.
    std::vector<hsize_t> block = dims;
    if (!block.empty()) block[0] = static_cast<hsize_t>(rows.count);
    const bool none = rows.count == 0 || (!dims.empty() && dims[0] == 0);
    if (!block.empty() && none) block[0] = 1;  // a dataspace to select nothing from
    H5Id memory(block.empty()
                    ? H5Screate(H5S_SCALAR)
                    : H5Screate_simple(static_cast<int>(block.size()), block.data(), nullptr),
                H5Sclose);
    bool selected = memory.valid();
    if (selected && none) {
      selected = H5Sselect_none(memory.get()) >= 0 && H5Sselect_none(space.get()) >= 0;
    } else if (selected && !dims.empty()) {
      std::vector<hsize_t> start(dims.size(), 0);
      start[0] = static_cast<hsize_t>(rows.first);
      selected = H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                     block.data(), nullptr) >= 0;
    }
    if (!selected ||
        H5Dwrite(set.get(), mem_type, memory.get(), space.get(), transfer_, data) < 0) {
      fail("cannot write dataset " + name);
    }
    return set;
  }

  void write_attribute(hid_t object, const std::string& object_name, const std::string& name,
                       double value) const {
    H5Id space(H5Screate(H5S_SCALAR), H5Sclose);
    H5Id attr(
        H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    if (!space.valid() || !attr.valid() || H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
      fail("cannot write attribute " + name + " of " + object_name);
    }
  }

  void write_attribute(hid_t object, const std::string& object_name, const std::string& name,
                       const std::string& value) const {
    H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.valid() || H5Tset_size(type.get(), value.empty() ? 1 : value.size()) < 0 ||
        H5Tset_strpad(type.get(), H5T_STR_NULLTERM) < 0) {
      fail("cannot create string type for attribute " + name + " of " + object_name);
    }
    H5Id space(H5Screate(H5S_SCALAR), H5Sclose);
    H5Id attr(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose);
    if (!space.valid() || !attr.valid() || H5Awrite(attr.get(), type.get(), value.c_str()) < 0) {
      fail("cannot write attribute " + name + " of " + object_name);
    }
  }

 private:
  hid_t file_;
  const std::string& path_;
  hid_t transfer_;  ///< the data transfer list of every H5Dwrite
};

constexpr const char* kTimes = "/fields/times";
constexpr hsize_t kTimesChunk = 64;

/// The XDMF AttributeType of a cell field with `components` values per cell.
const char* attribute_type(int components) {
  switch (components) {
    case 1:
      return "Scalar";
    case 3:
      return "Vector";
    case 6:
      return "Tensor6";
    case 9:
      return "Tensor";
    default:
      return "";
  }
}

/// Throws std::invalid_argument if a cell field of `layout` cannot be written beside the
/// others (see the FieldWriter constructor).
void check_layout(const FieldLayout& layout) {
  std::vector<std::string> taken{"times", "displacement", "pressure", "pressure_vertices"};
  for (const CellFieldSpec& f : layout.cells) {
    if (f.name.empty() || f.name.find('/') != std::string::npos || f.name == "." ||
        f.name == "..") {
      throw std::invalid_argument("FieldWriter: invalid cell field name '" + f.name + "'");
    }
    if (std::find(taken.begin(), taken.end(), f.name) != taken.end()) {
      throw std::invalid_argument("FieldWriter: cell field '" + f.name +
                                  "' clashes with another field of that name");
    }
    if (*attribute_type(f.components) == '\0') {
      throw std::invalid_argument("FieldWriter: cell field '" + f.name + "' has " +
                                  std::to_string(f.components) +
                                  " components (1, 3, 6 or 9 can be written)");
    }
    taken.push_back(f.name);
  }
}

/// What the files hold of a mesh, for the rows of some nodes and cells: node coordinates as
/// xyz (a section's at z = 0) and the cells' nodes. Triangle_6 numbers a triangle's nodes as
/// Tri6 does (corners, then the midsides of edges 01, 12, 20).
struct MeshArrays {
  std::vector<double> xyz;
  std::vector<std::int64_t> topology;

  static const std::vector<Tet10>& cells_of(const Mesh& mesh) { return mesh.tets; }
  static const std::vector<Tri6>& cells_of(const SectionMesh& mesh) { return mesh.triangles; }
  static int nodes_per_cell_of(const Mesh&) { return 10; }
  static int nodes_per_cell_of(const SectionMesh&) { return 6; }
  static int u_components_of(const Mesh&) { return 3; }
  static int u_components_of(const SectionMesh&) { return 2; }
  static const char* topology_type_of(const Mesh&) { return "Tetrahedron_10"; }
  static const char* topology_type_of(const SectionMesh&) { return "Triangle_6"; }

  template <class AnyMesh>
  MeshArrays(const AnyMesh& mesh, RowRange nodes, RowRange cells) {
    xyz.reserve(3 * static_cast<std::size_t>(nodes.count));
    for (Index n = nodes.first; n < nodes.first + nodes.count; ++n) {
      const std::array<double, 3> x = xyz_of(mesh.nodes[static_cast<std::size_t>(n)]);
      xyz.insert(xyz.end(), x.begin(), x.end());
    }
    const auto& all = cells_of(mesh);
    topology.reserve(static_cast<std::size_t>(nodes_per_cell_of(mesh) * cells.count));
    for (Index e = cells.first; e < cells.first + cells.count; ++e) {
      const auto& cell = all[static_cast<std::size_t>(e)];
      topology.insert(topology.end(), cell.begin(), cell.end());
    }
  }
  static std::array<double, 3> xyz_of(const Point& x) { return x; }
  static std::array<double, 3> xyz_of(const Point2& x) { return {x[0], x[1], 0.0}; }
};

}  // namespace

std::vector<std::string> FieldWriter::groups() const {
  std::vector<std::string> out;
  if (layout_.displacement) out.push_back("displacement");
  if (layout_.pressure) {
    out.push_back("pressure");
    out.push_back("pressure_vertices");
  }
  for (const CellFieldSpec& f : layout_.cells) out.push_back(f.name);
  return out;
}

namespace {

/// Throws std::runtime_error unless `range` lies in [0, total); `what` names the rows.
void check_rows(const RowRange& range, Index total, const std::string& what) {
  if (range.first < 0 || range.count < 0 || range.first + range.count > total) {
    throw std::runtime_error("FieldWriter: this process's " + what + " rows [" +
                             std::to_string(range.first) + ", " +
                             std::to_string(range.first + range.count) + ") lie outside the " +
                             std::to_string(total) + " " + what);
  }
}

}  // namespace

template <class AnyMesh>
void FieldWriter::take_mesh(const std::string& directory, const AnyMesh& mesh) {
  num_nodes_ = mesh.num_nodes();
  num_vertices_ = mesh.num_vertices;
  num_cells_ = static_cast<Index>(MeshArrays::cells_of(mesh).size());
  nodes_per_cell_ = MeshArrays::nodes_per_cell_of(mesh);
  u_components_ = MeshArrays::u_components_of(mesh);
  topology_type_ = MeshArrays::topology_type_of(mesh);
  check_layout(layout_);
  namespace fs = std::filesystem;
  const fs::path dir = directory.empty() ? fs::path(".") : fs::path(directory);
  h5_path_ = (dir / (stem_ + ".h5")).string();
  xdmf_path_ = (dir / (stem_ + ".xdmf")).string();
  if (shared_) {
    check_rows(rows_.nodes, num_nodes_, "nodes");
    check_rows(rows_.vertices, num_vertices_, "vertices");
    check_rows(rows_.cells, num_cells_, "cells");
  } else {
    rows_.nodes = {0, num_nodes_};
    rows_.vertices = {0, num_vertices_};
    rows_.cells = {0, num_cells_};
  }
}

template <class AnyMesh>
void FieldWriter::create(const std::string& directory, const AnyMesh& mesh) {
  const std::string& stem = stem_;
  take_mesh(directory, mesh);
  namespace fs = std::filesystem;
  const fs::path dir = directory.empty() ? fs::path(".") : fs::path(directory);
  if (stem.empty() || stem.find('/') != std::string::npos) {
    throw std::runtime_error("FieldWriter: invalid file stem '" + stem + "' in " + directory);
  }
  if (num_cells_ == 0) throw std::runtime_error("FieldWriter: " + h5_path_ + ": mesh has no cells");
  edges_ = edge_node_vertices(mesh);

  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    throw std::runtime_error("FieldWriter: cannot create output folder " + dir.string() + ": " +
                             ec.message());
  }
  // An index left over from an earlier run would point into the file truncated below.
  if (rows_.writes_index) fs::remove(xdmf_path_, ec);
  if (ec) {
    throw std::runtime_error("FieldWriter: cannot remove stale " + xdmf_path_ + ": " +
                             ec.message());
  }

  // Failures are reported by the exceptions below, with the system's cause.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(h5_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, rows_.file_access);
  if (file_ < 0) throw std::runtime_error("FieldWriter: cannot create " + h5_path_ + hdf5_cause());

  try {
    const H5File h5(file_, h5_path_, rows_.transfer);
    h5.create_group("/mesh");
    h5.create_group("/fields");
    for (const std::string& group : groups()) h5.create_group("/fields/" + group);

    const MeshArrays arrays(mesh, rows_.nodes, rows_.cells);
    {
      H5Id set =
          h5.write_dataset("/mesh/coordinates", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                           {static_cast<hsize_t>(num_nodes_), 3}, arrays.xyz.data(), rows_.nodes);
      h5.write_attribute(set.get(), "/mesh/coordinates", "units", "mm");
    }
    h5.write_dataset("/mesh/topology", H5T_STD_I64LE, H5T_NATIVE_INT64,
                     {static_cast<hsize_t>(num_cells_), static_cast<hsize_t>(nodes_per_cell_)},
                     arrays.topology.data(), rows_.cells);
    const std::int64_t nv = num_vertices_;
    h5.write_dataset("/mesh/vertex_count", H5T_STD_I64LE, H5T_NATIVE_INT64, {}, &nv,
                     {0, rows_.writes_index ? 1 : 0});

    // Output times: 1-D, grows by one per write.
    const hsize_t zero = 0;
    const hsize_t unlimited = H5S_UNLIMITED;
    H5Id space(H5Screate_simple(1, &zero, &unlimited), H5Sclose);
    H5Id plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (!space.valid() || !plist.valid() || H5Pset_chunk(plist.get(), 1, &kTimesChunk) < 0) {
      h5.fail("cannot set up dataset " + std::string(kTimes));
    }
    H5Id times(H5Dcreate2(file_, kTimes, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, plist.get(),
                          H5P_DEFAULT),
               H5Dclose);
    if (!times.valid()) h5.fail("cannot create dataset " + std::string(kTimes));
    h5.write_attribute(times.get(), kTimes, "units", "s");

    if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) h5.fail("cannot flush");
  } catch (...) {
    H5Fclose(file_);
    file_ = -1;
    throw;
  }
}

template <class AnyMesh>
void FieldWriter::reopen(const std::string& directory, const AnyMesh& mesh, double keep_until) {
  take_mesh(directory, mesh);
  edges_ = edge_node_vertices(mesh);
  if (!std::filesystem::is_regular_file(h5_path_))
    throw std::runtime_error("FieldWriter: " + h5_path_ + " not found (nothing to continue)");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fopen(h5_path_.c_str(), H5F_ACC_RDWR, rows_.file_access);
  if (file_ < 0) throw std::runtime_error("FieldWriter: cannot open " + h5_path_ + hdf5_cause());
  try {
    const H5File h5(file_, h5_path_, rows_.transfer);
    {
      H5Id coords(H5Dopen2(file_, "/mesh/coordinates", H5P_DEFAULT), H5Dclose);
      H5Id space(coords.valid() ? H5Dget_space(coords.get()) : -1, H5Sclose);
      hsize_t dims[2] = {0, 0};
      if (!space.valid() || H5Sget_simple_extent_dims(space.get(), dims, nullptr) != 2 ||
          dims[0] != static_cast<hsize_t>(num_nodes_)) {
        h5.fail("holds another mesh (expected " + std::to_string(num_nodes_) + " nodes)");
      }
      H5Id topo(H5Dopen2(file_, "/mesh/topology", H5P_DEFAULT), H5Dclose);
      H5Id topo_space(topo.valid() ? H5Dget_space(topo.get()) : -1, H5Sclose);
      if (!topo_space.valid() || H5Sget_simple_extent_dims(topo_space.get(), dims, nullptr) != 2 ||
          dims[0] != static_cast<hsize_t>(num_cells_) ||
          dims[1] != static_cast<hsize_t>(nodes_per_cell_)) {
        h5.fail("holds another mesh (expected " + std::to_string(num_cells_) + " " +
                topology_type_ + " cells)");
      }
    }
    H5Id set(H5Dopen2(file_, kTimes, H5P_DEFAULT), H5Dclose);
    H5Id space(set.valid() ? H5Dget_space(set.get()) : -1, H5Sclose);
    hsize_t count = 0;
    if (!space.valid() || H5Sget_simple_extent_dims(space.get(), &count, nullptr) != 1)
      h5.fail("cannot read " + std::string(kTimes));
    std::vector<double> times(count);
    if (count > 0 &&
        H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data()) < 0)
      h5.fail("cannot read " + std::string(kTimes));
    std::size_t keep = 0;
    while (keep < times.size() && times[keep] <= keep_until) ++keep;
    // Outputs after the checkpoint, and any a crash left half-written, go.
    const std::vector<std::string> field_groups = groups();
    for (const std::string& group : field_groups) {
      const std::string name = "/fields/" + group;
      if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) <= 0) h5.create_group(name);
    }
    for (std::size_t i = keep;; ++i) {
      bool any = false;
      for (const std::string& group : field_groups) {
        const std::string name = "/fields/" + group + "/" + std::to_string(i);
        if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0) {
          any = true;
          if (H5Ldelete(file_, name.c_str(), H5P_DEFAULT) < 0) h5.fail("cannot delete " + name);
        }
      }
      if (!any && i >= times.size()) break;
    }
    const hsize_t new_size = keep;
    if (H5Dset_extent(set.get(), &new_size) < 0) h5.fail("cannot shorten " + std::string(kTimes));
    if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) h5.fail("cannot flush");
    times_.assign(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(keep));
    if (rows_.writes_index) write_xdmf();
  } catch (...) {
    H5Fclose(file_);
    file_ = -1;
    throw;
  }
}

FieldWriter::FieldWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
                         FieldLayout layout)
    : stem_(stem), layout_(std::move(layout)) {
  create(directory, mesh);
}

FieldWriter::FieldWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
                         double keep_until, FieldLayout layout)
    : stem_(stem), layout_(std::move(layout)) {
  reopen(directory, mesh, keep_until);
}

FieldWriter::FieldWriter(const std::string& directory, const std::string& stem,
                         const SectionMesh& mesh, FieldLayout layout)
    : stem_(stem), layout_(std::move(layout)) {
  create(directory, mesh);
}

FieldWriter::FieldWriter(const std::string& directory, const std::string& stem,
                         const SectionMesh& mesh, double keep_until, FieldLayout layout)
    : stem_(stem), layout_(std::move(layout)) {
  reopen(directory, mesh, keep_until);
}

template <class AnyMesh>
void FieldWriter::open(const std::string& directory, const AnyMesh& mesh,
                       std::optional<double> keep_until) {
  if (keep_until)
    reopen(directory, mesh, *keep_until);
  else
    create(directory, mesh);
}

FieldWriter::FieldWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
                         FieldLayout layout, const FieldFileShare& share,
                         std::optional<double> keep_until)
    : stem_(stem), layout_(std::move(layout)), rows_(share), shared_(true) {
  open(directory, mesh, keep_until);
}

FieldWriter::FieldWriter(const std::string& directory, const std::string& stem,
                         const SectionMesh& mesh, FieldLayout layout, const FieldFileShare& share,
                         std::optional<double> keep_until)
    : stem_(stem), layout_(std::move(layout)), rows_(share), shared_(true) {
  open(directory, mesh, keep_until);
}

FieldWriter::~FieldWriter() {
  if (file_ >= 0) H5Fclose(file_);
}

void FieldWriter::write(double t, const std::vector<double>& u,
                        const std::vector<double>& p_vertices,
                        const std::vector<std::vector<double>>& cells) {
  if (shared_) {
    throw std::logic_error("FieldWriter: " + h5_path_ +
                           " is written by several processes; write_rows() writes a share");
  }
  // Pressures of the wrong count are refused by write_rows(), before the nodes' are needed.
  const bool pressure_at_all_nodes =
      layout_.pressure && p_vertices.size() == static_cast<std::size_t>(num_vertices_);
  write_rows(t, u,
             pressure_at_all_nodes ? pressure_at_nodes(edges_, p_vertices) : std::vector<double>(),
             p_vertices, cells);
}

void FieldWriter::write_rows(double t, const std::vector<double>& u_rows,
                             const std::vector<double>& p_node_rows,
                             const std::vector<double>& p_vertex_rows,
                             const std::vector<std::vector<double>>& cell_rows) {
  const H5File h5(file_, h5_path_, rows_.transfer);
  const auto nn = static_cast<std::size_t>(num_nodes_);
  const auto nv = static_cast<std::size_t>(num_vertices_);
  const auto ne = static_cast<std::size_t>(num_cells_);
  const auto nu = static_cast<std::size_t>(u_components_);
  const auto my_nodes = static_cast<std::size_t>(rows_.nodes.count);
  const auto my_vertices = static_cast<std::size_t>(rows_.vertices.count);
  const auto my_cells = static_cast<std::size_t>(rows_.cells.count);
  // "of this process's" where a share is written, so the counts are not read as the mesh's.
  const std::string of = shared_ ? " of this process's " : " ";
  if (layout_.displacement && u_rows.size() != nu * my_nodes) {
    h5.fail("displacement has " + std::to_string(u_rows.size()) + " entries, expected " +
            std::to_string(nu) + " x " + std::to_string(my_nodes) + of +
            "nodes = " + std::to_string(nu * my_nodes));
  }
  if (layout_.pressure && p_vertex_rows.size() != my_vertices) {
    h5.fail("pressure has " + std::to_string(p_vertex_rows.size()) + " entries, expected " +
            std::to_string(my_vertices) + " (one per vertex" +
            (shared_ ? " of this process's rows" : "") + ")");
  }
  if (layout_.pressure && p_node_rows.size() != my_nodes) {
    h5.fail("pressure at the nodes has " + std::to_string(p_node_rows.size()) +
            " entries, expected " + std::to_string(my_nodes) + " (one per node" + of + "nodes)");
  }
  if (cell_rows.size() != layout_.cells.size()) {
    h5.fail(std::to_string(cell_rows.size()) + " cell fields given, the layout has " +
            std::to_string(layout_.cells.size()));
  }
  for (std::size_t f = 0; f < cell_rows.size(); ++f) {
    const auto expected = static_cast<std::size_t>(layout_.cells[f].components) * my_cells;
    if (cell_rows[f].size() != expected) {
      h5.fail(layout_.cells[f].name + " has " + std::to_string(cell_rows[f].size()) +
              " entries, expected " + std::to_string(layout_.cells[f].components) + " x " +
              std::to_string(my_cells) + of + "cells = " + std::to_string(expected));
    }
  }
  if (!std::isfinite(t)) h5.fail("output time is not finite");

  const std::string step = std::to_string(times_.size());

  const auto put = [&](const std::string& group, std::vector<hsize_t> dims, const double* data,
                       RowRange rows, const std::string& units) {
    const std::string name = "/fields/" + group + "/" + step;
    H5Id set = h5.write_dataset(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data, rows);
    h5.write_attribute(set.get(), name, "time", t);
    h5.write_attribute(set.get(), name, "units", units);
  };
  if (layout_.displacement) {
    if (u_components_ == 3) {
      put("displacement", {nn, 3}, u_rows.data(), rows_.nodes, "mm");
    } else {
      const std::vector<double> u3 = displacement_in_3d(u_rows);
      put("displacement", {nn, 3}, u3.data(), rows_.nodes, "mm");
    }
  }
  if (layout_.pressure) {
    put("pressure", {nn}, p_node_rows.data(), rows_.nodes, "MPa");
    put("pressure_vertices", {nv}, p_vertex_rows.data(), rows_.vertices, "MPa");
  }
  for (std::size_t f = 0; f < cell_rows.size(); ++f) {
    const CellFieldSpec& spec = layout_.cells[f];
    std::vector<hsize_t> dims{ne};
    if (spec.components > 1) dims.push_back(static_cast<hsize_t>(spec.components));
    put(spec.name, dims, cell_rows[f].data(), rows_.cells, spec.units);
  }

  {
    H5Id set(H5Dopen2(file_, kTimes, H5P_DEFAULT), H5Dclose);
    const hsize_t old_size = times_.size();
    const hsize_t new_size = old_size + 1;
    const hsize_t one = 1;
    if (!set.valid() || H5Dset_extent(set.get(), &new_size) < 0) {
      h5.fail("cannot extend " + std::string(kTimes));
    }
    // The index writer appends the time; the others take part in the write with nothing.
    H5Id file_space(H5Dget_space(set.get()), H5Sclose);
    H5Id mem_space(H5Screate_simple(1, &one, nullptr), H5Sclose);
    const bool selected =
        file_space.valid() && mem_space.valid() &&
        (rows_.writes_index
             ? H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &old_size, nullptr, &one,
                                   nullptr) >= 0
             : H5Sselect_none(file_space.get()) >= 0 && H5Sselect_none(mem_space.get()) >= 0);
    if (!selected || H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, mem_space.get(), file_space.get(),
                              rows_.transfer, &t) < 0) {
      h5.fail("cannot append to " + std::string(kTimes));
    }
  }
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) h5.fail("cannot flush");

  times_.push_back(t);
  if (rows_.writes_index) write_xdmf();
}

void FieldWriter::write_xdmf() const {
  const std::string h5_name = xml_escape(stem_ + ".h5");
  const std::string n = std::to_string(num_nodes_);
  const std::string e = std::to_string(num_cells_);
  const std::string per_cell = " " + std::to_string(nodes_per_cell_);
  const auto item = [&](const std::string& dims, const char* type, int precision,
                        const std::string& path) {
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"" +
           std::to_string(precision) + "\" Format=\"HDF\">" + h5_name + ":" + path + "</DataItem>";
  };

  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<Xdmf Version=\"3.0\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"" << xml_escape(stem_)
    << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t i = 0; i < times_.size(); ++i) {
    const std::string step = std::to_string(i);
    x << "      <Grid Name=\"step_" << step << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << fmt_double(times_[i]) << "\"/>\n"
      << "        <Topology TopologyType=\"" << topology_type_ << "\" NumberOfElements=\"" << e
      << "\">\n"
      << "          " << item(e + per_cell, "Int", 8, "/mesh/topology") << "\n"
      << "        </Topology>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n"
      << "          " << item(n + " 3", "Float", 8, "/mesh/coordinates") << "\n"
      << "        </Geometry>\n";
    const auto attribute = [&](const std::string& name, const char* type, const char* center,
                               const std::string& dims) {
      x << "        <Attribute Name=\"" << xml_escape(name) << "\" AttributeType=\"" << type
        << "\" Center=\"" << center << "\">\n"
        << "          " << item(dims, "Float", 8, "/fields/" + xml_escape(name) + "/" + step)
        << "\n"
        << "        </Attribute>\n";
    };
    if (layout_.displacement) attribute("displacement", "Vector", "Node", n + " 3");
    if (layout_.pressure) attribute("pressure", "Scalar", "Node", n);
    for (const CellFieldSpec& f : layout_.cells) {
      attribute(f.name, attribute_type(f.components), "Cell",
                f.components == 1 ? e : e + " " + std::to_string(f.components));
    }
    x << "      </Grid>\n";
  }
  x << "    </Grid>\n"
    << "  </Domain>\n"
    << "</Xdmf>\n";

  write_file_atomically(xdmf_path_, x.str());
}

}  // namespace biphasic
