#include "io/atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace kinema {

std::string writeFileAtomically(const std::string& path, const std::string& contents) {
  std::vector<char> tmp(path.begin(), path.end());
  const char suffix[] = ".tmp-XXXXXX";
  tmp.insert(tmp.end(), suffix, suffix + sizeof(suffix));  // includes the terminating 0
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) return path + ": cannot create a temporary file beside it: " + std::strerror(errno);
  const std::string tmpPath(tmp.data());
  auto failWith = [&](const char* what) {
    const std::string message = path + ": " + what + ": " + std::strerror(errno);
    ::close(fd);
    ::unlink(tmpPath.c_str());
    return message;
  };
  // mkstemp creates 0600; give the file the usual permissions (subject to umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  const char* p = contents.data();
  size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return failWith("write failed");
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) return failWith("flush to disk failed");
  if (::close(fd) != 0) {
    const std::string message = path + ": close failed: " + std::strerror(errno);
    ::unlink(tmpPath.c_str());
    return message;
  }
  if (::rename(tmpPath.c_str(), path.c_str()) != 0) {
    const std::string message = path + ": cannot replace the file: " + std::strerror(errno);
    ::unlink(tmpPath.c_str());
    return message;
  }
  return {};
}

}  // namespace kinema
