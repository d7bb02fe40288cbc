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

void splitLines(const std::string& text, std::vector<std::string>& lines) {
  lines.clear();
  size_t start = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || text[i] == '\r') {
      lines.emplace_back(text, start, i - start);
      if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < text.size()) lines.emplace_back(text, start, text.size() - start);
}

bool isBlank(const std::string& s) { return s.find_first_not_of(" \t\f\v") == std::string::npos; }

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\f\v");
  if (b == std::string::npos) return {};
  const size_t e = s.find_last_not_of(" \t\f\v");
  return s.substr(b, e - b + 1);
}

}  // namespace kinema

namespace kinema {

bool isValidUtf8(const std::string& s) {
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  const auto* end = p + s.size();
  while (p < end) {
    const unsigned char c = *p;
    int extra;
    unsigned min;
    unsigned cp;
    if (c < 0x80) {
      ++p;
      continue;
    } else if ((c & 0xE0) == 0xC0) {
      extra = 1, min = 0x80, cp = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
      extra = 2, min = 0x800, cp = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
      extra = 3, min = 0x10000, cp = c & 0x07;
    } else {
      return false;
    }
    if (end - p <= extra) return false;
    for (int k = 1; k <= extra; ++k) {
      if ((p[k] & 0xC0) != 0x80) return false;
      cp = (cp << 6) | (p[k] & 0x3F);
    }
    // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8.
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    p += extra + 1;
  }
  return true;
}

std::string toUtf8(const std::string& s) {
  if (isValidUtf8(s)) return s;
  std::string out;
  out.reserve(s.size() * 2);
  for (unsigned char c : s) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

}  // namespace kinema
