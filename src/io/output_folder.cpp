#include "biphasic/io/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace biphasic {

namespace fs = std::filesystem;

namespace {

constexpr const char* kLockName = ".biphasic.lock";

/// 64-bit FNV-1a: a short, stable fingerprint of a text.
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

bool allowed_in_name(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == ',' || c == '=' || c == '+' || c == '-';
}

std::string cause(int error) { return std::strerror(error); }

}  // namespace

std::string default_output_folder(const std::string& case_path,
                                  const std::vector<std::string>& overrides) {
  const std::string stem = fs::path(case_path).stem().string();
  if (overrides.empty()) return (fs::path("results") / stem).string();
  std::string joined;
  for (const std::string& o : overrides) joined += (joined.empty() ? "" : ",") + o;
  std::string suffix = joined;
  for (char& c : suffix)
    if (!allowed_in_name(c)) c = '_';
  constexpr std::size_t kMax = 60, kKept = 50;
  if (suffix.size() > kMax) {
    char hash[16];
    std::snprintf(hash, sizeof hash, "%08llx",
                  static_cast<unsigned long long>(fnv1a(joined) & 0xffffffffULL));
    suffix = suffix.substr(0, kKept) + "~" + hash;
  }
  return (fs::path("results") / (stem + "--" + suffix)).string();
}

const std::vector<std::string>& OutputFolder::run_files() {
  static const std::vector<std::string> files{
      "summary.json",     "line.csv",        "reactions.csv",     "platens.csv",
      "fields.h5",        "fields.xdmf",     "steps.csv",         "checkpoint.bin",
      "summary.json.tmp", "fields.xdmf.tmp", "checkpoint.bin.tmp"};
  return files;
}

OutputFolder::OutputFolder(const std::string& path, EarlierRun earlier)
    : path_(path.empty() ? fs::path(".") : fs::path(path)) {
  const std::string name = path_.string();
  std::error_code ec;
  const fs::file_status status = fs::status(path_, ec);
  if (fs::exists(status) && !fs::is_directory(status))
    throw OutputFolderError("output folder " + name + " is a file, not a folder");
  if (!fs::exists(status)) {
    fs::create_directories(path_, ec);
    if (ec) throw OutputFolderError("cannot create output folder " + name + ": " + ec.message());
  }
  if (::access(name.c_str(), W_OK | X_OK) != 0)
    throw OutputFolderError("output folder " + name + " is not writable: " + cause(errno));

  // Lock first, so that a run still writing here is reported as such, not as an earlier run.
  const std::string lock_path = (path_ / kLockName).string();
  lock_fd_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) {
    throw OutputFolderError("cannot write in output folder " + name + " (creating " + lock_path +
                            "): " + cause(errno));
  }
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    std::string holder;
    char buf[32] = {};
    if (::pread(lock_fd_, buf, sizeof buf - 1, 0) > 0) holder = std::string(buf);
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw OutputFolderError("output folder " + name + " is in use by another run (pid " +
                              (holder.empty() ? std::string("unknown") : holder) +
                              "); wait for it to finish or choose another folder with -o");
    }
    throw OutputFolderError("cannot lock output folder " + name + ": " + cause(error));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(lock_fd_, 0) != 0 ||
      ::pwrite(lock_fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    const int error = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw OutputFolderError("cannot write in output folder " + name + " (" + lock_path +
                            "): " + cause(error));
  }

  const fs::path summary = path_ / "summary.json";
  if (!fs::exists(summary, ec) || earlier == EarlierRun::Continue) return;
  std::string earlier_status = "unknown";
  std::string write_msh;
  try {
    std::ifstream in(summary);
    const nlohmann::json j = nlohmann::json::parse(in);
    earlier_status = j.value("status", "unknown");
    write_msh = j.at("configuration").at("mesh").value("write_msh", "");
  } catch (const std::exception&) {
    // An unreadable summary is still an earlier run.
  }
  // A run stopped by invalid input wrote no results: its folder is reused without asking.
  if (earlier == EarlierRun::Refuse && earlier_status != "invalid") {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw OutputFolderError("output folder " + name +
                            " holds an earlier run (summary.json, status \"" + earlier_status +
                            "\"); pass --overwrite to replace it, --restart " + name +
                            " to continue it, or choose another folder with -o");
  }
  std::vector<std::string> files = run_files();
  const fs::path msh(write_msh);
  if (!write_msh.empty() && msh.is_relative() && msh.extension() == ".msh" &&
      write_msh.find("..") == std::string::npos)
    files.push_back(write_msh);
  for (const std::string& file : files) {
    const fs::path p = path_ / file;
    if (!fs::is_regular_file(fs::symlink_status(p, ec)) &&
        !fs::is_symlink(fs::symlink_status(p, ec)))
      continue;
    if (!fs::remove(p, ec) || ec) {
      ::close(lock_fd_);
      lock_fd_ = -1;
      throw OutputFolderError("cannot remove " + p.string() +
                              " of the earlier run: " + ec.message());
    }
    cleared_.push_back(file);
  }
}

OutputFolder::~OutputFolder() {
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

}  // namespace biphasic
