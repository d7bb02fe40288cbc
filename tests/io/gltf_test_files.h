#pragma once
// Builds small glTF files inside tests: a JSON document plus one binary buffer, written
// as .gltf (buffer as a base64 data URI) or .glb. Nothing here uses Kinema's reader.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace kinema::test {

constexpr int kGltfByte = 5120, kGltfUByte = 5121, kGltfShort = 5122, kGltfUShort = 5123, kGltfUInt = 5125,
              kGltfFloat = 5126;

struct GltfTestFile {
  nlohmann::json doc;
  std::string bin;

  GltfTestFile();
  // Appends raw bytes (padded to 4) as a new bufferView; returns its index.
  int addView(const std::string& bytes);
  // A tightly packed accessor over a new bufferView; `type` "SCALAR", "VEC3", ...
  int addFloats(const std::vector<float>& values, const char* type);
  template <class T>
  int addInts(const std::vector<T>& values, int componentType, const char* type, int count) {
    std::string bytes(values.size() * sizeof(T), '\0');
    std::memcpy(bytes.data(), values.data(), bytes.size());
    return addAccessor(addView(bytes), componentType, type, count);
  }
  int addAccessor(int view, int componentType, const char* type, int count);
  int addNode(const nlohmann::json& node);

  std::string gltf() const;  // the JSON text, buffer embedded
  std::string glb() const;   // GLB container
};

// A one-joint-per-node file with a 2-key animation: node 0 (translation STEP, rotation and
// scale LINEAR) with child node 1; used by several tests as a valid starting point.
GltfTestFile smallAnimatedFile();

}  // namespace kinema::test
