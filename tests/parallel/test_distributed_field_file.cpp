// One fields.h5 written by 1, 2 or 3 processes together through parallel HDF5 (ctest label
// mpi), against the file one process writes of the same state: every dataset bit for bit, the
// same XDMF index; the same for a continued file (a restart keeping the first output). The state
// is known in the one-process layout on every process, so each process's rows are checked
// against it as well.
#include <gtest/gtest.h>
#include <petscsys.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/box_mesh.hpp"
#include "../common/every_condition.hpp"
#include "../common/h5_reader.hpp"
#include "../common/run_binary.hpp"
#include "biphasic/parallel/distributed_assembly.hpp"
#include "biphasic/parallel/distributed_field_rows.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;
using e2e::read_text;

/// A value for entry i of output k that no two entries share.
double state_value(std::size_t i, int k) { return std::sin(0.37 * static_cast<double>(i) + k); }
double cell_value(Index e, int c, int k) { return 1000.0 * k + static_cast<double>(e) + 0.01 * c; }

/// A temporary folder made by process 0, its name known to all, removed at the end.
struct SharedTempDir {
  SharedTempDir() {
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    char name[] = "/tmp/biphasic_field_file_XXXXXX";
    if (rank == 0 && mkdtemp(name) == nullptr) name[0] = '\0';
    MPI_Bcast(name, sizeof name, MPI_CHAR, 0, PETSC_COMM_WORLD);
    path = name;
  }
  ~SharedTempDir() {
    MPI_Barrier(PETSC_COMM_WORLD);
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    std::error_code ec;
    if (rank == 0) fs::remove_all(path, ec);
  }
  std::string path;
};

TEST(DistributedFieldFile, IsTheOneProcessFileBitForBit) {
  const Mesh mesh = test::box_mesh({3, 2, 4}, {1.0, 0.8, 1.2});
  const Config config = test::every_condition();
  DistributedAssembly assembly(mesh, config, PETSC_COMM_WORLD);
  const PartitionedNumbering& numbering = assembly.numbering();
  const std::vector<Index> rank_major = rank_major_of_whole(mesh.num_vertices, numbering);
  const std::size_t n = rank_major.size();
  const auto num_nodes = static_cast<std::size_t>(mesh.num_nodes());
  const auto num_cells = static_cast<Index>(mesh.tets.size());
  const SubdomainMap& sub = assembly.subdomain();
  std::vector<Index> owned_cells;
  for (std::size_t e = 0; e < sub.element_owned.size(); ++e)
    if (sub.element_owned[e]) owned_cells.push_back(sub.global_element[e]);

  const FieldLayout layout{true, true, {{"J", 1, "-"}, {"stress", 6, "MPa"}}};
  const std::vector<std::array<Index, 2>> edges = edge_node_vertices(mesh);
  DistributedFieldRows rows(PETSC_COMM_WORLD, numbering, mesh.num_vertices, edges, num_cells,
                            owned_cells);
  const FieldFileShare& share = rows.share();
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);

  // Output k of the state: the whole one on every process, this process's owned part, the cell
  // fields of its own cells and of the whole mesh.
  struct Output {
    std::vector<double> whole, owned;
    std::vector<std::vector<double>> own_cells, all_cells;
  };
  auto output = [&](int k) {
    Output o;
    o.whole.resize(n);
    for (std::size_t i = 0; i < n; ++i) o.whole[i] = state_value(i, k);
    o.owned.resize(static_cast<std::size_t>(assembly.owned_size()));
    for (std::size_t i = 0; i < n; ++i) {
      const Index g = rank_major[i] - assembly.first_owned();
      if (g >= 0 && g < assembly.owned_size()) o.owned[static_cast<std::size_t>(g)] = o.whole[i];
    }
    for (const CellFieldSpec& f : layout.cells) {
      std::vector<double> own, all;
      for (Index e : owned_cells)
        for (int c = 0; c < f.components; ++c) own.push_back(cell_value(e, c, k));
      for (Index e = 0; e < num_cells; ++e)
        for (int c = 0; c < f.components; ++c) all.push_back(cell_value(e, c, k));
      o.own_cells.push_back(own);
      o.all_cells.push_back(all);
    }
    return o;
  };
  // Writes output k: all processes their rows into `shared`, process 0 alone the whole into
  // `alone`; checks this process's rows against the whole state.
  auto write = [&](FieldWriter& shared, FieldWriter* alone, int k, double t) {
    const Output o = output(k);
    std::vector<double> u, p_nodes, p_vertices;
    rows.node_rows(o.owned.data(), u, p_nodes, p_vertices);
    const std::vector<double> p_all(o.whole.begin() + static_cast<std::ptrdiff_t>(3 * num_nodes),
                                    o.whole.end());
    const std::vector<double> p_at_nodes = pressure_at_nodes(edges, p_all);
    for (Index a = 0; a < share.nodes.count; ++a) {
      const auto node = static_cast<std::size_t>(share.nodes.first + a);
      for (std::size_t c = 0; c < 3; ++c)
        ASSERT_EQ(u[3 * static_cast<std::size_t>(a) + c], o.whole[3 * node + c]);
      ASSERT_EQ(p_nodes[static_cast<std::size_t>(a)], p_at_nodes[node]);
    }
    for (Index v = 0; v < share.vertices.count; ++v)
      ASSERT_EQ(p_vertices[static_cast<std::size_t>(v)],
                p_all[static_cast<std::size_t>(share.vertices.first + v)]);
    std::vector<std::vector<double>> cells;
    for (std::size_t q = 0; q < layout.cells.size(); ++q) {
      cells.push_back(rows.cell_rows(o.own_cells[q], layout.cells[q].components));
      const auto width = static_cast<std::size_t>(layout.cells[q].components);
      const auto first = static_cast<std::size_t>(share.cells.first) * width;
      ASSERT_EQ(cells[q], std::vector<double>(o.all_cells[q].begin() + first,
                                              o.all_cells[q].begin() + first + cells[q].size()));
    }
    shared.write_rows(t, u, p_nodes, p_vertices, cells);
    if (alone) {
      const std::vector<double> u_all(o.whole.begin(),
                                      o.whole.begin() + static_cast<std::ptrdiff_t>(3 * num_nodes));
      alone->write(t, u_all, p_all, o.all_cells);
    }
  };
  // Process 0 compares the two files: every dataset of both, and the indices.
  auto compare = [&](const std::string& a_dir, const std::string& b_dir) {
    if (rank != 0) return;
    test::H5Reader a(a_dir + "/fields.h5"), b(b_dir + "/fields.h5");
    std::vector<std::string> paths{"/mesh/coordinates", "/fields/times"};
    for (const char* group : {"displacement", "pressure", "pressure_vertices", "J", "stress"})
      for (const char* k : {"0", "1"}) paths.push_back(std::string("/fields/") + group + "/" + k);
    for (const std::string& path : paths) {
      ASSERT_TRUE(b.exists(path)) << path;
      EXPECT_EQ(a.dims(path), b.dims(path)) << path;
      EXPECT_EQ(a.read<double>(path, H5T_NATIVE_DOUBLE), b.read<double>(path, H5T_NATIVE_DOUBLE))
          << path;
    }
    for (const char* path : {"/mesh/topology", "/mesh/vertex_count"})
      EXPECT_EQ(a.read<std::int64_t>(path, H5T_NATIVE_INT64),
                b.read<std::int64_t>(path, H5T_NATIVE_INT64))
          << path;
    EXPECT_EQ(a.time_attribute("/fields/stress/1"), b.time_attribute("/fields/stress/1"));
    EXPECT_EQ(b.string_attribute("/fields/stress/1", "units"), "MPa");
    EXPECT_EQ(b.string_attribute("/mesh/coordinates", "units"), "mm");
    EXPECT_FALSE(b.exists("/fields/J/2"));
    EXPECT_EQ(read_text(a_dir + "/fields.xdmf"), read_text(b_dir + "/fields.xdmf"));
  };

  const SharedTempDir tmp;
  ASSERT_FALSE(tmp.path.empty());
  const std::string shared_dir = tmp.path + "/shared", alone_dir = tmp.path + "/alone";
  {
    FieldWriter shared(shared_dir, "fields", mesh, layout, share, std::nullopt);
    std::unique_ptr<FieldWriter> alone =
        rank == 0 ? std::make_unique<FieldWriter>(alone_dir, "fields", mesh, layout) : nullptr;
    write(shared, alone.get(), 0, 0.5);
    write(shared, alone.get(), 1, 1.0);
    write(shared, alone.get(), 2, 1.5);  // dropped by the restart below
  }
  // A restart from t = 0.5 keeps output 0 and writes output 1 again.
  {
    FieldWriter shared(shared_dir, "fields", mesh, layout, share, 0.5);
    std::unique_ptr<FieldWriter> alone =
        rank == 0 ? std::make_unique<FieldWriter>(alone_dir, "fields", mesh, 0.5, layout) : nullptr;
    EXPECT_EQ(shared.num_outputs(), 1u);
    write(shared, alone.get(), 1, 1.0);
  }
  MPI_Barrier(PETSC_COMM_WORLD);
  compare(alone_dir, shared_dir);
}

TEST(DistributedFieldFile, BlocksCoverEveryRowOnce) {
  for (int size = 1; size <= 5; ++size) {
    Index next = 0;
    for (int r = 0; r < size; ++r) {
      const RowRange rows = block_rows(17, r, size);
      EXPECT_EQ(rows.first, next);
      EXPECT_GE(rows.count, 17 / size);
      EXPECT_LE(rows.count, 17 / size + 1);
      next = rows.first + rows.count;
    }
    EXPECT_EQ(next, 17);
  }
}

}  // namespace
}  // namespace biphasic
