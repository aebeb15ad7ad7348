// The folder a run writes into: where it is by default, who may use it, and what happens to an
// earlier run found in it.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace biphasic {

/// A problem with the output folder found before any work (exit status 1): the path is a file,
/// cannot be created or written, is locked by another run, or holds an earlier run.
class OutputFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The default output folder of a case: `results/<case stem>` without overrides, otherwise
/// `results/<case stem>--<key=value,...>` with every character outside [A-Za-z0-9._,=+-]
/// replaced by '_'. A suffix longer than 60 characters is cut to 50 and followed by '~' and
/// 8 hexadecimal digits of a hash of all the overrides, so that different overrides keep
/// different folders.
std::string default_output_folder(const std::string& case_path,
                                  const std::vector<std::string>& overrides);

/// What to do with an earlier run found in the folder (a summary.json).
enum class EarlierRun {
  Refuse,     ///< stop with OutputFolderError (a run that found invalid input is cleared)
  Overwrite,  ///< delete the earlier run's files first (--overwrite)
  Continue,   ///< keep them: the run continues from its checkpoint (--restart)
};

/// Holds a run's output folder for the lifetime of the object. The constructor creates the
/// folder, takes an exclusive flock(2) on `<folder>/.biphasic.lock` (holding the owner's pid),
/// and then deals with an earlier run as `earlier` says. The lock is released when the object
/// is destroyed or the process ends, however it ends. Throws OutputFolderError naming the folder
/// and the cause.
class OutputFolder {
 public:
  OutputFolder(const std::string& path, EarlierRun earlier);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// The files of an earlier run that the constructor deleted (names inside the folder).
  const std::vector<std::string>& cleared() const { return cleared_; }

  /// The files a run writes, as names inside its folder (besides mesh.write_msh).
  static const std::vector<std::string>& run_files();

 private:
  std::filesystem::path path_;
  int lock_fd_ = -1;
  std::vector<std::string> cleared_;
};

}  // namespace biphasic
