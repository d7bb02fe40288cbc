#pragma once
#include <cstddef>
#include <string>

namespace kinema {

// Ceilings on what a file may ask Kinema to allocate. Readers check them before
// allocating (or as soon as the count is known), so a hostile or corrupt file fails with
// a message naming the limit instead of exhausting memory. The defaults are far above
// any real character or capture; tests pass smaller ones. glTF has its own, tighter caps
// (io/gltf_limits.h: binary buffers make huge claims cheap).
struct InputLimits {
  size_t maxFileBytes = size_t(2) << 30;  // 2 GiB: the whole file is read into memory
  int maxJoints = 1 << 20;                // a 100,000-joint chain is fine; 1M+ is not a rig
  long long maxKeys = 1LL << 28;          // keys in one clip (BVH: frames x channels)
  int maxJsonDepth = 64;                  // .kinema nests 6 deep; JSON parsers recurse
  // Memory a file may make Kinema use, counted before it is allocated, so that no input
  // takes more than 4 x its size + 256 MB in all (docs/cli.md, "Input limits"):
  // the parsed JSON tree of a .kinema file at most 2 x the text's size + this,
  size_t jsonTreeBytesOverFileSize = size_t(64) << 20;
  // decoded images (RGBA, 4 bytes a pixel) of one file together at most the file's size
  // (with its external buffers and images) + this, checked from each image's header.
  size_t imageBytesOverFileSize = size_t(64) << 20;
  // glTF buffer and image uris may name files outside the glTF file's folder and its
  // sub-folders (--allow-outside-paths). Devices, FIFOs, sockets and /proc stay refused.
  bool allowOutsidePaths = false;
};

// The byte budgets above for a file of `fileBytes` bytes.
inline size_t jsonTreeBudgetBytes(size_t fileBytes, const InputLimits& limits) {
  return 2 * fileBytes + limits.jsonTreeBytesOverFileSize;
}
inline size_t imageBudgetBytes(size_t fileBytes, const InputLimits& limits) {
  return fileBytes + limits.imageBytesOverFileSize;
}

// "more than the limit of N <what> (InputLimits::<field>)", for one-line errors.
inline std::string limitExceeded(long long found, long long limit, const char* what, const char* field) {
  return std::to_string(found) + " " + what + ", more than the limit of " + std::to_string(limit) +
         " (InputLimits::" + field + ")";
}

}  // namespace kinema
