// Output folder rules (default name, lock, earlier runs) and checked writes (full disk through
// a link to /dev/full, which fails every write with ENOSPC).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "biphasic/io/atomic_file.hpp"
#include "biphasic/io/output_folder.hpp"
#include "biphasic/io/reaction_csv.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  explicit TempDir(const std::string& name)
      : path(fs::path(::testing::TempDir()) /
             ("biphasic_folder_" + name + "_" + std::to_string(getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  fs::path path;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(AtomicFile, ReplacesTheWholeFile) {
  TempDir dir("atomic");
  const fs::path file = dir.path / "summary.json";
  write_file_atomically(file.string(), "first\n");
  write_file_atomically(file.string(), "second\n");
  EXPECT_EQ(read_text(file), "second\n");
  EXPECT_FALSE(fs::exists(dir.path / "summary.json.tmp"));
}

TEST(AtomicFile, FullDiskKeepsTheOldFileAndNamesTheCause) {
  TempDir dir("full");
  const fs::path file = dir.path / "summary.json";
  write_file_atomically(file.string(), "{\"status\": \"running\"}\n");
  // The temporary lands on a full device: the write must fail and the good file stay.
  fs::create_symlink("/dev/full", dir.path / "summary.json.tmp");
  const std::string error = error_of([&] { write_file_atomically(file.string(), "new\n"); });
  EXPECT_NE(error.find("summary.json"), std::string::npos) << error;
  EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
  EXPECT_FALSE(fs::is_symlink(file));
  EXPECT_EQ(read_text(file), "{\"status\": \"running\"}\n");
}

TEST(ReactionCsvTest, FullDiskIsAnError) {
  TempDir dir("reactions");
  fs::create_symlink("/dev/full", dir.path / "reactions.csv");
  const std::string error =
      error_of([&] { ReactionCsv csv((dir.path / "reactions.csv").string()); });
  EXPECT_NE(error.find("reactions.csv"), std::string::npos) << error;
  EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
}

TEST(ReactionCsvTest, AppendKeepsTheRows) {
  TempDir dir("append");
  const std::string path = (dir.path / "reactions.csv").string();
  ReactionCsv(path).write(1.0, {"bottom"}, {{0.0, 0.0, 2.5}});
  ReactionCsv(path, true).write(2.0, {"bottom"}, {{0.0, 0.0, 3.5}});
  EXPECT_EQ(read_text(path), "t,boundary,Fx,Fy,Fz\n1,bottom,0,0,2.5\n2,bottom,0,0,3.5\n");
}

TEST(DefaultOutputFolder, NamesTheOverrides) {
  EXPECT_EQ(default_output_folder("cases/paper/mesh1.toml", {}), "results/mesh1");
  EXPECT_EQ(default_output_folder("mesh1.toml", {"time.dt=3.2", "material.permeability=1e-2"}),
            "results/mesh1--time.dt=3.2,material.permeability=1e-2");
  EXPECT_EQ(default_output_folder("c.toml", {"boundary[0].value=-0.16", "a=\"x y/z\""}),
            "results/c--boundary_0_.value=-0.16,a=_x_y_z_");
  // Long suffixes are cut and keep a hash of the full text, so they stay distinct.
  const std::string a = default_output_folder(
      "c.toml", {"stabilisation.type=flux_perturbation", "material.permeability=1e-2", "x=1"});
  const std::string b = default_output_folder(
      "c.toml", {"stabilisation.type=flux_perturbation", "material.permeability=1e-2", "x=2"});
  EXPECT_NE(a, b);
  EXPECT_LE(fs::path(a).filename().string().size(), 3 + 2 + 50 + 1 + 8u) << a;
  EXPECT_EQ(a.substr(0, 40), b.substr(0, 40));
}

TEST(OutputFolderTest, ARegularFileIsRefused) {
  TempDir dir("file");
  const fs::path file = dir.path / "notes.txt";
  std::ofstream(file) << "keep me\n";
  const std::string error = error_of([&] { OutputFolder f(file.string(), EarlierRun::Refuse); });
  EXPECT_NE(error.find(file.string()), std::string::npos) << error;
  EXPECT_NE(error.find("is a file"), std::string::npos) << error;
  EXPECT_EQ(read_text(file), "keep me\n");
  // A folder below a file cannot be made either.
  const std::string below =
      error_of([&] { OutputFolder f((file / "out").string(), EarlierRun::Refuse); });
  EXPECT_NE(below.find("cannot create output folder"), std::string::npos) << below;
}

TEST(OutputFolderTest, AFolderNothingCanBeWrittenInIsRefused) {
  // /proc/1 exists and is a folder, but no file can be created in it, not even by root.
  const std::string error = error_of([&] { OutputFolder f("/proc/1", EarlierRun::Refuse); });
  EXPECT_NE(error.find("/proc/1"), std::string::npos) << error;
}

TEST(OutputFolderTest, ASecondHolderIsRefusedWithThePid) {
  TempDir dir("lock");
  {
    const OutputFolder first(dir.path.string(), EarlierRun::Refuse);
    const std::string error =
        error_of([&] { OutputFolder second(dir.path.string(), EarlierRun::Refuse); });
    EXPECT_NE(error.find(dir.path.string()), std::string::npos) << error;
    EXPECT_NE(error.find("in use by another run (pid " + std::to_string(getpid()) + ")"),
              std::string::npos)
        << error;
  }
  // Released with the first holder.
  EXPECT_NO_THROW(OutputFolder again(dir.path.string(), EarlierRun::Refuse));
}

TEST(OutputFolderTest, AnEarlierRunIsRefusedOrClearedAsAWhole) {
  TempDir dir("earlier");
  std::ofstream(dir.path / "summary.json")
      << R"({"status": "completed", "configuration": {"mesh": {"write_msh": "m/mesh.msh"}}})";
  for (const char* f : {"line.csv", "reactions.csv", "fields.h5", "fields.xdmf"})
    std::ofstream(dir.path / f) << "old\n";
  fs::create_directories(dir.path / "m");
  std::ofstream(dir.path / "m" / "mesh.msh") << "old\n";
  std::ofstream(dir.path / "notes.txt") << "mine\n";

  const std::string error =
      error_of([&] { OutputFolder f(dir.path.string(), EarlierRun::Refuse); });
  EXPECT_NE(error.find(dir.path.string()), std::string::npos) << error;
  EXPECT_NE(error.find("earlier run"), std::string::npos) << error;
  EXPECT_NE(error.find("--overwrite"), std::string::npos) << error;
  EXPECT_TRUE(fs::exists(dir.path / "line.csv"));

  {
    const OutputFolder kept(dir.path.string(), EarlierRun::Continue);
    EXPECT_TRUE(kept.cleared().empty());
    EXPECT_TRUE(fs::exists(dir.path / "line.csv"));
  }
  const OutputFolder f(dir.path.string(), EarlierRun::Overwrite);
  for (const char* gone :
       {"summary.json", "line.csv", "reactions.csv", "fields.h5", "fields.xdmf", "m/mesh.msh"})
    EXPECT_FALSE(fs::exists(dir.path / gone)) << gone;
  EXPECT_EQ(read_text(dir.path / "notes.txt"), "mine\n");
  EXPECT_EQ(f.cleared().size(), 6u);
}

TEST(OutputFolderTest, ARunStoppedByInvalidInputIsReplaced) {
  TempDir dir("invalid");
  std::ofstream(dir.path / "summary.json") << R"({"status": "invalid"})";
  const OutputFolder f(dir.path.string(), EarlierRun::Refuse);
  EXPECT_FALSE(fs::exists(dir.path / "summary.json"));
}

}  // namespace
}  // namespace biphasic
