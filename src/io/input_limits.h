#pragma once
#include <cstddef>
#include <string>

namespace kinema {

// Ceilings on what a file may ask Kinema to allocate. Readers check them before
// allocating (or as soon as the count is known), so a hostile or corrupt file fails with
// a message naming the limit instead of exhausting memory. The defaults are far above
// any real character or capture; tests pass smaller ones.
struct InputLimits {
  size_t maxFileBytes = size_t(2) << 30;  // 2 GiB: the whole file is read into memory
  int maxJoints = 1 << 20;                // a 100,000-joint chain is fine; 1M+ is not a rig
  long long maxKeys = 1LL << 28;          // keys in one clip (BVH: frames x channels)
  int maxJsonDepth = 64;                  // .kinema nests 6 deep; JSON parsers recurse
  long long maxAccessorElements = 1LL << 28;  // glTF: elements in one accessor
  int maxNodes = 1 << 20;                 // glTF nodes (each becomes a joint)
};

// "more than the limit of N <what> (InputLimits::<field>)", for one-line errors.
inline std::string limitExceeded(long long found, long long limit, const char* what, const char* field) {
  return std::to_string(found) + " " + what + ", more than the limit of " + std::to_string(limit) +
         " (InputLimits::" + field + ")";
}

}  // namespace kinema
