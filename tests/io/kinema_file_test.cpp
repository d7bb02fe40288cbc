#include "io/kinema_file.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/default_character.h"
#include "core/rotation.h"
#include "io/bvh.h"
#include "io/scene_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::makeTempDir;
using test::readFile;
using test::writeFile;

// ---------------------------------------------------------------------------------------
// Bit-exact comparison of scenes.

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

uint64_t bits(double d) {
  uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  return u;
}

// Compares bit patterns (so -0 differs from +0 and nothing is "close enough").
#define EXPECT_SAME_BITS(a, b, where) EXPECT_EQ(bits(a), bits(b)) << (where) << ": " << (a) << " vs " << (b)

void expectSameFloats(const float* a, const float* b, int n, const std::string& where) {
  for (int i = 0; i < n; ++i) EXPECT_SAME_BITS(a[i], b[i], where + "[" + std::to_string(i) + "]");
}

void expectSameScene(const Scene& want, const Scene& got) {
  const Skeleton& a = want.skeleton;
  const Skeleton& b = got.skeleton;
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.names, b.names);
  EXPECT_EQ(a.parents, b.parents);
  ASSERT_EQ(b.rest.size(), a.rest.size());
  for (int i = 0; i < a.size(); ++i) {
    const std::string w = "joint " + std::to_string(i);
    expectSameFloats(&a.rest[i].translation.x, &b.rest[i].translation.x, 3, w + " translation");
    const float qa[4] = {a.rest[i].rotation.x, a.rest[i].rotation.y, a.rest[i].rotation.z, a.rest[i].rotation.w};
    const float qb[4] = {b.rest[i].rotation.x, b.rest[i].rotation.y, b.rest[i].rotation.z, b.rest[i].rotation.w};
    expectSameFloats(qa, qb, 4, w + " rotation");
    expectSameFloats(&a.rest[i].scale.x, &b.rest[i].scale.x, 3, w + " scale");
  }
  ASSERT_EQ(want.clips.size(), got.clips.size());
  for (size_t c = 0; c < want.clips.size(); ++c) {
    const Clip& ca = want.clips[c];
    const Clip& cb = got.clips[c];
    const std::string wc = "clip " + std::to_string(c);
    EXPECT_EQ(ca.name, cb.name) << wc;
    EXPECT_SAME_BITS(ca.frameTime, cb.frameTime, wc + " frame_time");
    ASSERT_EQ(ca.channels.size(), cb.channels.size()) << wc;
    for (size_t k = 0; k < ca.channels.size(); ++k) {
      const Channel& x = ca.channels[k];
      const Channel& y = cb.channels[k];
      const std::string w = wc + " channel " + std::to_string(k);
      EXPECT_EQ(x.joint, y.joint) << w;
      EXPECT_EQ(x.target, y.target) << w;
      EXPECT_EQ(x.interpolation, y.interpolation) << w;
      ASSERT_EQ(x.times.size(), y.times.size()) << w;
      ASSERT_EQ(x.values.size(), y.values.size()) << w;
      expectSameFloats(x.times.data(), y.times.data(), static_cast<int>(x.times.size()), w + " times");
      // Translation and scale keys have w = 0 in memory (the file has no fourth number).
      for (size_t i = 0; i < x.values.size(); ++i)
        expectSameFloats(&x.values[i].x, &y.values[i].x, 4, w + " values[" + std::to_string(i) + "]");
    }
  }
}

// Saves to a real file, loads it back through loadScene, compares bit for bit.
void expectFileRoundTrip(const Scene& scene) {
  const std::string dir = makeTempDir();
  ASSERT_FALSE(dir.empty());
  const std::string path = dir + "/scene.kinema";
  ASSERT_EQ(saveKinemaFile(path, scene), "");
  const Result<Scene> loaded = loadScene(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->source, path);
  expectSameScene(scene, loaded.value());
  // The loaded scene writes the very same bytes again.
  EXPECT_EQ(toKinemaJson(loaded.value()), readFile(path));
  std::remove(path.c_str());
  ::rmdir(dir.c_str());
}

glm::vec4 v3(float x, float y, float z) { return glm::vec4(x, y, z, 0.0f); }
glm::vec4 q4(const glm::quat& q) { return glm::vec4(q.x, q.y, q.z, q.w); }

// One channel of every target and interpolation mode, with awkward numbers (0.1, 1/3,
// negative zero, tiny and huge magnitudes) that only survive when floats are written in
// full.
std::vector<Clip> awkwardClips(const Skeleton& s) {
  Clip a;
  a.name = "walk \"fast\" \\ \u00e9\u6b69";
  a.frameTime = 1.0 / 30.0;
  const glm::quat r1 = glm::normalize(glm::quat(0.9f, 0.1f, -0.3f, 1.0f / 3.0f));
  const glm::quat r2 = axisAngle(glm::vec3(0.0f, 1.0f, 0.0f), 0.7f);
  a.channels.push_back({0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 0.1f, 1.0f / 3.0f},
                        {v3(0.1f, -0.0f, 1e-30f), v3(3.0e38f, -1.0f / 3.0f, 1e-45f), v3(7.0f, 8.0f, 9.0f)}});
  a.channels.push_back({s.size() - 1, ChannelTarget::Rotation, Interpolation::Step, {0.25f, 0.5f},
                        {q4(r1), q4(r2)}});
  a.channels.push_back({s.size() / 2, ChannelTarget::Scale, Interpolation::Step, {-0.5f}, {v3(2.0f, 0.5f, 1.1f)}});
  a.channels.push_back({s.size() / 2, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 1e-7f, 1e6f},
                        {q4(r2), q4(r1), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)}});
  a.channels.push_back({1, ChannelTarget::Translation, Interpolation::Step, {2.0f}, {v3(-0.0f, 0.0f, -7.5f)}});
  a.channels.push_back({1, ChannelTarget::Scale, Interpolation::Linear, {0.0f, 0.016666668f},
                        {v3(1.0f, 1.0f, 1.0f), v3(0.3f, 0.7f, 16777217.0f)}});
  Clip b;  // no frame grid, no channels
  b.name = "";
  return {a, b};
}

TEST(KinemaFile, DefaultCharacterRoundTripsExactly) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  ASSERT_GE(scene.skeleton.size(), 3);
  expectFileRoundTrip(scene);
  scene.clips = awkwardClips(scene.skeleton);
  expectFileRoundTrip(scene);
}

TEST(KinemaFile, DefaultCharacterWithPosedRestRoundTripsExactly) {
  // Non-identity rest rotations and non-unit scales as well.
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  for (int i = 0; i < scene.skeleton.size(); ++i) {
    Transform& t = scene.skeleton.rest[i];
    t.rotation = axisAngle(glm::vec3(1.0f, 2.0f, 3.0f + i), 0.1f * i);
    t.scale = glm::vec3(1.0f + 0.1f * i, 1.0f / (i + 3), 0.3f);
  }
  scene.clips = awkwardClips(scene.skeleton);
  expectFileRoundTrip(scene);
}

const char* kSmallBvh =
    "HIERARCHY\n"
    "ROOT Hips\n"
    "{\n"
    "  OFFSET 0.00 0.00 0.00\n"
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "  JOINT Chest\n"
    "  {\n"
    "    OFFSET 0.0 5.21 -0.1\n"
    "    CHANNELS 3 Zrotation Xrotation Yrotation\n"
    "    JOINT Head\n"
    "    {\n"
    "      OFFSET 0.0 4.3 0.33\n"
    "      CHANNELS 3 Yrotation Xrotation Zrotation\n"
    "      End Site\n"
    "      {\n"
    "        OFFSET 0.0 1.7 0.0\n"
    "      }\n"
    "    }\n"
    "  }\n"
    "  JOINT LeftLeg\n"
    "  {\n"
    "    OFFSET 3.1 -0.5 0.0\n"
    "    CHANNELS 3 Xrotation Yrotation Zrotation\n"
    "    End Site\n"
    "    {\n"
    "      OFFSET 0.0 -8.0 0.0\n"
    "    }\n"
    "  }\n"
    "}\n"
    "MOTION\n"
    "Frames: 3\n"
    "Frame Time: .0333333\n"
    "1.5 20.1 -3.3 10 20 30 -5 0.1 45 90 -90 0.5 12.25 -33.3 179.9\n"
    "1.6 20.0 -3.2 11 21 31 -6 0.2 44 89 -89 0.6 12.5 -33.2 -179.9\n"
    "1.7 19.9 -3.1 12 22 32 -7 0.3 43 88 -88 0.7 12.75 -33.1 0.0\n";

TEST(KinemaFile, BvhSceneRoundTripsExactly) {
  const Result<BvhData> bvh = parseBvh(kSmallBvh, "small.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.error();
  Scene scene;
  scene.skeleton = bvh->skeleton();
  scene.clips.push_back(bvh->clip());
  // 4 joints + 2 End Sites; a translation channel on Hips, rotation on the 4 joints.
  ASSERT_EQ(scene.skeleton.size(), 6);
  ASSERT_EQ(scene.clips[0].channels.size(), 5u);
  EXPECT_EQ(scene.clips[0].frameTime, 0.0333333);
  expectFileRoundTrip(scene);
}

// ---------------------------------------------------------------------------------------
// Random scenes.

class Gen {
 public:
  explicit Gen(uint32_t seed) : rng_(seed) {}
  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  float real(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
  // Any finite float, every exponent equally likely (subnormals, -0 and values near
  // FLT_MAX included), half the time a "nice" number instead.
  float anyFloat() {
    if (uniform(0, 1) == 0) return real(-10.0f, 10.0f);
    for (;;) {
      const uint32_t u = static_cast<uint32_t>(rng_());
      float f;
      std::memcpy(&f, &u, sizeof f);
      if (std::isfinite(f)) return f;
    }
  }
  glm::vec3 anyVec3() { return glm::vec3(anyFloat(), anyFloat(), anyFloat()); }
  glm::quat unitQuat() {
    for (;;) {
      const glm::quat q(real(-1, 1), real(-1, 1), real(-1, 1), real(-1, 1));
      const float len2 = glm::dot(q, q);
      if (len2 > 0.01f && len2 <= 1.0f) return glm::normalize(q);
    }
  }
  std::string name(int index) {
    static const char* pieces[] = {"a", "Z", "_", " ", ".", "\"", "\\", "/", "\t", "\u00e9", "\u6b69",
                                   "\U0001F600", "L", "R", "0", "9", "\x01"};
    std::string s;
    const int n = uniform(0, 6);
    for (int i = 0; i < n; ++i) s += pieces[uniform(0, static_cast<int>(std::size(pieces)) - 1)];
    return s + "#" + std::to_string(index);  // unique and never empty
  }

 private:
  std::mt19937 rng_;
};

Scene randomScene(Gen& g) {
  Scene scene;
  const int n = g.uniform(1, 40);
  for (int i = 0; i < n; ++i) {
    Transform t;
    t.translation = g.anyVec3();
    t.rotation = g.unitQuat();
    t.scale = g.uniform(0, 3) == 0 ? glm::vec3(1.0f) : g.anyVec3();
    scene.skeleton.addJoint(g.name(i), i == 0 ? -1 : g.uniform(-1, i - 1), t);
  }
  const int clips = g.uniform(0, 3);
  for (int c = 0; c < clips; ++c) {
    Clip clip;
    clip.name = g.name(c);
    clip.frameTime = g.uniform(0, 1) ? 0.0 : 1.0 / g.uniform(1, 240);
    const int channels = g.uniform(0, 6);
    for (int k = 0; k < channels; ++k) {
      Channel ch;
      ch.joint = g.uniform(0, n - 1);
      ch.target = static_cast<ChannelTarget>(g.uniform(0, 2));
      ch.interpolation = static_cast<Interpolation>(g.uniform(0, 1));
      float t = g.real(-5.0f, 5.0f);
      const int keys = g.uniform(1, 8);
      for (int i = 0; i < keys; ++i) {
        ch.times.push_back(t);
        t = std::nextafter(t, 1e30f) + (g.uniform(0, 2) == 0 ? 0.0f : g.real(0.0f, 2.0f));
        ch.values.push_back(ch.target == ChannelTarget::Rotation ? q4(g.unitQuat()) : glm::vec4(g.anyVec3(), 0.0f));
      }
      clip.channels.push_back(std::move(ch));
    }
    scene.clips.push_back(std::move(clip));
  }
  return scene;
}

TEST(KinemaFile, RandomScenesRoundTripExactly) {
  const int cases = test::propertyCases(200);
  Gen g(20240611u);
  for (int c = 0; c < cases; ++c) {
    SCOPED_TRACE("case " + std::to_string(c));
    const Scene scene = randomScene(g);
    ASSERT_EQ(scene.skeleton.validate(), "");
    const std::string text = toKinemaJson(scene);
    const Result<Scene> loaded = parseKinemaJson(text, "random.kinema");
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    expectSameScene(scene, loaded.value());
    ASSERT_EQ(toKinemaJson(loaded.value()), text);
    if (HasFatalFailure() || HasNonfatalFailure()) break;
  }
}

TEST(KinemaFile, RandomSceneFilesRoundTripExactly) {
  Gen g(7u);
  for (int c = 0; c < 5; ++c) expectFileRoundTrip(randomScene(g));
}

TEST(KinemaFile, ExtremeFloatsRoundTrip) {
  Scene scene;
  const float max = std::numeric_limits<float>::max();
  const float denormMin = std::numeric_limits<float>::denorm_min();
  Transform t;
  t.translation = glm::vec3(max, -max, denormMin);
  t.scale = glm::vec3(-0.0f, std::numeric_limits<float>::min(), 3.3e38f);
  scene.skeleton.addJoint("root", -1, t);
  expectFileRoundTrip(scene);
}

TEST(KinemaFile, SavingTwiceGivesIdenticalBytes) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  scene.clips = awkwardClips(scene.skeleton);
  const std::string dir = makeTempDir();
  const std::string a = dir + "/a.kinema", b = dir + "/b.kinema";
  ASSERT_EQ(saveKinemaFile(a, scene), "");
  const std::string first = readFile(a);
  ASSERT_EQ(saveKinemaFile(a, scene), "");
  ASSERT_EQ(saveKinemaFile(b, scene), "");
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(readFile(a), first);
  EXPECT_EQ(readFile(b), first);
  EXPECT_EQ(toKinemaJson(scene), first);
  test::runCommand("rm -rf '" + dir + "'");
}

TEST(KinemaFile, FileStartsWithFormatAndVersion) {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  const std::string text = toKinemaJson(scene);
  const size_t format = text.find("\"format\"");
  const size_t version = text.find("\"version\"");
  ASSERT_NE(format, std::string::npos);
  ASSERT_NE(version, std::string::npos);
  EXPECT_LT(format, version);
  EXPECT_LT(version, text.find("\"skeleton\""));
  EXPECT_EQ(text.back(), '\n');
}

// ---------------------------------------------------------------------------------------
// Reading: normalisation and defaults.

TEST(KinemaFile, NonUnitRotationsAreNormalisedOnLoad) {
  const std::string text = R"({"format":"kinema","version":1,
    "skeleton":{"joints":[
      {"name":"a","parent":-1,"rotation":[0,0,0,2]},
      {"name":"b","parent":0,"rotation":[0,3,0,4]}]},
    "clips":[{"name":"c","channels":[
      {"joint":"b","target":"rotation","times":[0,1],"values":[[0,0,-5,0],[1,1,1,1]]}]}]})";
  const Result<Scene> s = parseKinemaJson(text, "n.kinema");
  ASSERT_TRUE(s.ok()) << s.error();
  // |(0,0,0,2)| = 2 -> identity; |(0,3,0,4)| = 5 -> (0, .6, 0, .8).
  const glm::quat a = s->skeleton.rest[0].rotation;
  EXPECT_FLOAT_EQ(a.w, 1.0f);
  EXPECT_FLOAT_EQ(a.x, 0.0f);
  EXPECT_FLOAT_EQ(a.y, 0.0f);
  EXPECT_FLOAT_EQ(a.z, 0.0f);
  const glm::quat b = s->skeleton.rest[1].rotation;
  EXPECT_FLOAT_EQ(b.x, 0.0f);
  EXPECT_FLOAT_EQ(b.y, 0.6f);
  EXPECT_FLOAT_EQ(b.z, 0.0f);
  EXPECT_FLOAT_EQ(b.w, 0.8f);
  // Keys: (0,0,-5,0) -> (0,0,-1,0); (1,1,1,1) -> (.5,.5,.5,.5).
  const Channel& ch = s->clips.at(0).channels.at(0);
  EXPECT_FLOAT_EQ(ch.values[0].z, -1.0f);
  EXPECT_FLOAT_EQ(ch.values[0].w, 0.0f);
  for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(ch.values[1][i], 0.5f);
  // Defaults: no translation/scale given -> zero and one; no interpolation -> linear.
  EXPECT_EQ(s->skeleton.rest[1].translation, glm::vec3(0.0f));
  EXPECT_EQ(s->skeleton.rest[1].scale, glm::vec3(1.0f));
  EXPECT_EQ(ch.interpolation, Interpolation::Linear);
  EXPECT_EQ(s->clips[0].frameTime, 0.0);
}

// Found by a 10-minute fuzz_kinema_file run: a key like [7.7e26, 0.63, 0.21, 0.67] is
// finite, but its squared length overflows float, so glm::normalize gave (0, 0, 0, 0),
// which saved as a "zero quaternion" the reader then refused. Huge and tiny quaternions
// must normalise to unit length and save/load/save identically.
TEST(KinemaFile, HugeAndTinyQuaternionsNormaliseAndRoundTrip) {
  const std::string text = R"({"format":"kinema","version":1,
    "skeleton":{"joints":[
      {"name":"a","parent":-1,"rotation":[3e30,0,0,4e30]},
      {"name":"b","parent":0,"rotation":[0,3e-30,0,4e-30]}]},
    "clips":[{"name":"c","channels":[
      {"joint":"b","target":"rotation","times":[0,1],"values":[[7.7e26,0,0,0],[0,0,-2e-38,0]]}]}]})";
  const Result<Scene> s = parseKinemaJson(text, "huge.kinema");
  ASSERT_TRUE(s.ok()) << s.error();
  // |(3,0,0,4)| = 5 at any scale: (0.6, 0, 0, 0.8) and (0, 0.6, 0, 0.8).
  const glm::quat a = s->skeleton.rest[0].rotation, b = s->skeleton.rest[1].rotation;
  EXPECT_NEAR(a.x, 0.6f, 1e-6f);
  EXPECT_NEAR(a.w, 0.8f, 1e-6f);
  EXPECT_NEAR(b.y, 0.6f, 1e-6f);
  EXPECT_NEAR(b.w, 0.8f, 1e-6f);
  const Channel& ch = s->clips.at(0).channels.at(0);
  EXPECT_EQ(ch.values[0], glm::vec4(1, 0, 0, 0));
  EXPECT_EQ(ch.values[1], glm::vec4(0, 0, -1, 0));
  const std::string saved = toKinemaJson(s.value());
  const Result<Scene> back = parseKinemaJson(saved, "huge.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(toKinemaJson(back.value()), saved);
}

TEST(KinemaFile, MinimalFileLoadsWithoutClips) {
  const Result<Scene> s =
      parseKinemaJson(R"({"format":"kinema","version":1,"skeleton":{"joints":[{"name":"r","parent":-1}]}})", "m");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s->skeleton.size(), 1);
  EXPECT_TRUE(s->clips.empty());
}

// ---------------------------------------------------------------------------------------
// Errors: one line, starting with the file name, naming the JSON path.

// A valid file with four joints and one clip of two channels, with `edit` applied by
// plain text replacement (so each case shows exactly what is wrong).
std::string baseFile() {
  return R"({
  "format": "kinema",
  "version": 1,
  "skeleton": {"joints": [
    {"name": "root", "parent": -1, "translation": [0, 1, 0]},
    {"name": "spine", "parent": 0, "translation": [0, 0.5, 0], "rotation": [0, 0, 0, 1]},
    {"name": "head", "parent": 1, "translation": [0, 0.4, 0], "scale": [1, 1, 1]},
    {"name": "arm", "parent": 1, "translation": [0.2, 0.3, 0]}
  ]},
  "clips": [{"name": "wave", "frame_time": 0.5, "channels": [
    {"joint": "arm", "target": "rotation", "interpolation": "linear",
     "times": [0, 0.5, 1], "values": [[0, 0, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]},
    {"joint": "head", "target": "translation", "interpolation": "step",
     "times": [0, 1], "values": [[0, 0.4, 0], [0, 0.5, 0]]}
  ]}]
})";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' is not in the base file";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

struct ErrorCase {
  const char* what;
  std::string text;
  std::vector<std::string> mustContain;
};

std::vector<ErrorCase> errorCases() {
  const std::string f = baseFile();
  return {
      {"parent is a string", replaced(f, R"("name": "arm", "parent": 1)", R"("name": "arm", "parent": "spine")"),
       {"skeleton.joints[3].parent", "integer", "string"}},
      {"parent is a float", replaced(f, R"("name": "arm", "parent": 1)", R"("name": "arm", "parent": 1.5)"),
       {"skeleton.joints[3].parent", "integer"}},
      {"parent refers to a later joint", replaced(f, R"("name": "head", "parent": 1)", R"("name": "head", "parent": 3)"),
       {"skeleton.joints[2].parent", "3"}},
      {"parent refers to itself", replaced(f, R"("name": "head", "parent": 1)", R"("name": "head", "parent": 2)"),
       {"skeleton.joints[2].parent"}},
      {"parent below -1", replaced(f, R"("name": "head", "parent": 1)", R"("name": "head", "parent": -2)"),
       {"skeleton.joints[2].parent", "-2"}},
      {"parent 2^64-1 (not -1 in disguise)",
       replaced(f, R"("name": "head", "parent": 1)", R"("name": "head", "parent": 18446744073709551615)"),
       {"skeleton.joints[2].parent"}},
      {"parent missing", replaced(f, R"("name": "arm", "parent": 1,)", R"("name": "arm",)"),
       {"skeleton.joints[3].parent", "missing"}},
      {"duplicate names", replaced(f, R"("name": "arm")", R"("name": "spine")"),
       {"skeleton.joints[3].name", "spine"}},
      {"empty name", replaced(f, R"("name": "arm")", R"("name": "")"), {"skeleton.joints[3].name"}},
      {"missing format", replaced(f, R"("format": "kinema",)", ""), {"format", "missing"}},
      {"other format", replaced(f, R"("format": "kinema")", R"("format": "gltf")"), {"format", "gltf"}},
      {"missing version", replaced(f, R"("version": 1,)", ""), {"version", "missing"}},
      {"newer version", replaced(f, R"("version": 1)", R"("version": 2)"), {"version", "2", "newer"}},
      {"version 0", replaced(f, R"("version": 1)", R"("version": 0)"), {"version", "0"}},
      {"version as string", replaced(f, R"("version": 1)", R"("version": "1")"), {"version", "integer"}},
      {"syntax: missing comma", replaced(f, R"("version": 1,)", R"("version": 1)"), {"not valid JSON", "line 4"}},
      {"syntax: truncated", f.substr(0, f.size() / 2), {"not valid JSON"}},
      {"syntax: empty file", "", {"not valid JSON"}},
      {"syntax: control character in string", replaced(f, R"("wave")", "\"wa\nve\""), {"not valid JSON"}},
      {"top level is an array", "[1, 2]", {"object"}},
      {"skeleton missing", R"({"format": "kinema", "version": 1})", {"skeleton", "missing"}},
      {"joints not an array", R"({"format": "kinema", "version": 1, "skeleton": {"joints": 3}})",
       {"skeleton.joints", "array"}},
      {"unknown joint in channel", replaced(f, R"("joint": "head")", R"("joint": "neck")"),
       {"clips[0].channels[1].joint", "neck"}},
      {"unknown target", replaced(f, R"("target": "translation")", R"("target": "position")"),
       {"clips[0].channels[1].target", "position"}},
      {"unknown interpolation", replaced(f, R"("interpolation": "step")", R"("interpolation": "cubic")"),
       {"clips[0].channels[1].interpolation", "cubic"}},
      {"times decrease", replaced(f, R"("times": [0, 0.5, 1])", R"("times": [0, 1, 0.5])"),
       {"clips[0].channels[0].times[2]", "increase"}},
      {"times repeat", replaced(f, R"("times": [0, 0.5, 1])", R"("times": [0, 0.5, 0.5])"),
       {"clips[0].channels[0].times[2]"}},
      {"times equal once rounded to float",
       replaced(f, R"("times": [0, 0.5, 1])", R"("times": [0, 1, 1.00000001])"), {"clips[0].channels[0].times[2]"}},
      {"times empty", replaced(f, R"("times": [0, 1])", R"("times": [])"), {"clips[0].channels[1].times"}},
      {"fewer values than times", replaced(f, R"([[0, 0.4, 0], [0, 0.5, 0]])", R"([[0, 0.4, 0]])"),
       {"clips[0].channels[1].values", "2"}},
      {"value of the wrong size", replaced(f, R"([[0, 0.4, 0], [0, 0.5, 0]])", R"([[0, 0.4, 0], [0, 0.5]])"),
       {"clips[0].channels[1].values[1]", "3"}},
      {"rotation value with 3 numbers", replaced(f, R"([0, 0, 1, 0])", R"([0, 0, 1])"),
       {"clips[0].channels[0].values[1]", "4"}},
      {"zero quaternion key", replaced(f, R"([0, 0, 1, 0])", R"([0, 0, 0, 0])"),
       {"clips[0].channels[0].values[1]", "zero"}},
      {"zero rest rotation", replaced(f, R"("rotation": [0, 0, 0, 1])", R"("rotation": [0, 0, 0, 0])"),
       {"skeleton.joints[1].rotation", "zero"}},
      {"huge translation", replaced(f, R"([0.2, 0.3, 0])", R"([1e39, 0.3, 0])"),
       {"skeleton.joints[3].translation[0]", "range"}},
      {"huge negative scale", replaced(f, R"("scale": [1, 1, 1])", R"("scale": [1, 1, -1e39])"),
       {"skeleton.joints[2].scale[2]"}},
      {"huge key value", replaced(f, R"([0, 0.5, 0]])", R"([0, 1e39, 0]])"), {"clips[0].channels[1].values[1][1]"}},
      {"huge key time", replaced(f, R"("times": [0, 1])", R"("times": [0, 1e39])"), {"clips[0].channels[1].times[1]"}},
      {"overflowing double", replaced(f, R"([0.2, 0.3, 0])", R"([0.2, 1e400, 0])"), {}},
      {"number as a string", replaced(f, R"([0.2, 0.3, 0])", R"([0.2, "0.3", 0])"),
       {"skeleton.joints[3].translation[1]", "number"}},
      {"negative frame time", replaced(f, R"("frame_time": 0.5)", R"("frame_time": -0.5)"),
       {"clips[0].frame_time"}},
      {"clip name not a string", replaced(f, R"("name": "wave")", R"("name": 7)"), {"clips[0].name"}},
      {"channels missing", replaced(f, R"("name": "wave", "frame_time": 0.5, "channels")",
                                    R"("name": "wave", "frame_time": 0.5, "channelz")"),
       {"clips[0].channels", "missing"}},
      {"joint name with a newline in a message",
       replaced(f, R"("joint": "head")", R"("joint": "he\nad")"), {"clips[0].channels[1].joint"}},
  };
}

TEST(KinemaFile, BaseFileOfTheErrorCasesIsValid) {
  // Otherwise the error cases below would prove nothing.
  const Result<Scene> s = parseKinemaJson(baseFile(), "base.kinema");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s->skeleton.size(), 4);
  ASSERT_EQ(s->clips.size(), 1u);
  EXPECT_EQ(s->clips[0].channels.size(), 2u);
  EXPECT_EQ(s->clips[0].frameTime, 0.5);
}

void expectOneLineError(const std::string& error, const std::string& source, const std::string& what) {
  EXPECT_FALSE(error.empty()) << what;
  EXPECT_EQ(error.find('\n'), std::string::npos) << what << ": " << error;
  EXPECT_EQ(error.find('\r'), std::string::npos) << what << ": " << error;
  EXPECT_EQ(error.rfind(source + ": ", 0), 0u) << what << ": " << error;
}

TEST(KinemaFile, ErrorsNameTheFileAndTheJsonPath) {
  for (const ErrorCase& c : errorCases()) {
    const Result<Scene> s = parseKinemaJson(c.text, "walk.kinema");
    ASSERT_FALSE(s.ok()) << c.what << " was accepted";
    expectOneLineError(s.error(), "walk.kinema", c.what);
    for (const std::string& part : c.mustContain)
      EXPECT_NE(s.error().find(part), std::string::npos) << c.what << ": '" << part << "' not in: " << s.error();
  }
}

TEST(KinemaFile, ErrorsFromFilesStartWithThePath) {
  const std::string dir = makeTempDir();
  const std::string path = dir + "/bad.kinema";
  writeFile(path, replaced(baseFile(), R"("name": "arm", "parent": 1)", R"("name": "arm", "parent": "spine")"));
  const Result<Scene> viaLoad = loadKinemaFile(path);
  ASSERT_FALSE(viaLoad.ok());
  expectOneLineError(viaLoad.error(), path, "loadKinemaFile");
  EXPECT_NE(viaLoad.error().find("skeleton.joints[3].parent"), std::string::npos) << viaLoad.error();
  const Result<Scene> viaScene = loadScene(path);
  ASSERT_FALSE(viaScene.ok());
  EXPECT_EQ(viaScene.error(), viaLoad.error());

  const Result<Scene> missing = loadScene(dir + "/absent.kinema");
  ASSERT_FALSE(missing.ok());
  expectOneLineError(missing.error(), dir + "/absent.kinema", "missing file");
  test::runCommand("rm -rf '" + dir + "'");
}

TEST(KinemaFile, LoadSceneDispatchesOnExtension) {
  const std::string dir = makeTempDir();
  const std::string text = baseFile();
  for (const char* name : {"/x.kinema", "/UPPER.KINEMA"}) {
    writeFile(dir + name, text);
    const Result<Scene> s = loadScene(dir + name);
    ASSERT_TRUE(s.ok()) << name << ": " << s.error();
    EXPECT_EQ(s->skeleton.size(), 4) << name;
    EXPECT_EQ(s->source, dir + name);
  }
  // The same valid .kinema text under other names is refused with a clear message.
  for (const char* name : {"/x.json", "/x.obj", "/noextension", "/x.kinema.bak"}) {
    writeFile(dir + name, text);
    const Result<Scene> s = loadScene(dir + name);
    ASSERT_FALSE(s.ok()) << name;
    expectOneLineError(s.error(), dir + name, name);
    EXPECT_NE(s.error().find(".kinema"), std::string::npos) << s.error();
    EXPECT_NE(s.error().find(".bvh"), std::string::npos) << s.error();
  }
  // A .bvh goes to the BVH reader (a .kinema text there is a BVH error, not accepted).
  writeFile(dir + "/k.bvh", text);
  EXPECT_FALSE(loadScene(dir + "/k.bvh").ok());
  writeFile(dir + "/small.bvh", kSmallBvh);
  const Result<Scene> bvh = loadScene(dir + "/small.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.error();
  EXPECT_EQ(bvh->skeleton.size(), 6);
  test::runCommand("rm -rf '" + dir + "'");
}

TEST(KinemaFile, InvalidUtf8NameIsAnErrorNotACrash) {
  Scene scene;
  scene.skeleton.addJoint("H\xfc""fte", -1, Transform{});  // Latin-1, as old BVH files have
  const std::string dir = makeTempDir();
  const std::string path = dir + "/latin1.kinema";
  writeFile(path, "previous");
  const std::string error = saveKinemaFile(path, scene);
  EXPECT_FALSE(error.empty());
  expectOneLineError(error, path, "invalid UTF-8");
  EXPECT_EQ(readFile(path), "previous");
  test::runCommand("rm -rf '" + dir + "'");
}

}  // namespace
}  // namespace kinema
