#pragma once
#include <cstddef>
#include <string>
#include <vector>

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

// Splits on \n, \r\n and lone \r; the line ends are dropped.
void splitLines(const std::string& text, std::vector<std::string>& lines);
bool isBlank(const std::string& s);
std::string trim(const std::string& s);

}  // namespace kinema

namespace kinema {

// True when `s` is well-formed UTF-8 (JSON and glTF text must be).
bool isValidUtf8(const std::string& s);
// Text from older tools (BVH exporters) is often Latin-1: returns `s` unchanged when it is
// valid UTF-8, else reads each byte as a Latin-1 character and encodes it as UTF-8.
std::string toUtf8(const std::string& s);

}  // namespace kinema
