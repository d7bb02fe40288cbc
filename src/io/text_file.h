#pragma once
#include <string>
#include <vector>

namespace kinema {

// Reads a whole file; returns an empty string on success or "PATH: reason" on failure.
std::string readTextFile(const std::string& path, std::string& out);

// Splits on \n, \r\n and lone \r; the line ends are dropped.
void splitLines(const std::string& text, std::vector<std::string>& lines);
bool isBlank(const std::string& s);
std::string trim(const std::string& s);

}  // namespace kinema
