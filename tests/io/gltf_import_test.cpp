// glTF import on small files the tests write themselves (gltf_test_files.h): cubic
// splines with hand-computed midpoints, STEP, matrices, names, strips and fans, skin
// influences, sparse accessors, morph targets, warnings.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "io/gltf_reader.h"
#include "io/gltf_test_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::GltfTestFile;
using nlohmann::json;

Scene parsed(const GltfTestFile& f, bool binary = false) {
  Result<Scene> r = parseGltf(binary ? f.glb() : f.gltf(), binary ? "test.glb" : "test.gltf");
  EXPECT_TRUE(r.ok()) << r.error();
  return r.ok() ? std::move(r).value() : Scene{};
}

glm::quat quatOf(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

// Two keys 2 s apart. Translation: v0 = 0, out-tangent b0 = (1,0,0)/s, v1 = (1,2,3),
// in-tangent a1 = (0,0,-3)/s. glTF: p(u) = h00 v0 + h10 dt b0 + h01 v1 + h11 dt a1 with
// dt = 2. At u = 1/2: h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8, so
// p = (0.25,0,0) + (0.5,1,1.5) + (0,0,0.75) = (0.75, 1, 2.25).
// Rotation: v0 = identity (0,0,0,1), b0 = (0,0,0.5,0)/s, v1 = (0,0,1,0) (180 deg about z),
// a1 = 0. At u = 1/2: (0,0,0.5,0.5) + 1/8 * 2 * (0,0,0.5,0) = (0,0,0.625,0.5), normalised
// (0,0,0.780868809,0.624695048). At u = 1/4: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625,
// so (0,0,0.140625+0.15625,0.84375) = (0,0,0.296875,0.84375) before normalising.
GltfTestFile cubicFile() {
  GltfTestFile f;
  f.addNode({{"name", "mover"}});
  const int times = f.addFloats({0.0f, 2.0f}, "SCALAR");
  // Per key: in-tangent, value, out-tangent (the first in and last out are ignored).
  const int moves = f.addFloats({9, 9, 9, 0, 0, 0, 1, 0, 0,  //
                                 0, 0, -3, 1, 2, 3, 9, 9, 9},
                                "VEC3");
  const int turns = f.addFloats({9, 9, 9, 9, 0, 0, 0, 1, 0, 0, 0.5f, 0,  //
                                 0, 0, 0, 0, 0, 0, 1, 0, 9, 9, 9, 9},
                                "VEC4");
  f.doc["animations"] = {{{"samplers",
                           {{{"input", times}, {"output", moves}, {"interpolation", "CUBICSPLINE"}},
                            {{"input", times}, {"output", turns}, {"interpolation", "CUBICSPLINE"}}}},
                          {"channels",
                           {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}},
                            {{"sampler", 1}, {"target", {{"node", 0}, {"path", "rotation"}}}}}}}};
  return f;
}

TEST(GltfImport, CubicSplineMidpointsMatchHandComputation) {
  for (bool binary : {false, true}) {
    const Scene s = parsed(cubicFile(), binary);
    ASSERT_EQ(s.clips.size(), 1u);
    ASSERT_EQ(s.clips[0].channels.size(), 2u);
    const Channel& move = s.clips[0].channels[0];
    const Channel& turn = s.clips[0].channels[1];
    ASSERT_EQ(move.keys.size(), 2u);
    EXPECT_EQ(move.keys[0].interpolation, Interpolation::Hermite);
    EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(move, 1.0f)), glm::vec3(0.75f, 1.0f, 2.25f), 1e-6f);
    EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(move, 0.0f)), glm::vec3(0.0f), 1e-7f);
    EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(move, 2.0f)), glm::vec3(1, 2, 3), 1e-7f);
    EXPECT_SAME_ROTATION(quatOf(sampleChannel(turn, 1.0f)), glm::quat(0.624695048f, 0, 0, 0.780868809f), 1e-6f);
    const float n = std::sqrt(0.296875f * 0.296875f + 0.84375f * 0.84375f);
    EXPECT_SAME_ROTATION(quatOf(sampleChannel(turn, 0.5f)), glm::quat(0.84375f / n, 0, 0, 0.296875f / n), 1e-6f);
    // The world transform follows: the node is a root.
    Pose pose = Pose::rest(s.skeleton);
    sampleClip(s.clips[0], 1.0f, pose);
    EXPECT_VEC3_NEAR(glm::vec3(computeWorld(s.skeleton, pose)[0][3]), glm::vec3(0.75f, 1.0f, 2.25f), 1e-6f);
  }
}

TEST(GltfImport, CubicSplineWeightsUseTheTargetsLayout) {
  GltfTestFile f;
  const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int d0 = f.addFloats({1, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
  const int d1 = f.addFloats({0, 1, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pos}}}, {"targets", {{{"POSITION", d0}}, {{"POSITION", d1}}}}}}},
                      {"weights", {0.5, 0.25}},
                      {"extras", {{"targetNames", {"smile", "blink"}}}}}};
  f.addNode({{"mesh", 0}});
  const int times = f.addFloats({0.0f, 1.0f}, "SCALAR");
  // Per key: in-tangents (2), values (2), out-tangents (2). Target 0: 0 -> 1, zero
  // tangents: at u = 1/2 it is 1/2. Target 1: 1 -> 1 with out-tangent 2/s at key 0:
  // 1 + h10 * dt * 2 = 1 + 1/8 * 1 * 2 = 1.25.
  const int out = f.addFloats({7, 7, 0, 1, 0, 2, /**/ 0, 0, 1, 1, 7, 7}, "SCALAR");
  f.doc["animations"] = {{{"samplers", {{{"input", times}, {"output", out}, {"interpolation", "CUBICSPLINE"}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}};
  const Scene s = parsed(f);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].morphWeights, (std::vector<float>{0.5f, 0.25f}));
  EXPECT_EQ(s.meshes[0].targetNames, (std::vector<std::string>{"smile", "blink"}));
  EXPECT_VEC3_NEAR(s.meshes[0].primitives[0].targets[1].positionDeltas[0], glm::vec3(0, 1, 0), 0.0f);
  ASSERT_EQ(s.clips[0].channels.size(), 2u);
  EXPECT_EQ(s.clips[0].channels[1].property, "weights/1");
  EXPECT_NEAR(sampleChannel(s.clips[0].channels[0], 0.5f).x, 0.5f, 1e-6f);
  EXPECT_NEAR(sampleChannel(s.clips[0].channels[1], 0.5f).x, 1.25f, 1e-6f);
}

TEST(GltfImport, StepHoldsAndLinearRotationTakesTheShortArc) {
  const Scene s = parsed(test::smallAnimatedFile());
  ASSERT_EQ(s.clips.size(), 1u);
  EXPECT_EQ(s.clips[0].name, "move");
  // Keys whole seconds apart lie on many grids: the smallest common rate's, 24 fps.
  EXPECT_EQ(s.clips[0].frameTime, 1.0 / 24.0);
  const Channel& move = s.clips[0].channels[0];
  EXPECT_EQ(move.interpolation, Interpolation::Step);
  EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(move, 0.999f)), glm::vec3(0.0f), 0.0f);
  EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(move, 1.0f)), glm::vec3(1.0f), 0.0f);
  // Identity to 180 deg about z: halfway is 90 deg about z.
  EXPECT_SAME_ROTATION(quatOf(sampleChannel(s.clips[0].channels[1], 0.5f)),
                       glm::quat(std::sqrt(0.5f), 0, 0, std::sqrt(0.5f)), 1e-6f);
  // Node 1 ("tip") is at (0, 2, 0) below node 0: at t = 0.5 node 0 is at the origin
  // (STEP) turned 90 deg about z, so the tip is at (-2, 0, 0).
  Pose pose = Pose::rest(s.skeleton);
  sampleClip(s.clips[0], 0.5f, pose);
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, pose);
  EXPECT_VEC3_NEAR(glm::vec3(world[1][3]), glm::vec3(-2.0f, 0.0f, 0.0f), 1e-6f);
}

// Keys and node rotations far from unit length normalise to the same rotation as their unit
// versions: a plain length in float overflows beyond 1e19, and the fuzzer's keys of 1e36 came
// out as zero quaternions that the .kinema reader then refused.
TEST(GltfImport, HugeAndTinyRotationsNormaliseWithoutOverflow) {
  GltfTestFile f;
  const float h = std::sqrt(0.5f);
  f.addNode({{"name", "root"}, {"rotation", {0.0, 0.0, 3e37 * h, 3e37 * h}}});  // 90 deg about z, huge
  const int times = f.addFloats({0.0f, 1.0f}, "SCALAR");
  const int keys = f.addFloats({0.0f, 0.0f, 2e36f * h, 2e36f * h, 1e-40f, 0.0f, 0.0f, 0.0f}, "VEC4");
  f.doc["animations"] = {{{"samplers", {{{"input", times}, {"output", keys}, {"interpolation", "LINEAR"}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}}}}}};
  const Scene s = parsed(f);
  const glm::quat zQuarter(h, 0.0f, 0.0f, h);
  EXPECT_SAME_ROTATION(s.skeleton.rest[0].rotation, zQuarter, 1e-6f);
  ASSERT_EQ(s.clips.size(), 1u);
  EXPECT_SAME_ROTATION(quatOf(sampleChannel(s.clips[0].channels[0], 0.0f)), zQuarter, 1e-6f);
  // A denormal key along x is a half turn about x.
  EXPECT_SAME_ROTATION(quatOf(sampleChannel(s.clips[0].channels[0], 1.0f)), glm::quat(0.0f, 1.0f, 0.0f, 0.0f), 1e-6f);
}

TEST(GltfImport, SkeletonIsParentFirstWithNodeMap) {
  GltfTestFile f;
  f.addNode({{"name", "hand"}, {"translation", {1, 0, 0}}});      // 0: child of 2
  f.addNode({{"name", "root"}, {"children", {2}}});                // 1
  f.addNode({{"name", "arm"}, {"children", {0}}, {"translation", {0, 1, 0}}});  // 2: child of 1
  f.addNode({{"name", "loose"}});                                  // 3: another root
  const Scene s = parsed(f);
  ASSERT_EQ(s.skeleton.size(), 4);
  EXPECT_EQ(s.skeleton.validate(), "");
  for (int j = 0; j < 4; ++j) {
    const int p = s.skeleton.parents[j];
    EXPECT_LT(p, j);
    if (p >= 0) {  // the node graph's parent relation survives the reordering
      const json& kids = f.doc["nodes"][s.nodeOfJoint[p]]["children"];
      EXPECT_NE(std::find(kids.begin(), kids.end(), s.nodeOfJoint[j]), kids.end());
    }
  }
  const Pose pose = Pose::rest(s.skeleton);
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, pose);
  for (int j = 0; j < 4; ++j) {
    if (s.nodeOfJoint[j] == 0) {
      EXPECT_VEC3_NEAR(glm::vec3(world[j][3]), glm::vec3(1, 1, 0), 1e-7f);
    }
  }
}

TEST(GltfImport, NamesAreMadeUniqueAndTheFileNamesKept) {
  GltfTestFile f;
  f.addNode({{"name", "bone"}});
  f.addNode({{"name", "bone"}});
  f.addNode(json::object());
  f.addNode({{"name", "node_2"}});
  const Scene s = parsed(f);
  EXPECT_EQ(s.skeleton.validate(), "");  // unique
  EXPECT_EQ(s.nodeNames, (std::vector<std::string>{"bone", "bone", "", "node_2"}));
  EXPECT_NE(s.skeleton.find("bone"), -1);
  EXPECT_NE(s.skeleton.find("node_2"), -1);
  EXPECT_EQ(s.skeleton.names.size(), 4u);
}

TEST(GltfImport, MatricesAreDecomposedAndShearIsRefused) {
  GltfTestFile f;
  // T(1,2,3) * Rz(90 deg) * S(2,3,4), column-major: columns Rz*S = (0,2,0), (-3,0,0), (0,0,4).
  f.addNode({{"matrix", {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1}}});
  // A mirror: scale (-1, 1, 1).
  f.addNode({{"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  const Scene s = parsed(f);
  const Transform& t = s.skeleton.rest[0];
  EXPECT_VEC3_NEAR(t.translation, glm::vec3(1, 2, 3), 1e-6f);
  EXPECT_VEC3_NEAR(t.scale, glm::vec3(2, 3, 4), 1e-6f);
  EXPECT_SAME_ROTATION(t.rotation, glm::quat(std::sqrt(0.5f), 0, 0, std::sqrt(0.5f)), 1e-6f);
  const glm::mat4 m = s.skeleton.rest[1].toMatrix();
  EXPECT_NEAR(m[0][0], -1.0f, 1e-6f);
  EXPECT_NEAR(m[1][1], 1.0f, 1e-6f);

  GltfTestFile shear;
  shear.addNode(json::object());
  shear.addNode({{"matrix", {1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  Result<Scene> r = parseGltf(shear.gltf(), "shear.gltf");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("node 1"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("shear"), std::string::npos) << r.error();
  GltfTestFile flat;
  flat.addNode({{"matrix", {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  r = parseGltf(flat.gltf(), "flat.gltf");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("not invertible"), std::string::npos) << r.error();
}

// Four vertices as a strip and as a fan, with and without indices.
TEST(GltfImport, StripsAndFansBecomeTriangleLists) {
  GltfTestFile f;
  const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3");
  const int idx = f.addInts(std::vector<uint16_t>{3, 2, 1, 0}, test::kGltfUShort, "SCALAR", 4);
  f.doc["meshes"] = {{{"primitives",
                       {{{"attributes", {{"POSITION", pos}}}, {"mode", 5}},
                        {{"attributes", {{"POSITION", pos}}}, {"mode", 6}, {"indices", idx}},
                        {{"attributes", {{"POSITION", pos}}}},
                        {{"attributes", {{"POSITION", pos}}}, {"mode", 1}},
                        {{"attributes", {{"POSITION", pos}}}, {"mode", 0}}}}}};
  f.addNode({{"mesh", 0}});
  const Scene s = parsed(f);
  ASSERT_EQ(s.meshes[0].primitives.size(), 4u);  // the lines primitive is dropped...
  // ...and the points are kept as vertices without triangles.
  EXPECT_EQ(s.meshes[0].primitives[3].positions.size(), 4u);
  EXPECT_TRUE(s.meshes[0].primitives[3].indices.empty());
  EXPECT_EQ(s.meshes[0].primitives[0].indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(s.meshes[0].primitives[1].indices, (std::vector<uint32_t>{2, 1, 3, 1, 0, 3}));
  EXPECT_EQ(s.meshes[0].primitives[2].indices, (std::vector<uint32_t>{0, 1, 2}));  // 4th vertex: no whole triangle
  bool warned = false;  // ...and reported
  for (const std::string& w : s.warnings) warned |= w.find("lines are not kept") != std::string::npos;
  EXPECT_TRUE(warned);
  ASSERT_EQ(s.meshInstances.size(), 1u);
}

// Three JOINTS/WEIGHTS sets (12 influences): the 8 largest kept, largest first, summing to 1.
TEST(GltfImport, InfluencesKeepTheEightLargestRenormalised) {
  GltfTestFile f;
  const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  json attributes = {{"POSITION", pos}};
  for (int set = 0; set < 3; ++set) {
    std::vector<uint8_t> joints;
    std::vector<uint8_t> weights;  // normalised bytes: w / 255
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 4; ++k) {
        joints.push_back(static_cast<uint8_t>(set * 4 + k));
        weights.push_back(static_cast<uint8_t>(v == 0 ? 10 * (set * 4 + k + 1) : (set == 0 && k == 0 ? 255 : 0)));
      }
    attributes["JOINTS_" + std::to_string(set)] = f.addInts(joints, test::kGltfUByte, "VEC4", 3);
    const int w = f.addInts(weights, test::kGltfUByte, "VEC4", 3);
    f.doc["accessors"][w]["normalized"] = true;
    attributes["WEIGHTS_" + std::to_string(set)] = w;
  }
  f.doc["meshes"] = {{{"primitives", {{{"attributes", attributes}}}}}};
  std::vector<int> joints;
  for (int j = 0; j < 12; ++j) joints.push_back(f.addNode(json::object()));
  const int skinned = f.addNode({{"mesh", 0}, {"skin", 0}});
  (void)skinned;
  f.doc["skins"] = {{{"joints", joints}}};
  const Scene s = parsed(f);
  const MeshPrimitive& p = s.meshes[0].primitives[0];
  ASSERT_TRUE(p.skinned());
  // Vertex 0: weights 10, 20, ..., 120 on joints 0..11; kept: joints 11..4 with
  // 120..50, sum 680.
  for (int k = 0; k < kMaxInfluences; ++k) {
    EXPECT_EQ(p.influenceJoints[k], 11 - k);
    EXPECT_NEAR(p.influenceWeights[k], (120.0f - 10.0f * k) / 680.0f, 1e-6f);
  }
  EXPECT_EQ(p.influenceJoints[kMaxInfluences], 0);  // vertex 1: joint 0 alone, weight 1
  EXPECT_NEAR(p.influenceWeights[kMaxInfluences], 1.0f, 1e-7f);
  EXPECT_NEAR(p.influenceWeights[kMaxInfluences + 1], 0.0f, 0.0f);
  // Skin: identity inverse bind matrices when the file gives none.
  ASSERT_EQ(s.skins.size(), 1u);
  EXPECT_EQ(s.skins[0].inverseBind[5], glm::mat4(1.0f));
}

TEST(GltfImport, SparseAccessorsAreApplied) {
  GltfTestFile f;
  const int base = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int idxView = f.addView(std::string("\x02\x00", 2));
  std::string values(12, '\0');
  const float v[3] = {5, 6, 7};
  std::memcpy(values.data(), v, 12);
  const int valView = f.addView(values);
  f.doc["accessors"][base]["sparse"] = {{"count", 1},
                                        {"indices", {{"bufferView", idxView}, {"componentType", test::kGltfUShort}}},
                                        {"values", {{"bufferView", valView}}}};
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", base}}}}}}}};
  f.addNode({{"mesh", 0}});
  const Scene s = parsed(f);
  EXPECT_VEC3_NEAR(s.meshes[0].primitives[0].positions[1], glm::vec3(1, 0, 0), 0.0f);
  EXPECT_VEC3_NEAR(s.meshes[0].primitives[0].positions[2], glm::vec3(5, 6, 7), 0.0f);
}

TEST(GltfImport, BaseColourFactorAndEmbeddedTexture) {
  GltfTestFile f;
  // A PNG written by hand would be long; a 1x2 uncompressed 24-bit BMP is short. BMP
  // stores the bottom row first: green at the bottom, red at the top.
  std::string bmp = std::string("BM") + std::string(4, '\0') + std::string(4, '\0') + std::string("\x36\0\0\0", 4);
  const int32_t header[] = {40, 1, 2};
  bmp.append(reinterpret_cast<const char*>(header), 12);
  bmp += std::string("\x01\x00\x18\x00", 4) + std::string(24, '\0');
  bmp += std::string("\x00\xff\x00\x00", 4);  // bottom row: BGR green + padding to 4 bytes
  bmp += std::string("\x00\x00\xff\x00", 4);  // top row: BGR red + padding
  const int view = f.addView(bmp);
  f.doc["images"] = {{{"bufferView", view}, {"mimeType", "image/bmp"}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
  f.addNode(json::object());
  const Scene s = parsed(f);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].baseColor, glm::vec4(0.5f, 0.25f, 1, 1));
  ASSERT_EQ(s.materials[0].baseColorImage, 0);
  const TextureImage& image = s.images[0];
  ASSERT_EQ(image.width, 1);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(image.rgba, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));  // first row at the top
}

TEST(GltfImport, DroppedThingsAreReportedAndCompressedGeometryRefused) {
  GltfTestFile f;
  const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int uv = f.addFloats({0, 0, 1, 0, 0, 1}, "VEC2");
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}, {"TEXCOORD_1", uv}}}}}}}};
  f.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}};
  f.addNode({{"mesh", 0}, {"camera", 0}});
  const Scene s = parsed(f);
  EXPECT_EQ(s.meshes[0].primitives[0].texcoords.size(), 3u);
  std::string all;
  for (const std::string& w : s.warnings) all += w + "|";
  EXPECT_NE(all.find("TEXCOORD_1"), std::string::npos) << all;
  EXPECT_NE(all.find("cameras"), std::string::npos) << all;

  f.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  f.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  Result<Scene> r = parseGltf(f.gltf(), "draco.gltf");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("KHR_draco_mesh_compression"), std::string::npos) << r.error();
}

// KHR_mesh_quantization: normalised unsigned short positions read as value / 65535.
TEST(GltfImport, QuantizedPositions) {
  GltfTestFile f;
  const int pos = f.addInts(std::vector<uint16_t>{0, 0, 0, 65535, 0, 0, 0, 65535, 32768, 0}, test::kGltfUShort, "VEC3", 3);
  f.doc["accessors"][pos]["normalized"] = true;
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pos}}}}}}}};
  f.addNode({{"mesh", 0}});
  const Scene s = parsed(f);
  EXPECT_VEC3_NEAR(s.meshes[0].primitives[0].positions[1], glm::vec3(1, 0, 0), 0.0f);
  EXPECT_VEC3_NEAR(s.meshes[0].primitives[0].positions[2], glm::vec3(0, 1, 32768.0f / 65535.0f), 1e-7f);
}

// Two skins on one skeleton whose joints lie in separate trees (no common root).
TEST(GltfImport, SeveralSkinsWithoutACommonRoot) {
  GltfTestFile f;
  f.addNode({{"children", {1}}, {"translation", {1, 0, 0}}});  // 0
  f.addNode({{"translation", {0, 1, 0}}});                      // 1
  f.addNode({{"translation", {5, 0, 0}}});                      // 2: a second root
  const int ibm = f.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -5, 0, 0, 1}, "MAT4");
  f.doc["skins"] = {{{"joints", {1, 2}}, {"skeleton", 0}}, {{"joints", {2}}, {"inverseBindMatrices", ibm}}};
  const Scene s = parsed(f);
  ASSERT_EQ(s.skins.size(), 2u);
  ASSERT_EQ(s.skins[0].joints.size(), 2u);
  EXPECT_EQ(s.nodeOfJoint[s.skins[0].joints[0]], 1);
  EXPECT_EQ(s.nodeOfJoint[s.skins[0].joints[1]], 2);
  EXPECT_EQ(s.nodeOfJoint[s.skins[0].skeletonRoot], 0);
  EXPECT_EQ(s.skins[1].skeletonRoot, -1);
  EXPECT_EQ(s.skins[1].inverseBind[0][3], glm::vec4(-5, 0, 0, 1));  // column 3 = translation
  EXPECT_EQ(s.skins[0].inverseBind[1], glm::mat4(1.0f));
}

// Random forests in random node order: the skeleton is parent-first, keeps every
// parent-child edge, and each node's world position equals the product of its ancestors'
// TRS matrices walked in the file's own terms.
TEST(GltfImport, RandomNodeOrdersKeepTheHierarchy) {
  std::mt19937 rng(7);
  const int cases = test::propertyCases(200);
  for (int c = 0; c < cases; ++c) {
    const int n = 1 + static_cast<int>(rng() % 30);
    std::vector<int> parent(n, -1);
    for (int i = 1; i < n; ++i) parent[i] = (rng() % 5 == 0) ? -1 : static_cast<int>(rng() % i);  // a forest
    std::vector<int> nodeOf(n);  // shuffle: tree vertex i is node nodeOf[i]
    for (int i = 0; i < n; ++i) nodeOf[i] = i;
    std::shuffle(nodeOf.begin(), nodeOf.end(), rng);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    GltfTestFile f;
    f.doc["nodes"] = json::array();
    std::vector<glm::mat4> local(n);
    for (int node = 0; node < n; ++node) f.doc["nodes"].push_back(json::object());
    for (int i = 0; i < n; ++i) {
      const glm::vec3 t(u(rng), u(rng), u(rng));
      const glm::quat q = test::randomRotation(rng);
      json& node = f.doc["nodes"][nodeOf[i]];
      node["translation"] = {t.x, t.y, t.z};
      node["rotation"] = {q.x, q.y, q.z, q.w};
      local[i] = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(q);
      if (parent[i] >= 0) f.doc["nodes"][nodeOf[parent[i]]]["children"].push_back(nodeOf[i]);
    }
    const Scene s = parsed(f);
    ASSERT_EQ(s.skeleton.validate(), "");
    ASSERT_EQ(s.skeleton.size(), n);
    const std::vector<glm::mat4> world = computeWorld(s.skeleton, Pose::rest(s.skeleton));
    for (int j = 0; j < n; ++j) {
      const int i = static_cast<int>(std::find(nodeOf.begin(), nodeOf.end(), s.nodeOfJoint[j]) - nodeOf.begin());
      const int p = s.skeleton.parents[j];
      EXPECT_EQ(p < 0 ? -1 : s.nodeOfJoint[p], parent[i] < 0 ? -1 : nodeOf[parent[i]]);
      glm::mat4 expected = local[i];
      for (int a = parent[i]; a >= 0; a = parent[a]) expected = local[a] * expected;
      SCOPED_TRACE("case " + std::to_string(c));
      EXPECT_VEC3_NEAR(glm::vec3(world[j][3]), glm::vec3(expected[3]), 1e-4f);
    }
  }
}

}  // namespace
}  // namespace kinema
