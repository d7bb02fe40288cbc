#pragma once
#include <cstddef>

namespace kinema {

// Caps on what a glTF file may ask for, checked before anything is allocated, so that a
// small hostile file cannot make the reader allocate gigabytes or loop for minutes.
// Real assets (the Khronos samples, game characters) stay far below each one.
struct GltfLimits {
  static constexpr size_t kMaxFileBytes = size_t(1) << 30;          // 1 GiB .glb / .gltf
  static constexpr int kMaxJsonDepth = 64;                           // nested [ and {
  static constexpr size_t kMaxNodes = 65536;
  static constexpr size_t kMaxSkinJoints = 65535;                    // joint numbers are uint16
  static constexpr size_t kMaxAccessorElements = size_t(1) << 24;   // 16 M elements
  static constexpr size_t kMaxDecodedValues = size_t(1) << 27;      // 128 M numbers per file
  static constexpr size_t kMaxMorphTargets = 256;
  static constexpr int kMaxImageSide = 16384;
  static constexpr size_t kMaxImagePixels = size_t(1) << 26;        // 64 M pixels per file
};

}  // namespace kinema
