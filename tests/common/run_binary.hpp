// Running the biphasic binary from end-to-end tests, and the scratch files they use. Needs the
// compile definition BIPHASIC_BINARY (set for every test in tests/CMakeLists.txt).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace biphasic::e2e {

/// What a run of the binary gave: its exit status (−1 if it did not exit normally) and its
/// standard output and error, interleaved.
struct Result {
  int status;
  std::string output;  // stdout and stderr
};

/// Runs BIPHASIC_BINARY with `args` (through the shell). `env` ("NAME=value ...") is set for
/// the command only; `cwd`, if given, is its working folder.
inline Result run(const std::string& args, const std::string& env = "",
                  const std::filesystem::path& cwd = {}) {
  const std::string cmd = (cwd.empty() ? "" : "cd " + cwd.string() + " && ") +
                          (env.empty() ? "" : "env " + env + " ") + std::string(BIPHASIC_BINARY) +
                          " " + args + " 2>&1";
  Result r{-1, ""};
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

/// The folder `name`_<pid> in the temporary directory, created if missing (kept afterwards).
inline std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` to `path` (replacing the file) and returns `path`.
inline std::filesystem::path write_text(const std::filesystem::path& path,
                                        const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

/// The whole content of the file at `path` ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A fresh folder `name`_<pid> in the temporary directory for one test: emptied when made,
/// removed with its content when destroyed.
struct FreshDir {
  explicit FreshDir(const std::string& name)
      : dir(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~FreshDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  FreshDir(const FreshDir&) = delete;
  FreshDir& operator=(const FreshDir&) = delete;
  std::filesystem::path dir;
};

}  // namespace biphasic::e2e
