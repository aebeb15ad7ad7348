// Mesh cache: a stored mesh comes back bit for bit; anything that does not match (another
// description, a damaged or truncated file) is regenerated; the key covers every spec field.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh_cache.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace {

namespace fs = std::filesystem;
using biphasic::CachedMesh;
using biphasic::Mesh;

bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.nodes != b.nodes || a.num_vertices != b.num_vertices || a.tets != b.tets ||
      a.boundaries.size() != b.boundaries.size() || a.tet_region != b.tet_region ||
      a.region_names != b.region_names)
    return false;
  for (std::size_t i = 0; i < a.boundaries.size(); ++i)
    if (a.boundaries[i].name != b.boundaries[i].name ||
        a.boundaries[i].faces != b.boundaries[i].faces)
      return false;
  return true;
}

class MeshCache : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("biphasic_mesh_cache_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    biphasic::ColumnSpec spec;
    spec.nx = 2;
    spec.ny = 3;
    spec.nz = 4;
    spec.grading_faces = {"top"};
    spec.grading_ratio = 3.0;
    column_ = biphasic::generate_column(spec);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// cached_mesh with a generator that counts its calls.
  CachedMesh fetch(const std::string& description) {
    return biphasic::cached_mesh(dir_, description, [&] {
      ++generated_;
      return column_;
    });
  }
  std::vector<fs::path> files() const {
    std::vector<fs::path> out;
    if (fs::exists(dir_))
      for (const auto& entry : fs::directory_iterator(dir_)) out.push_back(entry.path());
    return out;
  }

  /// Rewrites the 8-byte index at byte `offset` of the only cache file to `value`, then
  /// recomputes the trailing FNV-1a checksum so that the file passes as intact.
  void rewrite_index_with_valid_checksum(std::size_t offset, std::int64_t value) {
    ASSERT_EQ(files().size(), 1u);
    const fs::path path = files()[0];
    std::vector<char> bytes(fs::file_size(path));
    std::ifstream(path, std::ios::binary).read(bytes.data(), static_cast<long>(bytes.size()));
    std::memcpy(bytes.data() + offset, &value, sizeof value);
    std::uint64_t h = 14695981039346656037ull;
    for (std::size_t i = 0; i + 8 < bytes.size(); ++i) {
      h ^= static_cast<unsigned char>(bytes[i]);
      h *= 1099511628211ull;
    }
    std::memcpy(bytes.data() + bytes.size() - 8, &h, sizeof h);
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), static_cast<long>(bytes.size()));
  }
  /// Byte offset of the first tetrahedron's first index in the entry of `description`
  /// (layout documented in mesh_cache.cpp).
  std::size_t first_tet_offset(const std::string& description) const {
    return 14 + 4 + 4 + 8 + description.size() + 8 + column_.nodes.size() * 24 + 8 + 8;
  }
  std::size_t first_face_offset(const std::string& description) const {
    const std::string& name = column_.boundaries[0].name;
    return first_tet_offset(description) + column_.tets.size() * 80 + 8 + 8 + name.size() + 8;
  }

  fs::path dir_;
  Mesh column_;
  int generated_ = 0;
};

TEST_F(MeshCache, StoresOnceThenReturnsTheSameMeshBitForBit) {
  const CachedMesh first = fetch("column A");
  EXPECT_FALSE(first.from_cache);
  const CachedMesh second = fetch("column A");
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(generated_, 1);
  EXPECT_TRUE(same_mesh(second.mesh, column_));
  ASSERT_EQ(files().size(), 1u);  // no temporary file left behind
  EXPECT_EQ(files()[0].extension(), ".mesh");
}

// The column's regions: per layer, from the bottom; stored and read back by the cache.
TEST_F(MeshCache, ColumnRegionsFollowTheLayersAndAreStored) {
  biphasic::ColumnSpec spec;
  spec.nx = 2;
  spec.nz = 4;
  spec.region_names = {"bone", "cartilage"};
  spec.region_tops = {0.75, 1.0};
  column_ = biphasic::generate_column(spec);
  ASSERT_EQ(column_.tet_region.size(), column_.tets.size());
  EXPECT_EQ(column_.region_names, (std::vector<std::string>{"bone", "cartilage"}));
  for (std::size_t t = 0; t < column_.tets.size(); ++t) {
    double z = 0.0;
    for (int c = 0; c < 4; ++c) z += 0.25 * column_.nodes[column_.tets[t][c]][2];
    EXPECT_EQ(column_.tet_region[t], z < 0.75 ? 0 : 1) << "tet " << t;
  }
  fetch("column with regions");
  const CachedMesh cached = fetch("column with regions");
  EXPECT_TRUE(cached.from_cache);
  EXPECT_TRUE(same_mesh(cached.mesh, column_));
  spec.region_tops = {0.6, 1.0};  // not a layer interface
  EXPECT_THROW(biphasic::generate_column(spec), std::runtime_error);
  spec.region_tops = {0.75, 0.9};  // short of the top
  EXPECT_THROW(biphasic::generate_column(spec), std::runtime_error);
}

TEST_F(MeshCache, AnotherDescriptionIsAnotherMesh) {
  fetch("column A");
  const CachedMesh other = fetch("column B");
  EXPECT_FALSE(other.from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_EQ(files().size(), 2u);
}

TEST_F(MeshCache, DamagedOrTruncatedFilesAreRegeneratedAndReplaced) {
  fetch("column A");
  ASSERT_EQ(files().size(), 1u);
  const fs::path path = files()[0];
  const auto size = fs::file_size(path);
  {  // one flipped byte in the node coordinates
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(size / 2));
    char c = 0;
    f.get(c);
    f.seekp(static_cast<std::streamoff>(size / 2));
    f.put(static_cast<char>(c ^ 0x10));
  }
  const CachedMesh repaired = fetch("column A");
  EXPECT_FALSE(repaired.from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_TRUE(fetch("column A").from_cache);  // the damaged file was replaced

  fs::resize_file(path, size - 20);
  EXPECT_FALSE(fetch("column A").from_cache);
  EXPECT_EQ(generated_, 3);
  fs::resize_file(path, 0);
  EXPECT_FALSE(fetch("column A").from_cache);
  EXPECT_EQ(generated_, 4);
  EXPECT_TRUE(same_mesh(fetch("column A").mesh, column_));
}

// A checksum shows the bytes are what was written, not that they form a mesh: an entry whose
// indices point outside the node array must not reach the assembly (it wrote out of bounds).
TEST_F(MeshCache, EntryWithValidChecksumButIndexOutOfRangeIsRegenerated) {
  fetch("column A");
  rewrite_index_with_valid_checksum(first_tet_offset("column A"), 1'000'000'000);
  const CachedMesh fresh = fetch("column A");
  EXPECT_FALSE(fresh.from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_TRUE(same_mesh(fresh.mesh, column_));
  EXPECT_TRUE(fetch("column A").from_cache);  // replaced by a sound entry

  rewrite_index_with_valid_checksum(first_tet_offset("column A") + 8 * 9, -3);  // an edge node
  EXPECT_FALSE(fetch("column A").from_cache);
  EXPECT_EQ(generated_, 3);
}

TEST_F(MeshCache, EntryWithBoundaryFaceNodeOutOfRangeIsRegenerated) {
  fetch("column A");
  ASSERT_FALSE(column_.boundaries.empty());
  rewrite_index_with_valid_checksum(first_face_offset("column A"), column_.num_nodes());
  const CachedMesh fresh = fetch("column A");
  EXPECT_FALSE(fresh.from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_TRUE(same_mesh(fresh.mesh, column_));
}

// Found by fuzz_mesh_cache: an entry holding an empty mesh (no nodes, no tets) passed the
// checksum, copied zero bytes to a null pointer (undefined behaviour, reported by UBSan) and
// came back as a "valid" mesh without tetrahedra.
TEST_F(MeshCache, EntryWithAnEmptyMeshIsRegenerated) {
  fetch("column A");
  ASSERT_EQ(files().size(), 1u);
  const fs::path path = files()[0];
  const std::string description = "column A";
  std::vector<char> bytes;
  const auto put = [&](const auto& value) {
    const char* p = reinterpret_cast<const char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof value);
  };
  const std::string magic = "biphasic-mesh\n";
  bytes.insert(bytes.end(), magic.begin(), magic.end());
  put(std::uint32_t{1});
  put(std::uint32_t{0x01020304u});
  put(std::uint64_t{description.size()});
  bytes.insert(bytes.end(), description.begin(), description.end());
  for (int i = 0; i < 4; ++i) put(std::uint64_t{0});  // nodes, num_vertices, tets, boundaries
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  put(h);
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<long>(bytes.size()));
  const CachedMesh fresh = fetch("column A");
  EXPECT_FALSE(fresh.from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_TRUE(same_mesh(fresh.mesh, column_));
}

// A FIFO (or a link to /dev/zero) in place of an entry used to block the run or grow memory
// without bound: only regular files are read, links and special files count as a miss.
TEST_F(MeshCache, FifoOrSymlinkInPlaceOfAnEntryIsAMissNotAHang) {
  fetch("column A");
  ASSERT_EQ(files().size(), 1u);
  const fs::path path = files()[0];
  fs::remove(path);
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EXPECT_FALSE(fetch("column A").from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(path)));  // replaced by a real entry
  EXPECT_TRUE(fetch("column A").from_cache);

  fs::remove(path);
  fs::create_symlink("/dev/zero", path);
  EXPECT_FALSE(fetch("column A").from_cache);
  EXPECT_EQ(generated_, 3);

  // Even a link to a sound entry is not followed.
  const fs::path elsewhere = dir_ / "elsewhere";
  fs::rename(path, elsewhere);
  fs::create_symlink(elsewhere, path);
  EXPECT_FALSE(fetch("column A").from_cache);
  EXPECT_EQ(generated_, 4);
}

TEST_F(MeshCache, EmptyDirectoryDisablesTheCache) {
  const auto generate = [&] {
    ++generated_;
    return column_;
  };
  EXPECT_FALSE(biphasic::cached_mesh({}, "column A", generate).from_cache);
  EXPECT_FALSE(biphasic::cached_mesh({}, "column A", generate).from_cache);
  EXPECT_EQ(generated_, 2);
  EXPECT_TRUE(files().empty());
}

TEST_F(MeshCache, UnwritableDirectoryStillGivesTheMesh) {
  fs::create_directories(dir_.parent_path());
  { std::ofstream(dir_) << "a file where the cache directory should be"; }
  const CachedMesh mesh = fetch("column A");
  EXPECT_FALSE(mesh.from_cache);
  EXPECT_TRUE(same_mesh(mesh.mesh, column_));
  fs::remove(dir_);
}

TEST(MeshCacheDirectory, FollowsTheEnvironment) {
  const char* saved = std::getenv("BIPHASIC_MESH_CACHE");
  const std::string restore = saved ? saved : "";
  setenv("BIPHASIC_MESH_CACHE", "/some/where", 1);
  EXPECT_EQ(biphasic::mesh_cache_directory(), fs::path("/some/where"));
  setenv("BIPHASIC_MESH_CACHE", "off", 1);
  EXPECT_TRUE(biphasic::mesh_cache_directory().empty());
  setenv("BIPHASIC_MESH_CACHE", "", 1);
  EXPECT_TRUE(biphasic::mesh_cache_directory().empty());
  unsetenv("BIPHASIC_MESH_CACHE");
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const std::string xdg_restore = xdg ? xdg : "";
  setenv("XDG_CACHE_HOME", "/xdg", 1);
  EXPECT_EQ(biphasic::mesh_cache_directory(), fs::path("/xdg/biphasic/meshes"));
  if (xdg)
    setenv("XDG_CACHE_HOME", xdg_restore.c_str(), 1);
  else
    unsetenv("XDG_CACHE_HOME");
  if (saved) setenv("BIPHASIC_MESH_CACHE", restore.c_str(), 1);
}

TEST(MeshCacheDescription, CoversEveryFieldThatShapesTheMeshButNotTheMshFile) {
  const biphasic::QuarterCylinderSpec base;
  const std::string key = biphasic::mesh_description(base);
  EXPECT_NE(key.find("libbiphasic_gmsh"), std::string::npos) << key;  // the mesher's identity
  auto differs = [&](auto change) {
    biphasic::QuarterCylinderSpec spec = base;
    change(spec);
    return biphasic::mesh_description(spec) != key;
  };
  using Spec = biphasic::QuarterCylinderSpec;
  EXPECT_TRUE(differs([](Spec& s) { s.radius = 17.0; }));
  EXPECT_TRUE(differs([](Spec& s) { s.height = 8.5; }));
  EXPECT_TRUE(differs([](Spec& s) { s.lc = 1.3 * (1.0 + 1e-15); }));  // exact, not rounded
  EXPECT_TRUE(differs([](Spec& s) { s.grading_faces = {"top"}; }));
  EXPECT_TRUE(differs([](Spec& s) { s.grading_ratio = 2.0; }));
  EXPECT_TRUE(differs([](Spec& s) { s.grading_distance = 3.0; }));
  EXPECT_TRUE(differs([](Spec& s) { s.layers = 8; }));
  EXPECT_TRUE(differs([](Spec& s) { s.layer_grading_faces = {"bottom"}; }));
  EXPECT_TRUE(differs([](Spec& s) { s.layer_grading_ratio = 5.0; }));
  EXPECT_FALSE(differs([](Spec& s) { s.write_msh = "mesh.msh"; }));

  const biphasic::SphereOctantSpec sphere;
  EXPECT_NE(biphasic::mesh_description(sphere), key);
  biphasic::SphereOctantSpec finer = sphere;
  finer.lc = 0.1;
  EXPECT_NE(biphasic::mesh_description(finer), biphasic::mesh_description(sphere));
}

TEST(MeshCacheGenerated, CachedQuarterCylinderEqualsAFreshOne) {
  const fs::path dir =
      fs::temp_directory_path() / ("biphasic_mesh_cache_generated_" + std::to_string(getpid()));
  fs::remove_all(dir);
  biphasic::QuarterCylinderSpec spec;
  spec.lc = 4.0;
  const std::string key = biphasic::mesh_description(spec);
  const auto generate = [&] { return biphasic::generate_quarter_cylinder(spec); };
  EXPECT_FALSE(biphasic::cached_mesh(dir, key, generate).from_cache);
  const CachedMesh cached = biphasic::cached_mesh(dir, key, generate);
  EXPECT_TRUE(cached.from_cache);
  EXPECT_TRUE(same_mesh(cached.mesh, generate()));
  fs::remove_all(dir);
}

}  // namespace
