#include "io/text_file.h"

#include <fcntl.h>
#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

namespace kinema {

namespace {

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  if (!S_ISREG(mode)) return "is not a regular file";
  return {};
}

// Files on /proc and /sys claim a size of 0 (or 4096) and are made up as they are read.
std::string pseudoFileSystem(int fd) {
  struct statfs fs {};
  if (::fstatfs(fd, &fs) != 0) return {};
  if (fs.f_type == PROC_SUPER_MAGIC) return "is on /proc, not a regular file";
  if (fs.f_type == SYSFS_MAGIC) return "is on /sys, not a regular file";
  return {};
}

struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Opens `path` for reading only when it is a regular file: stat first (opening a FIFO
// blocks), then open without blocking and check the opened file again (it may have been
// replaced in between).
std::string openRegular(const std::string& path, size_t maxBytes, Descriptor& file, size_t& size) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return path + ": " + std::strerror(errno);
  if (std::string kind = kindOf(st.st_mode); !kind.empty()) return path + ": " + kind;
  file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (file.fd < 0) return path + ": cannot open for reading: " + std::strerror(errno);
  if (::fstat(file.fd, &st) != 0) return path + ": " + std::strerror(errno);
  if (std::string kind = kindOf(st.st_mode); !kind.empty()) return path + ": " + kind;
  if (std::string pseudo = pseudoFileSystem(file.fd); !pseudo.empty()) return path + ": " + pseudo;
  if (static_cast<unsigned long long>(st.st_size) > maxBytes)
    return path + ": the file is " + std::to_string(st.st_size) + " bytes, more than the limit of " +
           std::to_string(maxBytes) + " (InputLimits::maxFileBytes)";
  size = static_cast<size_t>(st.st_size);
  return {};
}

template <class Bytes>
std::string readRegular(const std::string& path, Bytes& out, size_t maxBytes) {
  out.clear();
  Descriptor file;
  size_t size = 0;
  if (std::string e = openRegular(path, maxBytes, file, size); !e.empty()) return e;
  const size_t block = size_t(1) << 16;
  out.reserve(size + std::min(block, maxBytes + 1 - size));  // the one-past check needs no reallocation
  out.resize(size);
  size_t got = 0;
  // Read what fstat promised, then at most one more block: a file that grows past the
  // limit while being read is refused without reading the rest of it.
  while (true) {
    if (got == out.size()) {
      if (got > maxBytes) break;
      out.resize(got + std::min(block, maxBytes + 1 - got));
    }
    const ssize_t n = ::read(file.fd, reinterpret_cast<char*>(&out[0]) + got, out.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      out.clear();
      return path + ": read error: " + std::strerror(errno);
    }
    if (n == 0) break;
    got += static_cast<size_t>(n);
  }
  out.resize(got);
  if (got > maxBytes) {
    out.clear();
    Bytes().swap(out);
    return path + ": more than " + std::to_string(maxBytes) + " bytes, the limit (InputLimits::maxFileBytes)";
  }
  return {};
}

}  // namespace

std::string readTextFile(const std::string& path, std::string& out, size_t maxBytes) {
  return readRegular(path, out, maxBytes);
}

std::string readFileBytes(const std::string& path, std::vector<unsigned char>& out, size_t maxBytes) {
  return readRegular(path, out, maxBytes);
}

std::string notARegularFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::strerror(errno);
  if (std::string kind = kindOf(st.st_mode); !kind.empty()) return kind;
  struct statfs fs {};
  if (::statfs(path.c_str(), &fs) == 0 && (fs.f_type == PROC_SUPER_MAGIC || fs.f_type == SYSFS_MAGIC))
    return fs.f_type == PROC_SUPER_MAGIC ? "is on /proc, not a regular file" : "is on /sys, not a regular file";
  return {};
}

}  // namespace kinema
