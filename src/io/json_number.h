#pragma once
#include <charconv>
#include <cstdlib>
#include <string>

namespace kinema {

// The double whose shortest decimal form is the shortest form of `f`: JSON then shows
// 0.1 instead of 0.10000000149011612, and reading it back as float gives `f` exactly.
inline double jsonFloat(float f) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf) - 1, f);
  *r.ptr = '\0';
  return std::strtod(buf, nullptr);
}

}  // namespace kinema
