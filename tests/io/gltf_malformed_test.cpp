// Malformed and hostile glTF: each is refused with one line that names the file and the
// accessor, node, skin or animation at fault, never a crash.
#include <cmath>
#include <limits>
#include <string>

#include "io/gltf_reader.h"
#include "io/gltf_test_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::GltfTestFile;
using nlohmann::json;

// The error for `bytes`, checked to be one line that starts with the file's name.
std::string errorOf(const std::string& bytes, const std::string& name = "bad.gltf") {
  Result<Scene> r = parseGltf(bytes, name);
  EXPECT_FALSE(r.ok()) << "accepted";
  if (r.ok()) return {};
  EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
  EXPECT_EQ(r.error().rfind(name + ":", 0), 0u) << r.error();
  return r.error();
}

// A GLB of one JSON chunk (`json` already padded to 4 bytes).
std::string glbOfJson(const std::string& json) {
  auto u32 = [](std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
  };
  std::string out = "glTF";
  u32(out, 2);
  u32(out, static_cast<uint32_t>(20 + json.size()));
  u32(out, static_cast<uint32_t>(json.size()));
  u32(out, 0x4E4F534A);
  return out + json;
}

#define EXPECT_MENTIONS(error, ...)                                                            \
  do {                                                                                         \
    const std::string e_ = (error);                                                            \
    for (const char* part : {__VA_ARGS__}) EXPECT_NE(e_.find(part), std::string::npos) << e_; \
  } while (0)

TEST(GltfMalformed, TruncatedGlb) {
  const std::string glb = test::smallAnimatedFile().glb();
  ASSERT_TRUE(parseGltf(glb, "ok.glb").ok());
  for (size_t cut : {glb.size() - 1, glb.size() / 2, size_t(30), size_t(19), size_t(5)})
    EXPECT_MENTIONS(errorOf(glb.substr(0, cut), "cut.glb"), "truncated");
}

TEST(GltfMalformed, AccessorPastItsBuffer) {
  GltfTestFile f = test::smallAnimatedFile();
  f.doc["accessors"][1]["byteOffset"] = 4;  // 2 VEC3 floats from byte 4 need 28 > 24 bytes
  EXPECT_MENTIONS(errorOf(f.gltf()), "accessor 1", "bufferView");
  GltfTestFile g = test::smallAnimatedFile();
  g.doc["bufferViews"][1]["byteLength"] = 4000;  // the view itself past its buffer
  EXPECT_MENTIONS(errorOf(g.gltf()), "bufferView 1", "buffer 0");
  GltfTestFile h = test::smallAnimatedFile();
  h.doc["accessors"][1]["byteOffset"] = std::numeric_limits<uint64_t>::max() / 2;
  EXPECT_MENTIONS(errorOf(h.gltf()), "accessor 1");
}

TEST(GltfMalformed, WrongTypesAndCounts) {
  GltfTestFile f = test::smallAnimatedFile();
  f.doc["accessors"][1]["type"] = "VEC2";
  EXPECT_MENTIONS(errorOf(f.gltf()), "accessor 1", "VEC3");
  GltfTestFile g = test::smallAnimatedFile();
  g.doc["accessors"][0]["componentType"] = test::kGltfUShort;  // key times must be FLOAT
  EXPECT_MENTIONS(errorOf(g.gltf()), "accessor 0", "FLOAT");
}

TEST(GltfMalformed, WrongSamplerOutputCount) {
  GltfTestFile f = test::smallAnimatedFile();
  f.doc["accessors"][1]["count"] = 1;  // 2 keys need 2 translations
  EXPECT_MENTIONS(errorOf(f.gltf()), "animation 0 sampler 0", "expected 2");
  GltfTestFile g = test::smallAnimatedFile();
  g.doc["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE";  // needs 3 per key
  EXPECT_MENTIONS(errorOf(g.gltf()), "animation 0 sampler 0", "expected 6");
}

TEST(GltfMalformed, KeyTimesNotIncreasing) {
  GltfTestFile f = test::smallAnimatedFile();
  const int times = f.addFloats({0.0f, 0.0f}, "SCALAR");
  f.doc["animations"][0]["samplers"][1]["input"] = times;
  EXPECT_MENTIONS(errorOf(f.gltf()), "animation 0 sampler 1", "not increasing");
}

TEST(GltfMalformed, NanInData) {
  GltfTestFile f = test::smallAnimatedFile();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  f.doc["animations"][0]["samplers"][0]["output"] = f.addFloats({0, 0, 0, 1, nan, 1}, "VEC3");
  EXPECT_MENTIONS(errorOf(f.gltf()), "accessor 3", "finite");
  GltfTestFile g = test::smallAnimatedFile();
  g.doc["animations"][0]["samplers"][0]["output"] = g.addFloats({0, 0, 0, 1, INFINITY, 1}, "VEC3");
  EXPECT_MENTIONS(errorOf(g.glb(), "bad.glb"), "accessor 3", "finite");
}

TEST(GltfMalformed, NodeCycleAndTwoParents) {
  GltfTestFile cycle;
  cycle.addNode({{"children", {1}}});
  cycle.addNode({{"children", {2}}});
  cycle.addNode({{"children", {0}}});
  EXPECT_MENTIONS(errorOf(cycle.gltf()), "cycle");
  GltfTestFile self;
  self.addNode({{"children", {0}}});
  EXPECT_MENTIONS(errorOf(self.gltf()), "node 0", "cycle");
  GltfTestFile twoParents;
  twoParents.addNode({{"children", {2}}});
  twoParents.addNode({{"children", {2}}});
  twoParents.addNode(json::object());
  EXPECT_MENTIONS(errorOf(twoParents.gltf()), "node 2", "two parents", "0", "1");
  GltfTestFile missing;
  missing.addNode({{"children", {5}}});
  EXPECT_MENTIONS(errorOf(missing.gltf()), "node 0", "child 5");
}

GltfTestFile skinnedTriangle(uint8_t joint) {
  GltfTestFile f;
  const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int joints = f.addInts(std::vector<uint8_t>{0, 0, 0, 0, 1, 0, 0, 0, joint, 0, 0, 0}, test::kGltfUByte, "VEC4", 3);
  const int weights = f.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}}}}}}};
  f.addNode({{"children", {1}}});
  f.addNode(json::object());
  f.addNode({{"mesh", 0}, {"skin", 0}});
  f.doc["skins"] = {{{"joints", {0, 1}}}};
  return f;
}

TEST(GltfMalformed, JointIndexOutOfRange) {
  ASSERT_TRUE(parseGltf(skinnedTriangle(1).gltf(), "ok.gltf").ok());
  EXPECT_MENTIONS(errorOf(skinnedTriangle(2).gltf()), "node 2", "joint 2", "skin 0", "2 joints");
  GltfTestFile f = skinnedTriangle(1);
  f.doc["skins"][0]["joints"] = {0, 7};  // a skin joint that is no node
  EXPECT_MENTIONS(errorOf(f.gltf()), "skin 0", "node 7");
  GltfTestFile g = skinnedTriangle(1);
  g.doc["skins"][0]["inverseBindMatrices"] = g.addFloats(std::vector<float>(16, 0.0f), "MAT4");  // 1 for 2 joints
  EXPECT_MENTIONS(errorOf(g.gltf()), "skin 0", "1 matrices for 2 joints");
}

TEST(GltfMalformed, IndicesAndReferencesOutOfRange) {
  GltfTestFile f = skinnedTriangle(1);
  f.doc["meshes"][0]["primitives"][0]["indices"] = f.addInts(std::vector<uint16_t>{0, 1, 3}, test::kGltfUShort, "SCALAR", 3);
  EXPECT_MENTIONS(errorOf(f.gltf()), "mesh 0 primitive 0", "index 3");
  GltfTestFile g = skinnedTriangle(1);
  g.doc["nodes"][2]["mesh"] = 4;
  EXPECT_MENTIONS(errorOf(g.gltf()), "node 2", "mesh 4");
  GltfTestFile h = test::smallAnimatedFile();
  h.doc["animations"][0]["channels"][0]["target"]["node"] = 9;
  EXPECT_MENTIONS(errorOf(h.gltf()), "animation 0 channel 0", "node 9");
  GltfTestFile k = test::smallAnimatedFile();
  k.doc["animations"][0]["samplers"][0]["output"] = 42;
  EXPECT_MENTIONS(errorOf(k.gltf()), "accessor 42");
}

TEST(GltfMalformed, SparseIndicesOutOfRange) {
  GltfTestFile f = test::smallAnimatedFile();
  const int idx = f.addView(std::string("\x05\x00", 2));
  const int val = f.addView(std::string(12, '\0'));
  f.doc["accessors"][1]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", idx}, {"componentType", test::kGltfUShort}}},
                                     {"values", {{"bufferView", val}}}};
  EXPECT_MENTIONS(errorOf(f.gltf()), "accessor 1 sparse", "index 5");
}

TEST(GltfMalformed, LimitsAreCheckedBeforeAllocating) {
  GltfTestFile f = test::smallAnimatedFile();
  // Key times without a bufferView read as zeros: 2e9 of them would need 8 GB.
  f.doc["accessors"][0] = {{"componentType", test::kGltfFloat}, {"type", "SCALAR"}, {"count", 2000000000}};
  EXPECT_MENTIONS(errorOf(f.gltf()), "accessor 0", "limit");
  std::string deep = "{\"asset\":{\"version\":\"2.0\"},\"extras\":";
  for (int i = 0; i < 100000; ++i) deep += '[';
  EXPECT_MENTIONS(errorOf(deep), "nested");
}

TEST(GltfMalformed, NotGltf) {
  EXPECT_MENTIONS(errorOf("hello"), "bad.gltf:");
  EXPECT_MENTIONS(errorOf("[1, 2]"), "bad.gltf:");
  EXPECT_MENTIONS(errorOf(std::string("glTF\x01\0\0\0", 8) + std::string(20, '\0'), "v1.glb"), "version");
  Result<Scene> missing = loadGltf("/no/such/file.glb");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("/no/such/file.glb"), std::string::npos);
}

// Garbage and broken JSON: one readable line naming the file and where the JSON breaks,
// never the JSON library's exception text or the file's raw bytes.
TEST(GltfMalformed, GarbageAndBrokenJsonReadPlainly) {
  auto expectPlain = [](const std::string& e) {
    EXPECT_EQ(e.find("json.exception"), std::string::npos) << e;
    EXPECT_EQ(e.find("parse_error"), std::string::npos) << e;
    for (char c : e) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << int(static_cast<unsigned char>(c)) << " in " << e;
  };
  std::string garbage;
  for (int i = 0; i < 3000; ++i) garbage += static_cast<char>((i * 7919 + 13) % 251 + 1);  // no "glTF" header
  const std::string g = errorOf(garbage, "garbage.glb");
  expectPlain(g);
  EXPECT_MENTIONS(g, "not a glTF file");
  const std::string t = errorOf("hello world {not json", "text.glb");
  expectPlain(t);
  EXPECT_MENTIONS(t, "not a glTF file");

  // A GLB whose JSON chunk has ",," after its first member: the second comma is at 1-based
  // column index + 2 of the first comma.
  std::string text = R"({"asset":{"version":"2.0"},,"nodes":[{"name":"a"}]})";
  const size_t comma = text.find(",,");
  while (text.size() % 4) text += ' ';
  const std::string b = errorOf(glbOfJson(text), "broken.glb");
  expectPlain(b);
  const std::string where = "line 1, column " + std::to_string(comma + 2) + ":";
  EXPECT_MENTIONS(b, "malformed", where.c_str());
  // Text glTF cut short: the break is at the end, after the last byte.
  const std::string cut = R"({"asset":{"version":"2.0"},"nodes":[1,2)";
  const std::string c = errorOf(cut);
  expectPlain(c);
  const std::string end = "line 1, column " + std::to_string(cut.size() + 1) + ":";
  EXPECT_MENTIONS(c, "malformed", end.c_str());
  // A break on the third line is counted in lines.
  const std::string lines = errorOf("{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [}\n}");
  EXPECT_MENTIONS(lines, "line 3, column 13");
}

TEST(GltfMalformed, TooManyNodes) {
  std::string many = "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{}";
  for (int i = 0; i < 70000; ++i) many += ",{}";
  many += "]}";
  EXPECT_MENTIONS(errorOf(many), "70001 nodes", "limit");
}

// tinygltf hands an image's bufferView to the image loader without checking it lies in
// its buffer; ours checks before decoding.
TEST(GltfMalformed, ImageBufferViewPastItsBuffer) {
  GltfTestFile f;
  f.addNode(json::object());
  const int view = f.addView(std::string(8, 'x'));
  f.doc["bufferViews"][view]["byteLength"] = 1 << 20;
  f.doc["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  EXPECT_MENTIONS(errorOf(f.gltf()), "image 0", "bufferView 0", "buffer 0");
}

}  // namespace
}  // namespace kinema
