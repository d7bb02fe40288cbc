#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/text_lines.h"  // splitLines, trim, UTF-8: text helpers the readers share

namespace kinema {

// Reads a whole file; returns an empty string on success or "PATH: reason" on failure.
// Only regular files are read: FIFOs, devices, sockets and files on /proc or /sys are
// refused before they are opened for reading (a FIFO would block, /dev/zero never ends).
// Files larger than maxBytes are refused before anything is read, and the read stops one
// block past the limit should the file grow meanwhile.
std::string readTextFile(const std::string& path, std::string& out, size_t maxBytes = size_t(2) << 30);
// The same into bytes (glTF buffers and images).
std::string readFileBytes(const std::string& path, std::vector<unsigned char>& out, size_t maxBytes);

// "" when `path` names a regular file Kinema may read; otherwise why not, without the path
// ("is a FIFO (named pipe), not a regular file", "is on /proc, not a regular file", ...).
std::string notARegularFile(const std::string& path);

}  // namespace kinema
