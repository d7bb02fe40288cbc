#pragma once
// Hostile files the issue-19 tests build themselves (tests/io/hostile_read_test.cpp and
// tests/editor/hostile_open_e2e_test.cpp): a small valid BVH, a .gltf whose one buffer is
// the file a uri names, and PNGs whose header claims another size.
#include <cstdint>
#include <string>
#include <vector>

#include "io/image.h"

namespace kinema::test::hostile {

// hips (root, 1 m up) and knee, one frame.
inline const char kLegBvh[] =
    "HIERARCHY\nROOT hips\n{\nOFFSET 0 1 0\nCHANNELS 3 Xrotation Yrotation Zrotation\nJOINT knee\n{\nOFFSET 0 -0.5 0\n"
    "CHANNELS 3 Xrotation Yrotation Zrotation\nEnd Site\n{\nOFFSET 0 -0.5 0\n}\n}\n}\nMOTION\nFrames: 1\n"
    "Frame Time: 0.1\n0 0 0 0 0 0\n";

// A .gltf with one triangle whose buffer (36 bytes: three float vec3) is read from `uri`.
inline std::string gltfWithBufferUri(const std::string& uri, int byteLength = 36) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + uri + R"(", "byteLength": )" +
         std::to_string(byteLength) + R"(}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "accessors": [)"
         R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],)"
         R"( "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0, "name": "tri"}],)"
         R"( "scenes": [{"nodes": [0]}], "scene": 0})";
}

// The triangle's 36 bytes.
inline std::string triangleBytes() {
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  return std::string(reinterpret_cast<const char*>(v), sizeof v);
}

// A real PNG of w x h grey pixels whose header then claims `claimW` x `claimH` (stb reads
// the size from the IHDR chunk alone, before decoding).
inline std::string pngClaiming(int w, int h, int claimW, int claimH) {
  std::vector<std::uint8_t> rgba(static_cast<size_t>(w) * h * 4, 200);
  std::string png = encodePng(w, h, rgba.data());
  auto put = [&](size_t at, int v) {
    for (int k = 0; k < 4; ++k) png[at + k] = static_cast<char>((v >> (24 - 8 * k)) & 0xff);
  };
  put(16, claimW);  // 8 signature bytes, the chunk's length and "IHDR", then width and height
  put(20, claimH);
  return png;
}

inline std::string base64(const std::string& bytes) {
  static const char k[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += k[v >> 18];
    out += k[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? k[v & 63] : '=';
  }
  return out;
}

// A .kinema file of one joint and these PNG images.
inline std::string kinemaWithImages(const std::vector<std::string>& pngs) {
  std::string images;
  for (size_t i = 0; i < pngs.size(); ++i)
    images += std::string(i ? ", " : "") + R"({"name": "i)" + std::to_string(i) + R"(", "png": ")" + base64(pngs[i]) + "\"}";
  return R"({"format": "kinema", "version": 1, "skeleton": {"joints": [{"name": "a", "parent": -1}]}, "images": [)" +
         images + "]}";
}

}  // namespace kinema::test::hostile
