#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/message_text.h"

namespace tinygltf {
class Model;
}

namespace kinema {

// What the import pieces share while reading one glTF file: the parsed model, the file's
// name for messages, how much has been decoded (against GltfLimits::kMaxDecodedValues)
// and the warnings collected so far.
struct GltfContext {
  const tinygltf::Model& model;
  std::string file;
  size_t decodedValues = 0;
  std::vector<std::string> warnings;
  // Bytes of decoded images still allowed (InputLimits::imageBytesOverFileSize: the file's
  // size, external files included, + that many bytes).
  size_t imageBytesLeft = 0;
  size_t imageBytesOverFileSize = 0;

  // "FILE: WHAT": the one-line error every check returns.
  std::string error(const std::string& what) const { return oneLineMessage(file + ": " + what); }
  // Adds a warning once (the same drop reported by several primitives is said once).
  void warn(const std::string& what);
};

// Component types an accessor use accepts (bit masks of glTF componentType codes).
enum GltfComponentMask : unsigned {
  kCompByte = 1u << 0,
  kCompUByte = 1u << 1,
  kCompShort = 1u << 2,
  kCompUShort = 1u << 3,
  kCompUInt = 1u << 4,
  kCompFloat = 1u << 5,
};

// Reads accessor `index` as numbers after checking everything tinygltf leaves to us:
// the index, element type (`components`: 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4, 16 MAT4),
// component type against `allowed`, count (>= 1, capped), the bufferView and buffer
// bounds (offset + stride * (count - 1) + element size), the stride, sparse substitution
// (indices in range and increasing) and finite floats. Integer components of a
// `normalized` accessor become [0, 1] / [-1, 1] as glTF defines. `use` names the
// accessor's role in messages ("mesh 0 primitive 1 POSITION"). Returns "" or the error.
std::string readFloatAccessor(GltfContext& ctx, int index, int components, unsigned allowed,
                              const std::string& use, std::vector<float>& out);

// The same for integer data (indices, JOINTS_n): unsigned, non-normalised components.
std::string readUintAccessor(GltfContext& ctx, int index, int components, unsigned allowed,
                             const std::string& use, std::vector<uint32_t>& out);

// The element count of accessor `index` (0 when the index is out of range).
size_t accessorCount(const GltfContext& ctx, int index);

}  // namespace kinema
