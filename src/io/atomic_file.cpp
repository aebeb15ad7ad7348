#include "biphasic/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace biphasic {

namespace {

std::string cause(int error) { return std::strerror(error); }

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot create " + tmp + ": " + cause(errno));
  auto fail = [&](const std::string& what, int error) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + what + ": " + cause(error) + " (" +
                             path + " left as it was)");
  };
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  // fsync makes the rename below publish data that is on disk; a file system or device that
  // cannot sync (EINVAL, EROFS) has nothing more to do.
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) fail("fsync", errno);
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": close: " + cause(error) + " (" + path +
                             " left as it was)");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot replace " + path + " by " + tmp + ": " + cause(error));
  }
}

void flush_checked(std::ofstream& out, const std::string& path) {
  errno = 0;
  out.flush();
  if (!out) {
    const int error = errno;
    throw std::runtime_error("cannot write " + path + ": " +
                             (error != 0 ? cause(error) : std::string("stream failure")));
  }
}

}  // namespace biphasic
