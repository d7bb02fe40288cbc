#include "io/gltf_test_files.h"

namespace kinema::test {

namespace {
std::string base64(const std::string& in) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t v = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8) | uint8_t(in[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += abc[(v >> s) & 63];
  }
  if (i + 1 == in.size()) {
    const uint32_t v = uint8_t(in[i]) << 16;
    out += abc[(v >> 18) & 63];
    out += abc[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == in.size()) {
    const uint32_t v = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8);
    out += abc[(v >> 18) & 63];
    out += abc[(v >> 12) & 63];
    out += abc[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

void appendU32(std::string& s, uint32_t v) {
  for (int i = 0; i < 4; ++i) s += char((v >> (8 * i)) & 0xff);
}
}  // namespace

GltfTestFile::GltfTestFile() {
  doc["asset"] = {{"version", "2.0"}};
  doc["nodes"] = nlohmann::json::array();
}

int GltfTestFile::addView(const std::string& bytes) {
  const size_t offset = bin.size();
  bin += bytes;
  while (bin.size() % 4) bin += '\0';
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}});
  return static_cast<int>(doc["bufferViews"].size()) - 1;
}

int GltfTestFile::addFloats(const std::vector<float>& values, const char* type) {
  const int n = std::string(type) == "SCALAR" ? 1 : std::string(type) == "VEC2" ? 2 : std::string(type) == "VEC3" ? 3
              : std::string(type) == "VEC4" ? 4 : 16;
  return addInts(values, kGltfFloat, type, static_cast<int>(values.size()) / n);
}

int GltfTestFile::addAccessor(int view, int componentType, const char* type, int count) {
  doc["accessors"].push_back({{"bufferView", view}, {"componentType", componentType}, {"type", type}, {"count", count}});
  return static_cast<int>(doc["accessors"].size()) - 1;
}

int GltfTestFile::addNode(const nlohmann::json& node) {
  doc["nodes"].push_back(node);
  return static_cast<int>(doc["nodes"].size()) - 1;
}

std::string GltfTestFile::gltf() const {
  nlohmann::json d = doc;
  if (!bin.empty())
    d["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
  return d.dump();
}

std::string GltfTestFile::glb() const {
  nlohmann::json d = doc;
  if (!bin.empty()) d["buffers"] = {{{"byteLength", bin.size()}}};
  std::string json = d.dump();
  while (json.size() % 4) json += ' ';
  std::string out = "glTF";
  appendU32(out, 2);
  appendU32(out, static_cast<uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  appendU32(out, static_cast<uint32_t>(json.size()));
  appendU32(out, 0x4E4F534A);
  out += json;
  if (!bin.empty()) {
    appendU32(out, static_cast<uint32_t>(bin.size()));
    appendU32(out, 0x004E4942);
    out += bin;
  }
  return out;
}

GltfTestFile smallAnimatedFile() {
  GltfTestFile f;
  f.addNode({{"name", "root"}, {"children", {1}}, {"translation", {0, 1, 0}}});
  f.addNode({{"name", "tip"}, {"translation", {0, 2, 0}}});
  const int times = f.addFloats({0.0f, 1.0f}, "SCALAR");
  const int moves = f.addFloats({0, 0, 0, 1, 1, 1}, "VEC3");
  const int turns = f.addFloats({0, 0, 0, 1, 0, 0, 1, 0}, "VEC4");  // identity, then 180 degrees about z
  f.doc["animations"] = {{{"name", "move"},
                          {"samplers",
                           {{{"input", times}, {"output", moves}, {"interpolation", "STEP"}},
                            {{"input", times}, {"output", turns}, {"interpolation", "LINEAR"}}}},
                          {"channels",
                           {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}},
                            {{"sampler", 1}, {"target", {{"node", 0}, {"path", "rotation"}}}}}}}};
  return f;
}

}  // namespace kinema::test
