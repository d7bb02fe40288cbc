// The IK's fast paths against the general code they shortcut, bit for bit:
// - IkProblem::validate's two parts (ik_chain.h): the plain check, which builds no
//   message, may say yes only where the full checks find nothing; validate() then gives
//   the full checks' answer on every problem. Random trees, targets and corruptions of each
//   checked field (indices out of range or off the chain, NaN and infinite numbers, zero
//   weight).
// - IkChain's FK along one target's path against its general FK.
// - solveTwoBone's one-pass case (one target, no rig, no trace) against its general loop.
// - TwoBoneIkJob's SSE geometry against its glm scalar one.
// (CCD's and FABRIK's plain sweeps and passes against the general ones: IkSolvers'
// TraceRecordsEveryStepAndChangesNothing, since a trace takes the general code.)
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include "ik/ik_chain.h"
#include "ik/ik_solver.h"
#include "ik/two_bone_job_core.h"
#include "ik_test_chains.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(IkFastPaths, ValidatePlainCheckSaysYesOnlyWhereTheFullChecksPass) {
  std::mt19937 rng(20);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  int plain = 0, invalid = 0;
  for (int k = 0; k < 4000; ++k) {
    // A random tree of 2..12 joints (each parent an earlier joint, mostly the previous).
    Skeleton s;
    const int n = 2 + static_cast<int>(rng() % 11);
    for (int i = 0; i < n; ++i) {
      const int parent = i == 0 ? -1 : (rng() % 4 ? i - 1 : static_cast<int>(rng() % i));
      s.addJoint("j" + std::to_string(i), parent, Transform::fromTranslation({0.0f, 1.0f, 0.0f}));
    }
    Pose pose = Pose::rest(s);
    IkProblem p;
    p.skeleton = &s;
    p.pose = &pose;
    const int targets = 1 + static_cast<int>(rng() % 2);
    for (int t = 0; t < targets; ++t) {
      IkTarget target;
      target.effector = static_cast<int>(rng() % n);
      // Root, middle joint: default, an ancestor, or any joint (often not an ancestor).
      auto pick = [&](int def) {
        const int r = static_cast<int>(rng() % 3);
        if (r == 0) return def;
        int j = target.effector;
        if (r == 1)
          for (int up = static_cast<int>(rng() % 4); up > 0 && s.parents[j] >= 0; --up) j = s.parents[j];
        else
          j = static_cast<int>(rng() % n);
        return j;
      };
      target.root = pick(-1);
      target.mid = pick(-1);
      target.position = {1.0f, 2.0f, 0.5f};
      target.hasOrientation = rng() % 2;
      target.hasPole = rng() % 2;
      p.targets.push_back(target);
    }
    // One corruption in most cases.
    IkTarget& t = p.targets[0];
    const int joint = static_cast<int>(rng() % n);
    switch (rng() % 16) {
      case 0: t.effector = n + static_cast<int>(rng() % 3); break;
      case 1: t.root = n; break;
      case 2: t.mid = n; break;
      case 3: t.position.y = rng() % 2 ? nan : inf; break;
      case 4: t.orientation = glm::quat(0.0f, 0.0f, 0.0f, 0.0f); break;
      case 5: t.orientation.w = nan; break;
      case 6: t.weight = rng() % 2 ? 0.0f : nan; break;
      case 7: t.pole.z = inf; break;
      case 8: pose.local[joint].translation.x = nan; break;
      case 9: pose.local[joint].rotation.z = inf; break;
      case 10: pose.local[joint].scale.y = nan; break;
      case 11: p.rootTransform[rng() % 4][rng() % 3] = nan; break;
      case 12: pose.local.pop_back(); break;
      case 13: p.targets.clear(); break;
      default: break;
    }
    for (bool twoBone : {false, true}) {
      const std::string full = ik_detail::validateInFull(p, twoBone);
      if (ik_detail::plainlyValid(p, twoBone)) {
        ++plain;
        EXPECT_EQ(full, "") << "case " << k << (twoBone ? " (two-bone)" : "");
      }
      invalid += !full.empty();
      EXPECT_EQ(p.validate(twoBone), full) << "case " << k;
    }
  }
  // Both kinds were met often.
  EXPECT_GT(plain, 500);
  EXPECT_GT(invalid, 1000);
}

TEST(IkFastPaths, ValidateARigGoesThroughTheFullChecks) {
  Skeleton s;
  for (int i = 0; i < 3; ++i) s.addJoint("j" + std::to_string(i), i - 1, Transform::fromTranslation({0, 1, 0}));
  Pose pose = Pose::rest(s);
  IkRig rig;
  rig.limits.resize(2);  // one short: the rig does not fit
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  p.rig = &rig;
  p.targets.resize(1);
  p.targets[0].effector = 2;
  EXPECT_FALSE(ik_detail::plainlyValid(p, false));
  EXPECT_NE(p.validate(), "");
  rig.limits.resize(3);
  EXPECT_EQ(p.validate(), "");
}

// Bitwise equality of two poses (EXPECT_EQ on floats would let -0 pass for +0).
bool sameBits(const Pose& a, const Pose& b) {
  return a.local.size() == b.local.size() &&
         std::memcmp(a.local.data(), b.local.data(), a.local.size() * sizeof(Transform)) == 0;
}

TEST(IkFastPaths, ChainForwardKinematicsEqualsTheGeneralLoop) {
  std::mt19937 rng(21);
  for (int k = 0; k < 200; ++k) {
    const Skeleton s = test::makeChain(2 + k % 12, &rng);
    Pose pose = test::randomPose(s, rng, 2.0f);
    IkProblem p;
    p.skeleton = &s;
    p.pose = &pose;
    p.targets.resize(1);
    p.targets[0].effector = s.size() - 1;
    p.targets[0].root = k % 3 == 0 ? -1 : static_cast<int>(rng() % (s.size() - 1));
    if (k % 2) {  // a placement: turned and moved
      p.rootTransform = glm::mat4_cast(glm::normalize(glm::quat(1.0f, 0.3f, -0.2f, 0.1f)));
      p.rootTransform[3] = glm::vec4(0.5f, -1.0f, 2.0f, 1.0f);
    }
    ik_detail::IkChain& c = ik_detail::workspace();
    ASSERT_EQ(c.build(p), "");
    ASSERT_TRUE(c.chain && c.rigid);
    const std::vector<glm::vec3> positions = c.positions;
    const std::vector<glm::quat> rotations = c.rotation;
    c.chain = false;  // the general loop over parent slots
    c.forwardKinematics();
    ASSERT_EQ(std::memcmp(positions.data(), c.positions.data(), positions.size() * sizeof(glm::vec3)), 0) << k;
    ASSERT_EQ(std::memcmp(rotations.data(), c.rotation.data(), rotations.size() * sizeof(glm::quat)), 0) << k;
  }
}

TEST(IkFastPaths, TwoBoneOnePassEqualsTheGeneralLoop) {
  std::mt19937 rng(22);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  const IkRig emptyRig;  // a rig (without limits) sends solveTwoBone down its general loop
  int solved = 0;
  for (int k = 0; k < 1000; ++k) {
    // 3..6 joints in a line; the arm: the effector, its middle joint and root above.
    const Skeleton s = test::makeChain(3 + k % 4, &rng);
    const Pose start = test::randomPose(s, rng, 2.0f);
    IkProblem p;
    p.skeleton = &s;
    IkTarget t;
    t.effector = s.size() - 1;
    if (k % 3 == 1 && s.size() > 3) t.mid = t.effector - 2;  // a rigid joint between
    if (k % 5 == 2 && s.size() > 4) t.root = 0;
    t.position = {u(rng), u(rng), u(rng)};
    t.hasPole = k % 2;
    t.pole = {u(rng), u(rng), u(rng)};
    t.hasOrientation = k % 7 == 3;
    t.orientation = glm::quat(u(rng), u(rng), u(rng), u(rng));
    p.targets.push_back(t);
    IkSettings settings;
    settings.twoBoneSoften = k % 4 == 1 ? 0.2f : 0.0f;
    Pose a = start, b = start;
    if (k % 6 == 5) a.local[1].rotation *= 1.7f, b.local[1].rotation *= 1.7f;  // non-unit: made unit first
    if (k % 8 == 7) {  // negative zeros at the top, where the one-pass FK skips a rotation
      a.local[0].translation = b.local[0].translation = glm::vec3(-0.0f, 0.5f, -0.0f);
      a.local[0].rotation = b.local[0].rotation = glm::quat(1.0f, -0.0f, k % 16 == 7 ? -0.0f : 0.0f, -0.0f);
    }
    p.pose = &a;
    const IkResult ra = solveTwoBone(p, settings);
    p.pose = &b;
    p.rig = &emptyRig;
    const IkResult rb = solveTwoBone(p, settings);
    ASSERT_EQ(ra.message, "");
    ASSERT_EQ(rb.message, "");
    EXPECT_TRUE(sameBits(a, b)) << "case " << k;
    EXPECT_EQ(std::memcmp(&ra.error, &rb.error, sizeof(float)), 0) << "case " << k;
    EXPECT_EQ(ra.converged, rb.converged);
    EXPECT_EQ(ra.iterations, rb.iterations);
    solved += ra.converged;
  }
  EXPECT_GT(solved, 100);  // reachable targets among them
}

TEST(IkFastPaths, TwoBoneJobInSseRegistersEqualsTheScalarJob) {
#if defined(__SSE2__)
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f), len(0.1f, 2.0f);
  int fast = 0;
  for (int k = 0; k < 20000; ++k) {
    TwoBoneIkJob job;
    job.startPosition = {u(rng), u(rng), u(rng)};
    job.startRotation = test::randomRotation(rng, 3.0f);
    job.midPosition = job.startPosition + len(rng) * glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
    job.midRotation = test::randomRotation(rng, 3.0f);
    job.endPosition = job.midPosition + len(rng) * glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
    job.target = {u(rng), u(rng), u(rng)};
    switch (k % 6) {
      case 0: break;                                                 // no pole: the current side
      case 1: job.pole = {u(rng), u(rng), u(rng)}; break;            // a pole
      case 2: job.target = job.startPosition; break;                 // target on the start joint
      case 3: job.endPosition = job.midPosition; break;              // a zero bone
      case 4: job.pole = (job.target - job.startPosition) * 2.0f; break;  // pole on the target line
      default: job.target = job.startPosition + 1e3f * (job.target - job.startPosition); break;  // far out
    }
    glm::quat c1[2], c2[2], t1[2], t2[2];
    bool r[2] = {false, true};
    auto outputsTo = [&](int side) {
      job.startCorrection = &c1[side];
      job.midCorrection = &c2[side];
      job.startTurn = &t1[side];
      job.midTurn = &t2[side];
      job.reached = &r[side];
    };
    outputsTo(0);
    ik_detail::runTwoBoneJobScalar(job);
    outputsTo(1);
    if (!ik_detail::runTwoBoneJobSse(job)) {
      // Only the rare cases are left to the scalar job.
      EXPECT_TRUE(k % 6 == 2 || k % 6 == 3) << "case " << k;
      continue;
    }
    ++fast;
    ASSERT_EQ(r[0], r[1]) << k;
    EXPECT_EQ(std::memcmp(&c1[0], &c1[1], sizeof(glm::quat)), 0) << "case " << k;
    EXPECT_EQ(std::memcmp(&c2[0], &c2[1], sizeof(glm::quat)), 0) << "case " << k;
    EXPECT_EQ(std::memcmp(&t1[0], &t1[1], sizeof(glm::quat)), 0) << "case " << k;
    EXPECT_EQ(std::memcmp(&t2[0], &t2[1], sizeof(glm::quat)), 0) << "case " << k;
  }
  EXPECT_GT(fast, 10000);
#endif
}

}  // namespace
}  // namespace kinema
