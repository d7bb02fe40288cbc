#include "io/text_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace kinema {

std::string readTextFile(const std::string& path, std::string& out) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return path + ": " + std::strerror(errno);
  if (S_ISDIR(st.st_mode)) return path + ": is a directory, not a file";
  std::ifstream in(path, std::ios::binary);
  if (!in) return path + ": cannot open for reading";
  out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return path + ": read error";
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
