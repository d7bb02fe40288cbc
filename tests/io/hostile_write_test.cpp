// Issue 19, the writers' side: whatever the readers accept converts, in output and memory
// linear in the input (a chain 20,000 joints deep in CI, 200,000 by hand with
// KINEMA_DEEP_CHAIN_DEPTH; a joint name of KINEMA_HUGE_NAME_BYTES), sample counts near the
// float limit and denormal frame times, an image that does not decode; and what Blender
// needs: a BVH -> glb carries a skin (an armature), BVH End Sites have the bone's length.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <tiny_gltf.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "core/forward_kinematics.h"
#include "io/bvh.h"
#include "io/bvh_writer.h"
#include "io/gltf_limits.h"
#include "io/gltf_writer.h"
#include "io/image.h"
#include "io/scene_files.h"
#include "io/gltf_test_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

long envCount(const char* name, long fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  const long v = std::strtol(text, nullptr, 10);
  return v > 0 ? v : fallback;
}

long fileSize(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? static_cast<long>(st.st_size) : -1;
}

// One run of the kinema binary: exit status, stderr, wall time and the child's own peak
// resident memory (wait4's rusage, not the test process's).
struct KinemaRun {
  int status = -1;
  std::string err;
  double seconds = 0.0;
  long peakKb = 0;
};

KinemaRun runKinema(const std::vector<std::string>& args, const std::string& dir) {
  KinemaRun run;
  const std::string errPath = dir + "/stderr.txt";
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open("/dev/null", O_WRONLY);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(KINEMA_BINARY));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(KINEMA_BINARY, argv.data());
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  ::wait4(pid, &status, 0, &usage);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.peakKb = usage.ru_maxrss;
  run.err = test::readFile(errPath);
  return run;
}

// Memory bound for a conversion: the issue's 256 MB + 4x the bytes it handles (input and
// output), or 256 MB + `extraBytes` where a writer's document model needs more.
void expectBoundedMemory(const KinemaRun& run, long extraBytes, const char* what) {
#if defined(KINEMA_UNDER_SANITIZER)
  (void)run, (void)extraBytes, (void)what;  // ASan's own overhead
#else
  const long boundKb = 256 * 1024 + extraBytes / 1024;
  EXPECT_LE(run.peakKb, boundKb) << what << ": peak " << run.peakKb << " KB";
#endif
}

// ROOT r -> j1 -> ... -> j(depth-1) -> End Site, every OFFSET (0, 1, 0) but the root's, two
// frames. `longName` bytes replace j1's name when given.
std::string deepChainBvh(long depth, size_t longName = 0) {
  std::string t = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  t.reserve(static_cast<size_t>(depth) * 60 + longName);
  for (long i = 1; i < depth; ++i) {
    t += "JOINT ";
    t += (longName && i == 1) ? std::string(longName, 'J') : "j" + std::to_string(i);
    t += "\n{\nOFFSET 0 1 0.5\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
  }
  t += "End Site\n{\nOFFSET 0 1 0\n}\n";
  for (long i = 0; i < depth; ++i) t += "}\n";
  t += "MOTION\nFrames: 2\nFrame Time: 0.0333333\n";
  std::string row;
  for (long c = 0; c < 6 + 3 * (depth - 1); ++c) row += c == 7 ? "10 " : "0 ";
  row.back() = '\n';
  return t + row + row;
}

void expectSameSkeleton(const Skeleton& a, const Skeleton& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  int bad = 0;
  for (int j = 0; j < a.size() && bad < 5; ++j) {
    if (a.names[j] != b.names[j] || a.parents[j] != b.parents[j] ||
        glm::length(a.rest[j].translation - b.rest[j].translation) > 1e-5f) {
      ADD_FAILURE() << what << ": joint " << j << " differs";
      ++bad;
    }
  }
}

TEST(HostileWrite, DeepChainConvertsToEveryFormatInLinearSizeAndMemory) {
  const long depth = envCount("KINEMA_DEEP_CHAIN_DEPTH", 20000);
  const std::string dir = test::makeTempDir();
  const std::string input = dir + "/deep.bvh";
  test::writeFile(input, deepChainBvh(depth));
  const long inBytes = fileSize(input);
  Result<Scene> source = loadScene(input);
  ASSERT_TRUE(source.ok()) << source.error();
  ASSERT_EQ(source->skeleton.size(), depth + 1);  // + the End Site
  for (const char* ext : {".bvh", ".kinema", ".glb"}) {
    const std::string output = dir + "/out" + ext;
    const KinemaRun run = runKinema({"convert", input, output}, dir);
    const long outBytes = fileSize(output);
    std::cout << "[ deep chain " << depth << " -> " << ext << " ] exit " << run.status << ", " << run.seconds
              << " s, peak " << run.peakKb / 1024 << " MB, " << outBytes / 1024 << " KB out\n";
    ASSERT_EQ(run.status, 0) << ext << ": " << run.err.substr(0, 300);
    // Linear output: a BVH indented to its depth would be depth^2 (gigabytes) here.
    EXPECT_LE(outBytes, 8 * inBytes) << ext;
    // The writers build a document before the text: glTF through tinygltf's model and
    // nlohmann JSON, about 9 KB per node with its animation channel (bound: 12 KB per joint);
    // .kinema through nlohmann's ordered_json, about 1 KB per joint beyond 4x its bytes.
    if (std::string(ext) == ".glb")
      expectBoundedMemory(run, 12 * 1024 * (depth + 1), ext);
    else if (std::string(ext) == ".kinema")
      expectBoundedMemory(run, 4 * (inBytes + outBytes) + 1024 * (depth + 1), ext);
    else
      expectBoundedMemory(run, 4 * (inBytes + outBytes), ext);
    if (std::string(ext) == ".glb" && static_cast<size_t>(depth + 1) > GltfLimits::kMaxNodes) continue;  // refused on reading
    Result<Scene> back = loadScene(output);
    ASSERT_TRUE(back.ok()) << back.error().substr(0, 300);
    expectSameSkeleton(source->skeleton, back->skeleton, ext);
  }
  test::runCommand("rm -rf '" + dir + "'");
}

TEST(HostileWrite, HugeJointNameConvertsInLinearSize) {
  const size_t bytes = static_cast<size_t>(envCount("KINEMA_HUGE_NAME_BYTES", 5 << 20));
  const std::string dir = test::makeTempDir();
  const std::string input = dir + "/name.bvh";
  test::writeFile(input, deepChainBvh(3, bytes));
  const long inBytes = fileSize(input);
  for (const char* ext : {".bvh", ".kinema", ".glb"}) {
    const std::string output = dir + "/out" + ext;
    const KinemaRun run = runKinema({"convert", input, output}, dir);
    const long outBytes = fileSize(output);
    std::cout << "[ " << bytes << "-byte name -> " << ext << " ] exit " << run.status << ", " << run.seconds
              << " s, peak " << run.peakKb / 1024 << " MB\n";
    ASSERT_EQ(run.status, 0) << ext << ": " << run.err.substr(0, 300);
    EXPECT_LE(outBytes, 3 * inBytes) << ext;  // .kinema names the joint twice (skeleton, channel)
    expectBoundedMemory(run, 4 * (inBytes + outBytes), ext);
    Result<Scene> back = loadScene(output);
    ASSERT_TRUE(back.ok()) << back.error().substr(0, 300);
    ASSERT_GE(back->skeleton.size(), 2);
    EXPECT_EQ(back->skeleton.names[1], std::string(bytes, 'J')) << ext;
  }
  test::runCommand("rm -rf '" + dir + "'");
}

// One joint with a translation channel from `t0` to `t1` (interpolation `mode`).
Scene oneChannelScene(float t0, float t1, Interpolation mode, ChannelTarget target, double frameTime) {
  Scene scene;
  scene.source = "channel.kinema";
  scene.skeleton.addJoint("a", -1, Transform::identity());
  Clip clip;
  clip.name = "c";
  clip.frameTime = frameTime;
  clip.channels.push_back(Channel(0, target, mode, {t0, t1}, {{0, 0, 0, 0}, {1, 0.5f, 0, 0}}));
  scene.clips.push_back(clip);
  return scene;
}

bool oneLineUnder300(const std::string& s) { return s.find('\n') == std::string::npos && s.size() <= 300; }

TEST(HostileWrite, SampleCountsNearTheFloatLimitDoNotOverflowAndOnlyResamplingIsRefused) {
  // Keys at 0 and 3e38 s: a BVH would need 9e39 frames. The refusal says so in double
  // (the old message printed -9223372036854775808).
  const Scene huge = oneChannelScene(0.0f, 3e38f, Interpolation::Linear, ChannelTarget::Translation, 1.0 / 30);
  const Result<std::string> bvh = bvhText(huge.skeleton, &huge.clips[0], {});
  ASSERT_FALSE(bvh.ok());
  EXPECT_TRUE(oneLineUnder300(bvh.error())) << bvh.error();
  EXPECT_EQ(bvh.error().find("-9223372036854775808"), std::string::npos) << bvh.error();
  EXPECT_NE(bvh.error().find("3e+38 s"), std::string::npos) << bvh.error();
  EXPECT_NE(bvh.error().find("9e+39 frames"), std::string::npos) << bvh.error();
  // glTF holds LINEAR keys exactly: no resampling, so nothing to refuse (the old check
  // refused every clip this long).
  std::vector<std::string> report;
  const Result<std::string> linear = gltfBytes(huge, {}, &report);
  ASSERT_TRUE(linear.ok()) << linear.error();
  EXPECT_TRUE(report.empty()) << report[0];
  // An Euler curve must be resampled: 9e39 samples is refused, the count said in double.
  const Scene euler = oneChannelScene(0.0f, 3e38f, Interpolation::Linear, ChannelTarget::Euler, 1.0 / 30);
  const Result<std::string> sampled = gltfBytes(euler, {});
  ASSERT_FALSE(sampled.ok());
  EXPECT_TRUE(oneLineUnder300(sampled.error())) << sampled.error();
  EXPECT_EQ(sampled.error(),
            "cannot export: clip 0 would need 9e+39 samples per resampled curve (3e+38 s at 30 fps; at most 1e+07)");
}

TEST(HostileWrite, DenormalFrameTimeClipResamplesAtTheDefaultRate) {
  // 1 / 1e-310 is infinite: the old check printed a nonsense count and refused.
  const Scene scene = oneChannelScene(0.0f, 1.0f, Interpolation::Linear, ChannelTarget::Euler, 1e-310);
  std::vector<std::string> report;
  const Result<std::string> bytes = gltfBytes(scene, {}, &report);
  ASSERT_TRUE(bytes.ok()) << bytes.error();
  ASSERT_FALSE(report.empty());
  EXPECT_NE(report[0].find("resampled at 24 fps instead of inf fps"), std::string::npos) << report[0];
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadASCIIFromString(&model, &err, &warn, bytes->data(), static_cast<unsigned>(bytes->size()), ""))
      << err;
  ASSERT_EQ(model.animations.size(), 1u);
  // 0..1 s at the default 24 fps: 25 samples.
  EXPECT_EQ(model.accessors[model.animations[0].samplers[0].input].count, 25u);
}

TEST(HostileWrite, BvhWithADenormalFrameTimeLoadsAndConvertsEverywhere) {
  const std::string dir = test::makeTempDir();
  std::string text = deepChainBvh(3);
  text.replace(text.find("Frame Time: 0.0333333"), 21, "Frame Time: 1e-310");
  const std::string input = dir + "/denormal.bvh";
  test::writeFile(input, text);
  for (const char* ext : {".bvh", ".kinema", ".glb"}) {
    const std::string output = dir + "/out" + ext;
    const KinemaRun run = runKinema({"convert", input, output}, dir);
    ASSERT_EQ(run.status, 0) << ext << ": " << run.err;
    EXPECT_NE(run.err.find("Frame Time 1e-310 s is too small to tell frames apart: read as 1/24 s (the default frame rate)"), std::string::npos)
        << run.err;
    Result<Scene> back = loadScene(output);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->clips.size(), 1u);
    EXPECT_NEAR(back->clips[0].duration(), 1.0 / 24, 1e-6) << ext;  // two frames, 1/24 s apart
    EXPECT_EQ(back->clips[0].validate(back->skeleton), "") << ext;
  }
  test::runCommand("rm -rf '" + dir + "'");
}

TEST(HostileWrite, GltfWithAnImageThatDoesNotDecodeConverts) {
  // Two textured materials: image 0 is garbage, image 1 a 2x1 PNG. Material 1 must keep
  // its picture (index 1 -> 0), material 0 its colour without a texture.
  test::GltfTestFile f;
  const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int bad = f.addView("this is not an image at all");
  const unsigned char rgba[8] = {255, 0, 0, 255, 0, 0, 255, 255};
  const int good = f.addView(encodePng(2, 1, rgba));
  f.doc["images"] = nlohmann::json::parse("[{\"bufferView\": " + std::to_string(bad) +
                                          ", \"mimeType\": \"image/png\", \"name\": \"broken\"}, {\"bufferView\": " +
                                          std::to_string(good) + ", \"mimeType\": \"image/png\", \"name\": \"ok\"}]");
  f.doc["textures"] = nlohmann::json::parse(R"([{"source": 0}, {"source": 1}])");
  f.doc["materials"] = nlohmann::json::parse(
      R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "baseColorFactor": [0.5, 0.25, 1, 1]}},
          {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1}}}])");
  const std::string p = std::to_string(pos);
  f.doc["meshes"] = nlohmann::json::parse("[{\"primitives\": [{\"attributes\": {\"POSITION\": " + p +
                                          "}, \"material\": 0}, {\"attributes\": {\"POSITION\": " + p +
                                          "}, \"material\": 1}]}]");
  const int node = f.addNode(nlohmann::json::parse(R"({"name": "n", "mesh": 0})"));
  f.doc["scenes"] = nlohmann::json::parse("[{\"nodes\": [" + std::to_string(node) + "]}]");
  f.doc["scene"] = 0;
  const std::string dir = test::makeTempDir();
  const std::string input = dir + "/broken_image.glb";
  test::writeFile(input, f.glb());
  Result<Scene> loaded = loadScene(input);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  ASSERT_EQ(loaded->images.size(), 2u);
  ASSERT_TRUE(isUndecodedImage(loaded->images[0]));
  for (const char* ext : {".glb", ".kinema"}) {
    const std::string output = dir + "/out" + ext;
    const KinemaRun run = runKinema({"convert", input, output}, dir);
    ASSERT_EQ(run.status, 0) << ext << ": " << run.err;
    EXPECT_NE(run.err.find("image 0"), std::string::npos) << run.err;  // the load warning names it
    Result<Scene> back = loadScene(output);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->images.size(), 1u) << ext;
    EXPECT_EQ(back->images[0].width, 2);
    EXPECT_EQ(back->images[0].rgba, std::vector<uint8_t>(rgba, rgba + 8));
    ASSERT_EQ(back->materials.size(), 2u);
    EXPECT_EQ(back->materials[0].baseColorImage, -1) << ext;
    EXPECT_VEC3_NEAR(glm::vec3(back->materials[0].baseColor), glm::vec3(0.5f, 0.25f, 1.0f), 1e-6f);
    EXPECT_EQ(back->materials[1].baseColorImage, 0) << ext;
  }
  test::runCommand("rm -rf '" + dir + "'");
}

// The glb's node world matrices from its own TRS, walked from the scene roots.
std::vector<glm::dmat4> nodeWorlds(const tinygltf::Model& m) {
  std::vector<glm::dmat4> world(m.nodes.size(), glm::dmat4(1.0));
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (int root : m.scenes[0].nodes) stack.push_back({root, glm::dmat4(1.0)});
  while (!stack.empty()) {
    const auto [n, parent] = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = m.nodes[n];
    glm::dmat4 local(1.0);
    if (node.translation.size() == 3)
      local = glm::translate(local, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
      local *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) local = glm::scale(local, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    world[n] = parent * local;
    for (int c : node.children) stack.push_back({c, world[n]});
  }
  return world;
}

TEST(HostileWrite, BvhToGlbCarriesAnArmatureSkinPerRoot) {
  // Two trees: Hips (at 1,2,3) -> Spine (0,1,0) -> End Site (0,0.5,0), Hips -> Leg (0.2,-1,0)
  // -> End Site; and a lone root Prop (5,0,0) -> End Site (0,0,1).
  const std::string bvh =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 1 2 3\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      " JOINT Spine\n {\n  OFFSET 0 1 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "  End Site\n  {\n   OFFSET 0 0.5 0\n  }\n }\n"
      " JOINT Leg\n {\n  OFFSET 0.2 -1 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "  End Site\n  {\n   OFFSET 0 -1 0\n  }\n }\n}\n"
      "ROOT Prop\n{\n OFFSET 5 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      " End Site\n {\n  OFFSET 0 0 1\n }\n}\n"
      "MOTION\nFrames: 2\nFrame Time: 0.04\n"
      "1 2 3 0 0 0 30 0 0 0 0 0 5 0 0 0 0 0\n1 2 3 0 0 0 60 0 0 0 0 0 5 0 0 0 0 0\n";
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/walk.bvh", bvh);
  const KinemaRun run = runKinema({"convert", dir + "/walk.bvh", dir + "/walk.glb"}, dir);
  ASSERT_EQ(run.status, 0) << run.err;
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, dir + "/walk.glb")) << err;
  ASSERT_EQ(m.skins.size(), 2u);  // glTF asks a skin's joints to share a root: one per tree
  const std::vector<std::vector<std::string>> trees{{"Hips", "Spine", "Spine_End", "Leg", "Leg_End"},
                                                    {"Prop", "Prop_End"}};
  const std::vector<glm::dvec3> rest{{1, 2, 3}, {1, 3, 3}, {1, 3.5, 3}, {1.2, 1, 3}, {1.2, 0, 3}, {5, 0, 0}, {5, 0, 1}};
  const std::vector<glm::dmat4> world = nodeWorlds(m);
  size_t expectedIndex = 0;
  for (size_t s = 0; s < 2; ++s) {
    const tinygltf::Skin& skin = m.skins[s];
    EXPECT_EQ(skin.name, s == 0 ? "walk_Hips" : "walk_Prop");
    std::vector<std::string> names;
    for (int n : skin.joints) names.push_back(m.nodes[n].name);
    EXPECT_EQ(names, trees[s]);
    const tinygltf::Accessor& a = m.accessors[skin.inverseBindMatrices];
    ASSERT_EQ(a.type, TINYGLTF_TYPE_MAT4);
    ASSERT_EQ(a.count, skin.joints.size());
    const tinygltf::BufferView& v = m.bufferViews[a.bufferView];
    const float* ibm = reinterpret_cast<const float*>(m.buffers[v.buffer].data.data() + v.byteOffset + a.byteOffset);
    for (size_t k = 0; k < skin.joints.size(); ++k, ++expectedIndex) {
      // The rest pose's world matrix from the BVH OFFSETs (sums along the chain, by hand)
      // and from the glb's own nodes; the inverse bind matrix inverts both.
      const glm::dmat4 fromBvh = glm::translate(glm::dmat4(1.0), rest[expectedIndex]);
      glm::dmat4 inverseBind;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) inverseBind[c][r] = ibm[k * 16 + c * 4 + r];
      const glm::dmat4 a1 = inverseBind * fromBvh, a2 = inverseBind * world[skin.joints[k]];
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
          EXPECT_NEAR(a1[c][r], c == r ? 1.0 : 0.0, 1e-6) << names[k];
          EXPECT_NEAR(a2[c][r], c == r ? 1.0 : 0.0, 1e-6) << names[k];
        }
    }
  }
  // Read back by Kinema: the skeleton is unchanged and the skins name its joints.
  Result<Scene> back = loadScene(dir + "/walk.glb");
  ASSERT_TRUE(back.ok()) << back.error();
  Result<Scene> source = loadScene(dir + "/walk.bvh");
  ASSERT_TRUE(source.ok());
  expectSameSkeleton(source->skeleton, back->skeleton, "glb");
  ASSERT_EQ(back->skins.size(), 2u);
  // A scene that has skins keeps exactly those (glTF -> glTF adds none).
  std::vector<std::string> report;
  const Result<std::string> again = gltfBytes(back.value(), {true}, &report);
  ASSERT_TRUE(again.ok());
  tinygltf::Model m2;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&m2, &err, &warn, reinterpret_cast<const unsigned char*>(again->data()),
                                          static_cast<unsigned>(again->size())));
  EXPECT_EQ(m2.skins.size(), 2u);
  test::runCommand("rm -rf '" + dir + "'");
}

TEST(HostileWrite, BvhEndSitesContinueTheBoneWithItsLength) {
  // a -> b (0,2,0) -> c (3,0,0) turned 90 degrees about Z at rest: c is a leaf that is not an
  // End Site, so the writer adds one, 3 long and along the b -> c bone in world space
  // (an End Site written as c's offset in c's own turned frame would point along +Y).
  Skeleton s;
  s.addJoint("a", -1, Transform::identity());
  s.addJoint("b", 0, Transform::fromTranslation({0, 2, 0}));
  Transform c = Transform::fromTranslation({3, 0, 0});
  c.rotation = glm::angleAxis(3.14159265f / 2, glm::vec3(0, 0, 1));
  s.addJoint("c", 1, c);
  std::vector<std::string> report;
  const Result<std::string> text = bvhText(s, nullptr, {}, &report);
  ASSERT_TRUE(text.ok()) << text.error();
  ASSERT_FALSE(report.empty());
  EXPECT_NE(report.back().find("End Site as long as their bone"), std::string::npos) << report.back();
  Result<BvhData> back = parseBvh(text.value(), "c.bvh");
  ASSERT_TRUE(back.ok()) << back.error();
  const Skeleton sk = back->skeleton();
  const int end = sk.find("c_End");
  ASSERT_GE(end, 0);
  EXPECT_NEAR(glm::length(sk.rest[end].translation), 3.0f, 1e-5f);
  const std::vector<glm::mat4> world = computeWorld(sk, back->framePose(0));
  const glm::vec3 bone = glm::vec3(world[sk.find("c")][3]) - glm::vec3(world[sk.find("b")][3]);
  const glm::vec3 tail = glm::vec3(world[end][3]) - glm::vec3(world[sk.find("c")][3]);
  EXPECT_VEC3_NEAR(bone, glm::vec3(3, 0, 0), 1e-5f);
  EXPECT_VEC3_NEAR(tail, bone, 1e-5f);  // same direction and length
}

}  // namespace
}  // namespace kinema
