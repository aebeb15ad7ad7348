// Mesh cache: a stored mesh comes back bit for bit; anything that does not match (another
// description, a damaged or truncated file) is regenerated; the key covers every spec field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
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
      a.boundaries.size() != b.boundaries.size())
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
