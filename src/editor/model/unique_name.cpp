#include "editor/model/unique_name.h"

#include <cctype>
#include <cstdio>

namespace kinema {

std::string uniqueName(const std::string& base, const std::function<bool(const std::string&)>& taken) {
  std::string stem = base;
  const size_t n = stem.size();
  if (n > 4 && stem[n - 4] == '.' && std::isdigit(static_cast<unsigned char>(stem[n - 3])) &&
      std::isdigit(static_cast<unsigned char>(stem[n - 2])) && std::isdigit(static_cast<unsigned char>(stem[n - 1])))
    stem.resize(n - 4);
  if (!taken(stem)) return stem;
  for (int i = 1;; ++i) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, ".%03d", i);
    if (!taken(stem + suffix)) return stem + suffix;
  }
}

}  // namespace kinema
