// glTF export: structure read back with tinygltf, samplers evaluated here with the glTF
// specification's formulas (independently of io/gltf_curves) against our own sampling.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstdlib>
#include <cstring>
#include <fstream>

#include "anim/sampling.h"
#include "core/rotation.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/image.h"
#include "io/sample_scene.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::makeSampleScene;

tinygltf::Model parse(const std::string& bytes, bool binary) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                       reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       static_cast<unsigned>(bytes.size()))
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                      static_cast<unsigned>(bytes.size()), "");
  EXPECT_TRUE(ok) << err;
  return model;
}

tinygltf::Model exportAndParse(const Scene& scene, std::vector<std::string>* report = nullptr, bool binary = false) {
  GltfWriteOptions options;
  options.binary = binary;
  Result<std::string> bytes = gltfBytes(scene, options, report);
  EXPECT_TRUE(bytes.ok()) << bytes.error();
  return bytes ? parse(bytes.value(), binary) : tinygltf::Model{};
}

template <class T>
std::vector<T> read(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors.at(accessor);
  const tinygltf::BufferView& v = m.bufferViews.at(a.bufferView);
  const size_t n = a.count * tinygltf::GetNumComponentsInType(a.type);
  std::vector<T> out(n);
  std::memcpy(out.data(), m.buffers.at(v.buffer).data.data() + v.byteOffset + a.byteOffset, n * sizeof(T));
  return out;
}

int nodeOf(const Scene& s, int joint) { return s.nodeOfJoint[joint]; }

const tinygltf::AnimationChannel* findChannel(const tinygltf::Animation& a, int node, const std::string& path) {
  for (const auto& c : a.channels)
    if (c.target_node == node && c.target_path == path) return &c;
  return nullptr;
}

// The glTF 2.0 specification's sampler (Appendix C), written out here on its own.
std::vector<float> evaluate(const tinygltf::Model& m, const tinygltf::AnimationSampler& s, int components, float t) {
  const std::vector<float> times = read<float>(m, s.input), out = read<float>(m, s.output);
  const bool cubic = s.interpolation == "CUBICSPLINE";
  const int n = static_cast<int>(times.size());
  auto value = [&](int k, int slot) {
    const size_t at = (cubic ? 3 * k + slot : k) * size_t(components);
    return std::vector<float>(out.begin() + at, out.begin() + at + components);
  };
  if (t <= times[0]) return value(0, 1);
  if (t >= times[n - 1]) return value(n - 1, 1);
  int k = 0;
  while (times[k + 1] <= t) ++k;
  const float td = times[k + 1] - times[k], u = (t - times[k]) / td;
  if (s.interpolation == "STEP") return value(k, 1);
  std::vector<float> a = value(k, 1), b = value(k + 1, 1), r(components);
  if (!cubic) {
    if (components == 4) {
      glm::quat qa(a[3], a[0], a[1], a[2]), qb(b[3], b[0], b[1], b[2]);
      if (glm::dot(qa, qb) < 0) qb = -qb;
      const glm::quat q = glm::slerp(qa, qb, u);
      return {q.x, q.y, q.z, q.w};
    }
    for (int i = 0; i < components; ++i) r[i] = (1 - u) * a[i] + u * b[i];
    return r;
  }
  const std::vector<float> bk = value(k, 2), ak1 = value(k + 1, 0);
  const float u2 = u * u, u3 = u2 * u;
  for (int i = 0; i < components; ++i)
    r[i] = (2 * u3 - 3 * u2 + 1) * a[i] + td * (u3 - 2 * u2 + u) * bk[i] + (-2 * u3 + 3 * u2) * b[i] +
           td * (u3 - u2) * ak1[i];
  if (components == 4) {
    const glm::quat q = glm::normalize(glm::quat(r[3], r[0], r[1], r[2]));
    return {q.x, q.y, q.z, q.w};
  }
  return r;
}

// Largest difference between the file's channel and ours over `samples` times.
double maxDifference(const tinygltf::Model& m, const tinygltf::Animation& anim, const tinygltf::AnimationChannel& c,
                     const Channel& ours, int samples) {
  const int components = c.target_path == "rotation" ? 4 : 3;
  double worst = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const float t = ours.endTime() * float(i) / float(samples);
    const std::vector<float> got = evaluate(m, anim.samplers[c.sampler], components, t);
    glm::vec4 want = sampleChannel(ours, t);
    if (ours.target == ChannelTarget::Euler) {
      const glm::quat q = eulerToQuat(glm::vec3(want), ours.eulerOrder);
      want = {q.x, q.y, q.z, q.w};
    }
    if (components == 4) {
      const glm::quat a(got[3], got[0], got[1], got[2]), b(want.w, want.x, want.y, want.z);
      const glm::quat d = glm::inverse(a) * b;
      worst = std::max(worst, 2.0 * std::atan2(glm::length(glm::vec3(d.x, d.y, d.z)), std::abs(d.w)));
    } else {
      worst = std::max(worst, double(glm::length(glm::vec3(got[0], got[1], got[2]) - glm::vec3(want))));
    }
  }
  return worst;
}

TEST(GltfWriter, NodesKeepNamesFileOrderAndRestPose) {
  const Scene scene = makeSampleScene();
  const tinygltf::Model m = exportAndParse(scene);
  ASSERT_EQ(m.nodes.size(), 9u);
  for (int j = 0; j < scene.skeleton.size(); ++j) {
    const tinygltf::Node& n = m.nodes[nodeOf(scene, j)];
    EXPECT_EQ(n.name, scene.skeleton.names[j]);
    const int parent = scene.skeleton.parents[j];
    if (parent >= 0) {
      const auto& siblings = m.nodes[nodeOf(scene, parent)].children;
      EXPECT_NE(std::find(siblings.begin(), siblings.end(), nodeOf(scene, j)), siblings.end()) << n.name;
    }
  }
  // Root: translation (0, 1, 0), 0.5 rad about Y -> quaternion (0, sin 0.25, 0, cos 0.25).
  const tinygltf::Node& root = m.nodes[nodeOf(scene, test::kRoot)];
  ASSERT_EQ(root.translation.size(), 3u);
  EXPECT_DOUBLE_EQ(root.translation[1], 1.0);
  ASSERT_EQ(root.rotation.size(), 4u);
  EXPECT_NEAR(root.rotation[1], std::sin(0.25), 1e-7);
  EXPECT_NEAR(root.rotation[3], std::cos(0.25), 1e-7);
  EXPECT_TRUE(root.scale.empty());  // identity scale is left to glTF's default
  ASSERT_EQ(m.scenes.size(), 1u);
  EXPECT_EQ(m.scenes[0].nodes, (std::vector<int>{1, 2}));  // Body (node 1) and Root (node 2)
}

TEST(GltfWriter, SkinMeshMorphTargetsAndTexturedMaterial) {
  const Scene scene = makeSampleScene();
  const tinygltf::Model m = exportAndParse(scene);
  ASSERT_EQ(m.skins.size(), 1u);
  const tinygltf::Skin& skin = m.skins[0];
  ASSERT_EQ(skin.joints.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(skin.joints[i], nodeOf(scene, i));
  EXPECT_EQ(skin.skeleton, nodeOf(scene, test::kRoot));
  const std::vector<float> ibm = read<float>(m, skin.inverseBindMatrices);
  ASSERT_EQ(ibm.size(), 8u * 16u);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(ibm[16 * 3 + i], (&scene.skins[0].inverseBind[3][0][0])[i]);

  const tinygltf::Node& body = m.nodes[nodeOf(scene, test::kBody)];
  EXPECT_EQ(body.mesh, 0);
  EXPECT_EQ(body.skin, 0);
  ASSERT_EQ(m.meshes.size(), 1u);
  const tinygltf::Primitive& p = m.meshes[0].primitives.at(0);
  for (const char* a : {"POSITION", "NORMAL", "TEXCOORD_0", "JOINTS_0", "JOINTS_1", "WEIGHTS_0", "WEIGHTS_1"})
    EXPECT_EQ(p.attributes.count(a), 1u) << a;
  // POSITION bounds by hand: x = +-0.1, y from 1 to 1.75, z = 0.
  const tinygltf::Accessor& pos = m.accessors[p.attributes.at("POSITION")];
  EXPECT_EQ(pos.minValues, (std::vector<double>{-0.1f, 1.0, 0.0}));
  EXPECT_EQ(pos.maxValues, (std::vector<double>{0.1f, 1.75, 0.0}));
  // Eight influences come back as two sets of four, in order.
  const std::vector<uint16_t> j0 = read<uint16_t>(m, p.attributes.at("JOINTS_0")),
                              j1 = read<uint16_t>(m, p.attributes.at("JOINTS_1"));
  const std::vector<float> w0 = read<float>(m, p.attributes.at("WEIGHTS_0")),
                           w1 = read<float>(m, p.attributes.at("WEIGHTS_1"));
  const MeshPrimitive& src = scene.meshes[0].primitives[0];
  for (int v = 0; v < 8; ++v)
    for (int i = 0; i < 8; ++i) {
      const float w = i < 4 ? w0[v * 4 + i] : w1[v * 4 + i - 4];
      const uint16_t j = i < 4 ? j0[v * 4 + i] : j1[v * 4 + i - 4];
      EXPECT_EQ(w, src.influenceWeights[v * 8 + i]);
      if (w != 0.0f) {
        EXPECT_EQ(j, src.influenceJoints[v * 8 + i]);
      }
    }
  EXPECT_EQ(read<uint16_t>(m, p.indices), std::vector<uint16_t>(src.indices.begin(), src.indices.end()));
  ASSERT_EQ(p.targets.size(), 2u);
  const tinygltf::Accessor& smile = m.accessors[p.targets[0].at("POSITION")];
  EXPECT_EQ(smile.maxValues, (std::vector<double>{0.0, 0.0, 0.35f}));
  EXPECT_EQ(m.meshes[0].weights, (std::vector<double>{0.25, 0.0}));
  ASSERT_TRUE(m.meshes[0].extras.Has("targetNames"));
  EXPECT_EQ(m.meshes[0].extras.Get("targetNames").Get(1).Get<std::string>(), "blink");

  ASSERT_EQ(m.materials.size(), 1u);
  const tinygltf::Material& mat = m.materials[0];
  EXPECT_EQ(mat.name, "clay");
  EXPECT_TRUE(mat.doubleSided);
  EXPECT_NEAR(mat.pbrMetallicRoughness.baseColorFactor[0], 0.8, 1e-7);
  const int texture = mat.pbrMetallicRoughness.baseColorTexture.index;
  ASSERT_EQ(texture, 0);
  const tinygltf::Image& image = m.images.at(m.textures.at(texture).source);
  EXPECT_EQ(image.mimeType, "image/png");
  // tinygltf decoded the embedded PNG: the pixels are the checker's.
  EXPECT_EQ(image.width, 4);
  EXPECT_EQ(image.image, scene.images[0].rgba);
}

TEST(GltfWriter, EachInterpolationGetsTheSamplerThatHoldsIt) {
  const Scene scene = makeSampleScene();
  const tinygltf::Model m = exportAndParse(scene);
  ASSERT_EQ(m.animations.size(), 2u);
  const tinygltf::Animation& a = m.animations[0];
  EXPECT_EQ(a.name, "dance");
  auto kind = [&](int joint, const char* path) {
    const tinygltf::AnimationChannel* c = findChannel(a, nodeOf(scene, joint), path);
    return c ? a.samplers[c->sampler].interpolation : std::string("none");
  };
  EXPECT_EQ(kind(test::kB1, "translation"), "CUBICSPLINE");  // Catmull-Rom
  EXPECT_EQ(kind(test::kB2, "rotation"), "LINEAR");          // Squad, resampled
  EXPECT_EQ(kind(test::kB3, "rotation"), "LINEAR");          // slerp
  EXPECT_EQ(kind(test::kB4, "scale"), "STEP");
  EXPECT_EQ(kind(test::kB5, "rotation"), "LINEAR");          // Euler, resampled
  EXPECT_EQ(kind(test::kB6, "translation"), "CUBICSPLINE");  // Bezier, automatic handles
  EXPECT_EQ(kind(test::kB7, "rotation"), "CUBICSPLINE");     // Hermite rotation
  EXPECT_EQ(kind(test::kRoot, "translation"), "CUBICSPLINE");  // TCB
  EXPECT_EQ(kind(test::kBody, "weights"), "LINEAR");
  EXPECT_EQ(a.channels.size(), 9u);  // "temperature" has no place in glTF
  for (const auto& s : a.samplers) {
    const tinygltf::Accessor& in = m.accessors[s.input];
    const std::vector<float> t = read<float>(m, s.input);
    ASSERT_EQ(in.minValues.size(), 1u);
    EXPECT_EQ(in.minValues[0], t.front());
    EXPECT_EQ(in.maxValues[0], t.back());
  }
}

TEST(GltfWriter, CatmullRomTangentsAreTheKeyChordsOverTheSpan) {
  const Scene scene = makeSampleScene();
  const tinygltf::Model m = exportAndParse(scene);
  const tinygltf::Animation& a = m.animations[0];
  const tinygltf::AnimationChannel* c = findChannel(a, nodeOf(scene, test::kB1), "translation");
  ASSERT_NE(c, nullptr);
  const Channel& ours = scene.clips[0].channels[0];
  const std::vector<float> out = read<float>(m, a.samplers[c->sampler].output);
  ASSERT_EQ(out.size(), ours.times.size() * 9);
  // Interior keys: in = out = (p[k+1] - p[k-1]) / (t[k+1] - t[k-1]) (Catmull-Rom by hand).
  for (int k = 1; k + 1 < ours.keyCount(); ++k) {
    const glm::vec3 want =
        glm::vec3(ours.values[k + 1] - ours.values[k - 1]) / (ours.times[k + 1] - ours.times[k - 1]);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(out[9 * k + 6 + i], want[i], 1e-6) << "out-tangent, key " << k;
      EXPECT_NEAR(out[9 * k + i], want[i], 1e-6) << "in-tangent, key " << k;
      EXPECT_EQ(out[9 * k + 3 + i], ours.values[k][i]);
    }
  }
  // And the file's curve is ours everywhere, not just at the keys.
  EXPECT_LT(maxDifference(m, a, *c, ours, 1000), 2e-6);
}

TEST(GltfWriter, ExactSamplersReproduceTheClipEverywhere) {
  const Scene scene = makeSampleScene();
  const tinygltf::Model m = exportAndParse(scene);
  const tinygltf::Animation& a = m.animations[0];
  for (const Channel& ch : scene.clips[0].channels) {
    if (ch.target == ChannelTarget::Scalar || ch.joint == test::kB2 || ch.joint == test::kB5) continue;
    const char* path = ch.target == ChannelTarget::Translation ? "translation"
                       : ch.target == ChannelTarget::Scale     ? "scale"
                                                               : "rotation";
    const tinygltf::AnimationChannel* c = findChannel(a, nodeOf(scene, ch.joint), path);
    ASSERT_NE(c, nullptr) << scene.skeleton.names[ch.joint];
    EXPECT_LT(maxDifference(m, a, *c, ch, 1200), 1e-5) << scene.skeleton.names[ch.joint] << " " << path;
  }
  // Morph weights: two targets per key, both channels reproduced.
  const tinygltf::AnimationChannel* w = findChannel(a, nodeOf(scene, test::kBody), "weights");
  ASSERT_NE(w, nullptr);
  for (int i = 0; i <= 100; ++i) {
    const float t = 1.2f * i / 100.0f;
    const std::vector<float> got = evaluate(m, a.samplers[w->sampler], 2, t);
    EXPECT_NEAR(got[0], sampleChannel(scene.clips[0].channels[8], t).x, 1e-6);
    EXPECT_NEAR(got[1], sampleChannel(scene.clips[0].channels[9], t).x, 1e-6);
  }
}

// "max error X deg" from the report line about `joint`.
double reportedDegrees(const std::vector<std::string>& report, const std::string& joint) {
  for (const std::string& line : report)
    if (line.find("joint '" + joint + "'") != std::string::npos && line.find("max error ") != std::string::npos)
      return std::atof(line.c_str() + line.find("max error ") + 10);
  return -1.0;
}

TEST(GltfWriter, ResampledRotationsReportTheirError) {
  const Scene scene = makeSampleScene();
  std::vector<std::string> report;
  const tinygltf::Model m = exportAndParse(scene, &report);
  const tinygltf::Animation& a = m.animations[0];
  for (int joint : {int(test::kB2), int(test::kB5)}) {
    const std::string name = scene.skeleton.names[joint];
    const double reported = reportedDegrees(report, name);
    ASSERT_GE(reported, 0.0) << "no report line for " << name;
    const Channel* ours = nullptr;
    for (const Channel& ch : scene.clips[0].channels)
      if (ch.joint == joint) ours = &ch;
    const tinygltf::AnimationChannel* c = findChannel(a, nodeOf(scene, joint), "rotation");
    ASSERT_NE(c, nullptr);
    // Measured densely here: the report (probes inside each interval) is close to it.
    const double measured = maxDifference(m, a, *c, *ours, 20000) * 180.0 / 3.14159265358979;
    EXPECT_GT(measured, 1e-4) << name << ": a resampled curve that matches exactly needs no resampling";
    EXPECT_NEAR(reported, measured, 0.25 * measured + 1e-4) << name;
    // 24 samples per second (the clip has no frame rate: the document's default), keys kept.
    const std::vector<float> t = read<float>(m, a.samplers[c->sampler].input);
    for (size_t i = 1; i < t.size(); ++i) EXPECT_LE(t[i] - t[i - 1], 1.0f / 24.0f + 1e-6f);
    for (float key : ours->times) EXPECT_NE(std::find(t.begin(), t.end(), key), t.end());
  }
  bool dropped = false;
  for (const std::string& line : report) dropped = dropped || line.find("'temperature' dropped") != std::string::npos;
  EXPECT_TRUE(dropped);
  EXPECT_EQ(report.size(), 3u);  // B2, B5, temperature: nothing else is lost
}

TEST(GltfWriter, BezierWithLongHandlesIsResampled) {
  Scene scene;
  scene.skeleton.addJoint("a", -1, Transform::identity());
  Channel ch(0, ChannelTarget::Translation, Interpolation::Bezier, {0.0f, 1.0f}, {{0, 0, 0, 0}, {1, 0, 0, 0}});
  ch.keys.resize(2);
  for (KeySettings& k : ch.keys) {
    k.interpolation = Interpolation::Bezier;
    k.leftHandleType = k.rightHandleType = HandleType::Free;
  }
  ch.keys[0].rightHandleTime = 0.6f;  // not a third: time is not linear in the curve parameter
  ch.keys[0].rightHandleValue = {0.1f, 0, 0, 0};
  ch.keys[1].leftHandleTime = -0.1f;
  ch.keys[1].leftHandleValue = {-0.5f, 0, 0, 0};
  Clip clip;
  clip.channels.push_back(ch);
  scene.clips.push_back(clip);
  std::vector<std::string> report;
  GltfWriteOptions options;
  options.resampleRate = 100.0;
  ASSERT_TRUE(gltfBytes(scene, options, &report).ok());
  ASSERT_EQ(report.size(), 1u);
  EXPECT_NE(report[0].find("resampled at 100 fps"), std::string::npos) << report[0];
  const tinygltf::Model m = parse(gltfBytes(scene, options).value(), false);
  EXPECT_EQ(m.animations[0].samplers[0].interpolation, "LINEAR");
  EXPECT_EQ(read<float>(m, m.animations[0].samplers[0].input).size(), 101u);
}

TEST(GltfWriter, WeightsAreRenormalisedAndInfluencesCheckedAgainstTheSkin) {
  Scene scene = makeSampleScene();
  for (float& w : scene.meshes[0].primitives[0].influenceWeights) w *= 2.0f;  // sums of 2
  const tinygltf::Model m = exportAndParse(scene);
  const tinygltf::Primitive& p = m.meshes[0].primitives[0];
  const std::vector<float> w0 = read<float>(m, p.attributes.at("WEIGHTS_0")),
                           w1 = read<float>(m, p.attributes.at("WEIGHTS_1"));
  for (int v = 0; v < 8; ++v) {
    float sum = 0.0f;
    for (int i = 0; i < 4; ++i) sum += w0[v * 4 + i] + w1[v * 4 + i];
    EXPECT_NEAR(sum, 1.0f, 1e-6f) << "vertex " << v;
  }
  scene.meshes[0].primitives[0].influenceJoints[0] = 8;  // the skin has joints 0..7
  const Result<std::string> bad = gltfBytes(scene, {});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("uses joint 8 of a skin with 8"), std::string::npos) << bad.error();
}

TEST(GltfWriter, AbsurdResamplingIsRefused) {
  Scene scene = makeSampleScene();
  scene.clips[0].channels[1].times.back() = 1.0e6f;  // the Squad channel, a million seconds long
  const Result<std::string> bytes = gltfBytes(scene, {});
  ASSERT_FALSE(bytes.ok());
  EXPECT_NE(bytes.error().find("clip 0 would need"), std::string::npos) << bytes.error();
}

TEST(GltfWriter, GlbIsBinaryAndHoldsTheSameScene) {
  const Scene scene = makeSampleScene();
  GltfWriteOptions options;
  options.binary = true;
  const Result<std::string> glb = gltfBytes(scene, options);
  ASSERT_TRUE(glb.ok());
  ASSERT_GT(glb->size(), 20u);
  EXPECT_EQ(glb->substr(0, 4), "glTF");
  uint32_t version = 0, length = 0;
  std::memcpy(&version, glb->data() + 4, 4);
  std::memcpy(&length, glb->data() + 8, 4);
  EXPECT_EQ(version, 2u);
  EXPECT_EQ(length, glb->size());
  const tinygltf::Model m = parse(glb.value(), true);
  EXPECT_EQ(m.nodes.size(), 9u);
  EXPECT_EQ(m.animations.size(), 2u);
  EXPECT_EQ(m.images.at(0).image, scene.images[0].rgba);
}

// A primitive with vertices and no triangle (an empty index list) stays without triangles: it
// is written as points, since glTF triangles without indices would read back as one triangle
// per three vertices (the fuzzer's round trip found it).
TEST(GltfWriter, APrimitiveWithoutTrianglesStaysWithoutTriangles) {
  Scene scene = makeSampleScene();
  ASSERT_FALSE(scene.meshes.empty());
  MeshPrimitive& prim = scene.meshes[0].primitives.at(0);
  ASSERT_GE(prim.positions.size(), 3u);
  prim.indices.clear();
  const Result<std::string> gltf = gltfBytes(scene, {});
  ASSERT_TRUE(gltf.ok()) << gltf.error();
  EXPECT_EQ(parse(gltf.value(), false).meshes.at(0).primitives.at(0).mode, TINYGLTF_MODE_POINTS);
  const Result<Scene> back = parseGltf(gltf.value(), "points.gltf");
  ASSERT_TRUE(back.ok()) << back.error();
  const MeshPrimitive& read = back->meshes.at(0).primitives.at(0);
  EXPECT_EQ(read.positions.size(), prim.positions.size());
  EXPECT_TRUE(read.indices.empty());
}

TEST(GltfWriter, FailedSaveLeavesThePreviousFile) {
  const std::string dir = test::makeTempDir();
  const std::string path = dir + "/out.gltf";
  test::writeFile(path, "previous");
  Scene scene = makeSampleScene();
  scene.skins[0].joints[2] = 99;
  const std::string error = saveGltf(path, scene, {});
  EXPECT_NE(error.find("skin 0"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_EQ(test::readFile(path), "previous");
  EXPECT_EQ(saveGltf(path, makeSampleScene(), {}), "");
  EXPECT_NE(test::readFile(path), "previous");
}

// Writes the sample scene where the validator test (tests/tools/validate_gltf.cmake)
// asks for it; otherwise into a temporary folder, checking tinygltf reads the files.
TEST(GltfWriterSamples, WriteForValidation) {
  const char* env = std::getenv("KINEMA_GLTF_SAMPLE_DIR");
  const std::string dir = env && *env ? env : test::makeTempDir();
  const Scene scene = makeSampleScene();
  for (const char* ext : {".gltf", ".glb"}) {
    GltfWriteOptions options;
    options.binary = std::string(ext) == ".glb";
    ASSERT_EQ(saveGltf(dir + "/sample_scene" + ext, scene, options), "");
    const tinygltf::Model m = parse(test::readFile(dir + "/sample_scene" + ext), options.binary);
    EXPECT_EQ(m.nodes.size(), 9u);
  }
}

}  // namespace
}  // namespace kinema
