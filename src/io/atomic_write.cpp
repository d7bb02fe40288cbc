#include "io/atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace kinema {

namespace {

// A save through a symbolic link replaces the file it points to, not the link.
std::string resolveLinks(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
  char* real = ::realpath(path.c_str(), nullptr);
  if (!real) return path;  // a dangling link: replace the link itself
  std::string out(real);
  std::free(real);
  return out;
}

// Flushes the rename itself to disk (the folder's entry), best effort.
void syncFolderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

std::string writeFileAtomically(const std::string& requested, const std::string& contents) {
  const std::string path = resolveLinks(requested);
  std::vector<char> tmp(path.begin(), path.end());
  const char suffix[] = ".tmp-XXXXXX";
  tmp.insert(tmp.end(), suffix, suffix + sizeof(suffix));  // includes the terminating 0
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) return requested + ": cannot create a temporary file beside it: " + std::strerror(errno);
  const std::string tmpPath(tmp.data());
  auto failWith = [&](const char* what) {
    const std::string message = requested + ": " + what + ": " + std::strerror(errno);
    ::close(fd);
    ::unlink(tmpPath.c_str());
    return message;
  };
  // mkstemp creates 0600: keep the replaced file's permissions, or use the usual ones.
  struct stat old {};
  if (::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
    ::fchmod(fd, old.st_mode & 07777);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
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
    const std::string message = requested + ": close failed: " + std::strerror(errno);
    ::unlink(tmpPath.c_str());
    return message;
  }
  if (::rename(tmpPath.c_str(), path.c_str()) != 0) {
    const std::string message = requested + ": cannot replace the file: " + std::strerror(errno);
    ::unlink(tmpPath.c_str());
    return message;
  }
  syncFolderOf(path);
  return {};
}

}  // namespace kinema
