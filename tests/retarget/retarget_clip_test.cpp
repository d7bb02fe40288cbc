// Pose transfer: onto the same skeleton nothing changes, onto a scaled copy the motion
// scales, onto an A-posed copy with rolled bone axes the world bone directions agree.
#include <gtest/gtest.h>

#include "core/default_character.h"
#include "io/scene_files.h"
#include "retarget/retarget_clip.h"
#include "retarget/retarget_test_support.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

constexpr float kDegree = 0.01745329251994329577f;

Clip retarget(const Skeleton& s, const Clip& clip, const Skeleton& t, const BoneMap& map, int root, float scale,
              bool inPlace = false) {
  Clip out;
  RetargetJob job;
  job.source = &s;
  job.sourceClip = &clip;
  job.target = &t;
  job.map = &map;
  job.sourceRoot = job.targetRoot = root;
  job.rootScale = scale;
  job.inPlace = inPlace;
  job.output = &out;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

TEST(RetargetClip, OntoItsOwnSkeletonNothingChanges) {
  std::vector<std::pair<Skeleton, Clip>> takes;
  std::mt19937 rng(21);
  const Skeleton character = makeDefaultCharacter();
  takes.push_back({character, makeSmoothTake(character, 60, rng)});
  if (!sharedDataDir().empty()) {
    const Result<Scene> cmu = loadScene(sharedDataDir() + "/bvh/cmu_01_01_first720.bvh");
    ASSERT_TRUE(cmu.ok()) << cmu.error();
    takes.push_back({cmu->skeleton, cmu->clips[0]});
  }
  for (const auto& [s, clip] : takes) {
    const Clip out = retarget(s, clip, s, mapByIdenticalNames(s, s), 0, 1.0f);
    const float tolerance = 1e-6f * restHeight(s);
    const int frames = clipFrameCount(clip);
    ASSERT_EQ(clipFrameCount(out), frames);
    float worst = 0.0f;
    for (int f = 0; f < frames; ++f) {
      const std::vector<glm::mat4> a = worldAtFrame(s, clip, f), b = worldAtFrame(s, out, f);
      for (int j = 0; j < s.size(); ++j) worst = std::max(worst, glm::length(positionOf(a[j]) - positionOf(b[j])));
    }
    EXPECT_LE(worst, tolerance) << s.names[0] << ": height " << restHeight(s);
  }
}

TEST(RetargetClip, OntoAUniformlyScaledCopyTheMotionScales) {
  std::mt19937 rng(7);
  const Skeleton s = makeDefaultCharacter();
  const Clip clip = makeSmoothTake(s, 45, rng);
  const float k = 1.7f;
  Skeleton big = s;
  for (Transform& t : big.rest) t.translation *= k;
  const HumanoidMap hs = findHumanoid(s).value().bones, hb = findHumanoid(big).value().bones;
  const float scale = restHipHeight(big, hb).value() / restHipHeight(s, hs).value();
  EXPECT_NEAR(scale, k, 1e-5f);
  const Clip out = retarget(s, clip, big, mapThroughHumanoid(hs, hb), 0, scale);
  // Every mapped joint (and the joints they carry) is where the source's is, times k.
  float worst = 0.0f;
  for (int f = 0; f < clipFrameCount(clip); ++f) {
    const std::vector<glm::mat4> a = worldAtFrame(s, clip, f), b = worldAtFrame(big, out, f);
    // Unmapped end joints (HeadTop, the tips) follow their mapped parents.
    for (int j = 0; j < s.size(); ++j) worst = std::max(worst, glm::length(positionOf(b[j]) - k * positionOf(a[j])));
  }
  EXPECT_LE(worst, 1e-5f * k * restHeight(s));
}

TEST(RetargetClip, InPlaceDropsHorizontalRootMotion) {
  std::mt19937 rng(3);
  const Skeleton s = makeDefaultCharacter();
  const Clip clip = makeSmoothTake(s, 30, rng);
  const Clip out = retarget(s, clip, s, mapByIdenticalNames(s, s), 0, 1.0f, true);
  for (int f = 0; f < clipFrameCount(clip); ++f) {
    const glm::vec3 hips = positionOf(worldAtFrame(s, out, f)[0]);
    const glm::vec3 source = positionOf(worldAtFrame(s, clip, f)[0]);
    EXPECT_NEAR(hips.x, s.rest[0].translation.x, 1e-6f);
    EXPECT_NEAR(hips.z, s.rest[0].translation.z, 1e-6f);
    EXPECT_NEAR(hips.y, source.y, 1e-6f);
  }
}

// The copy: upper arms lowered by 40 degrees in the rest pose (A-pose), then every joint's
// axes rolled about its bone by a different angle, with the children turned back so that
// the rest positions stay where they were.
Skeleton aPoseRolledCopy(const Skeleton& s) {
  Skeleton t = s;
  for (const char* side : {".L", ".R"}) {
    const int arm = t.find(std::string("UpperArm") + side);
    const float sign = side[1] == 'L' ? -1.0f : 1.0f;  // left arm lies along +X: turn it down about -Z
    t.rest[arm].rotation = axisAngle(glm::vec3(0, 0, 1), sign * 40.0f * kDegree) * t.rest[arm].rotation;
  }
  for (int j = 0; j < t.size(); ++j) {
    glm::vec3 bone(0.0f);
    for (int c = 0; c < t.size(); ++c)
      if (t.parents[c] == j) bone = t.rest[c].translation;
    if (glm::length(bone) == 0.0f) bone = glm::vec3(0, 1, 0);
    const glm::quat roll = axisAngle(bone, (20.0f + 13.0f * static_cast<float>(j % 7)) * kDegree);
    t.rest[j].rotation = t.rest[j].rotation * roll;
    for (int c = 0; c < t.size(); ++c)
      if (t.parents[c] == j) {
        t.rest[c].translation = glm::conjugate(roll) * t.rest[c].translation;
        t.rest[c].rotation = glm::conjugate(roll) * t.rest[c].rotation;
      }
  }
  return t;
}

TEST(RetargetClip, APoseWithRolledAxesKeepsWorldBoneDirections) {
  const Skeleton s = makeDefaultCharacter();
  const Skeleton t = aPoseRolledCopy(s);
  // The copy really is A-posed: the left forearm's joint sits 40 degrees below the shoulder line.
  const std::vector<glm::mat4> rest = computeWorld(t, Pose::rest(t));
  const glm::vec3 d = positionOf(rest[t.find("LowerArm.L")]) - positionOf(rest[t.find("UpperArm.L")]);
  EXPECT_NEAR(std::atan2(-d.y, d.x), 40.0f * kDegree, 1e-4f);
  const HumanoidMap hs = findHumanoid(s).value().bones, ht = findHumanoid(t).value().bones;
  const BoneMap map = mapThroughHumanoid(hs, ht);
  const int cases = propertyCases(4);
  for (int c = 0; c < cases; ++c) {
    std::mt19937 rng(100 + c);
    const Clip clip = makeSmoothTake(s, 40, rng, 0.8f);
    const Clip out = retarget(s, clip, t, map, 0, 1.0f);
    float worst = 0.0f;
    for (int f = 0; f < clipFrameCount(clip); ++f) {
      const std::vector<glm::mat4> a = worldAtFrame(s, clip, f), b = worldAtFrame(t, out, f);
      // Every mapped joint's bone: towards each of its children.
      for (const BonePair& p : map.pairs)
        for (int child = 0; child < s.size(); ++child) {
          if (s.parents[child] != p.source) continue;
          const int tc = t.find(s.names[child]);
          const glm::vec3 ds = glm::normalize(positionOf(a[child]) - positionOf(a[p.source]));
          const glm::vec3 dt = glm::normalize(positionOf(b[tc]) - positionOf(b[p.target]));
          worst = std::max(worst, std::acos(std::min(1.0f, glm::dot(ds, dt))));
        }
    }
    EXPECT_LT(worst, 1.0f * kDegree) << "case " << c;
  }
}

TEST(RetargetClip, ValidateNamesTheProblem) {
  const Skeleton s = makeDefaultCharacter();
  std::mt19937 rng(1);
  const Clip clip = makeSmoothTake(s, 3, rng);
  BoneMap map = mapByIdenticalNames(s, s);
  Clip out;
  RetargetJob job;
  job.source = &s;
  job.sourceClip = &clip;
  job.target = &s;
  job.map = &map;
  job.output = &out;
  EXPECT_EQ(job.validate(), "");
  job.rootScale = 0.0f;
  EXPECT_NE(job.validate(), "");
  job.rootScale = 1.0f;
  map.pairs.push_back(map.pairs.front());
  EXPECT_NE(job.validate().find("mapped twice"), std::string::npos);
  EXPECT_FALSE(job.run());
}

TEST(RetargetClip, ZeroLengthLegsHaveNoHipHeight) {
  Skeleton s = makeDefaultCharacter();
  for (Transform& t : s.rest) t.translation.y = 0.0f;
  HumanoidMap h = findHumanoid(makeDefaultCharacter()).value().bones;
  const Result<float> r = restHipHeight(s, h);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("zero-length legs"), std::string::npos) << r.error();
}

}  // namespace
}  // namespace kinema::test
