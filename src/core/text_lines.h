#pragma once
// Plain text helpers shared by every text reader (line splitting, trimming, UTF-8).
#include <string>
#include <vector>

namespace kinema {

// Splits on \n, \r\n and lone \r; the line ends are dropped.
void splitLines(const std::string& text, std::vector<std::string>& lines);
bool isBlank(const std::string& s);
std::string trim(const std::string& s);

// True when `s` is well-formed UTF-8 (JSON and glTF text must be).
bool isValidUtf8(const std::string& s);
// Text from older tools (BVH exporters) is often Latin-1: returns `s` unchanged when it is
// valid UTF-8, else reads each byte as a Latin-1 character and encodes it as UTF-8.
std::string toUtf8(const std::string& s);

}  // namespace kinema
