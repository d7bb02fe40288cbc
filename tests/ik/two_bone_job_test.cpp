// TwoBoneIkJob (model-space inputs, local corrections out) against hand-derived planar
// angles (seed 002's x_e, y_e formulas), the law-of-cosines geometry and solveTwoBone.
#include <gtest/gtest.h>

#include <cmath>

#include "ik/ik_solver.h"
#include "ik/two_bone_job.h"
#include "ik_test_chains.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::planarArm;
using test::wrap;
using test::zAngle;

// Runs a job on joints a, b, c of a pose (inputs by FK) and applies its corrections.
struct Solved {
  glm::quat startCorrection, midCorrection;
  bool reached = false;
  std::vector<glm::mat4> world;  // FK of the corrected pose
};

TwoBoneIkJob jobFor(const Skeleton& s, const Pose& pose, int a, int b, int c, const glm::vec3& target) {
  const std::vector<glm::mat4> w = computeWorld(s, pose);
  TwoBoneIkJob job;
  job.startPosition = glm::vec3(w[a][3]);
  job.startRotation = glm::normalize(glm::quat_cast(glm::mat3(w[a])));
  job.midPosition = glm::vec3(w[b][3]);
  job.midRotation = glm::normalize(glm::quat_cast(glm::mat3(w[b])));
  job.endPosition = glm::vec3(w[c][3]);
  job.target = target;
  return job;
}

Solved apply(const Skeleton& s, Pose pose, TwoBoneIkJob job, int a, int b) {
  Solved out;
  job.startCorrection = &out.startCorrection;
  job.midCorrection = &out.midCorrection;
  job.reached = &out.reached;
  EXPECT_TRUE(job.validate().empty()) << job.validate();
  EXPECT_TRUE(job.run());
  pose.local[a].rotation = pose.local[a].rotation * out.startCorrection;
  pose.local[b].rotation = pose.local[b].rotation * out.midCorrection;
  out.world = computeWorld(s, pose);
  return out;
}

glm::vec3 at(const Solved& r, int j) { return glm::vec3(r.world[j][3]); }

bool finite(const glm::quat& q) { return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w); }

TEST(TwoBoneJob, PlanarClosedFormBothElbows) {
  const float l1 = 1.2f, l2 = 0.8f;
  const Skeleton s = planarArm(l1, l2);
  const float bend = 0.2f;  // the elbow's starting bend about Z
  for (const glm::vec2 t : {glm::vec2(1.1f, 0.9f), glm::vec2(-0.5f, 1.4f), glm::vec2(0.7f, -0.3f)}) {
    const float c2 = (t.x * t.x + t.y * t.y - l1 * l1 - l2 * l2) / (2.0f * l1 * l2);
    for (float sign : {1.0f, -1.0f}) {
      // x_e = l1 cos t1 + l2 cos(t1 + t2), y_e = l1 sin t1 + l2 sin(t1 + t2), by hand:
      const float t2 = sign * std::acos(c2);
      const float t1 = std::atan2(t.y, t.x) - std::atan2(l2 * std::sin(t2), l1 + l2 * std::cos(t2));
      const glm::vec3 elbow(l1 * std::cos(t1), l1 * std::sin(t1), 0.0f);
      Pose pose = Pose::rest(s);
      pose.local[1].rotation = glm::angleAxis(bend, glm::vec3(0, 0, 1));
      TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, glm::vec3(t, 0.0f));
      job.pole = elbow;  // the direction of the wanted elbow from the shoulder
      const Solved r = apply(s, pose, job, 0, 1);
      EXPECT_TRUE(r.reached);
      // Start local rotation was identity, so its correction is the whole angle t1; the
      // elbow's was Rz(bend), so its correction turns by t2 - bend. Both purely about Z.
      EXPECT_NEAR(wrap(zAngle(r.startCorrection) - t1), 0.0f, 1e-4f) << "sign " << sign;
      EXPECT_NEAR(wrap(zAngle(r.midCorrection) - (t2 - bend)), 0.0f, 1e-4f) << "sign " << sign;
      EXPECT_NEAR(std::hypot(r.startCorrection.x, r.startCorrection.y), 0.0f, 1e-5f);
      EXPECT_NEAR(std::hypot(r.midCorrection.x, r.midCorrection.y), 0.0f, 1e-5f);
      EXPECT_VEC3_NEAR(at(r, 1), elbow, 1e-5f);
      EXPECT_VEC3_NEAR(at(r, 2), glm::vec3(t, 0.0f), 1e-5f);
    }
  }
}

TEST(TwoBoneJob, PoleOutOfPlanePicksTheBendPlane) {
  // Target on +X at distance 1.2 with unit bones: the elbow lies 0.6 along X and
  // sqrt(1 - 0.36) = 0.8 off the line, on the pole's side (here +Z), then -Z.
  const Skeleton s = planarArm(1.0f, 1.0f);
  for (float side : {1.0f, -1.0f}) {
    Pose pose = Pose::rest(s);
    pose.local[1].rotation = glm::angleAxis(0.5f, glm::vec3(0, 0, 1));
    TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, glm::vec3(1.2f, 0.0f, 0.0f));
    job.pole = glm::vec3(0.3f, 0.0f, 2.0f * side);  // its part along X does not count
    const Solved r = apply(s, pose, job, 0, 1);
    EXPECT_VEC3_NEAR(at(r, 1), glm::vec3(0.6f, 0.0f, 0.8f * side), 1e-5f);
    EXPECT_VEC3_NEAR(at(r, 2), glm::vec3(1.2f, 0.0f, 0.0f), 1e-5f);
  }
}

TEST(TwoBoneJob, TwistTurnsTheBendPlaneAboutTheTargetLine) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(0.5f, glm::vec3(0, 0, 1));
  TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, glm::vec3(1.2f, 0.0f, 0.0f));
  job.pole = glm::vec3(0.0f, 1.0f, 0.0f);
  // +Y turned by +90 degrees about +X is +Z; by 180 degrees, -Y.
  job.twistAngle = glm::half_pi<float>();
  EXPECT_VEC3_NEAR(at(apply(s, pose, job, 0, 1), 1), glm::vec3(0.6f, 0.0f, 0.8f), 1e-5f);
  job.twistAngle = glm::pi<float>();
  EXPECT_VEC3_NEAR(at(apply(s, pose, job, 0, 1), 1), glm::vec3(0.6f, -0.8f, 0.0f), 1e-5f);
}

TEST(TwoBoneJob, WithoutPoleKeepsTheCurrentSide) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  for (float bend : {0.7f, -0.7f}) {
    Pose pose = Pose::rest(s);
    // Shoulder turned by -bend, elbow by +bend: the hand on the X axis, the elbow off it
    // (on -Y for a positive bend). Without a pole the elbow stays on its side.
    pose.local[0].rotation = glm::angleAxis(-bend, glm::vec3(0, 0, 1));
    pose.local[1].rotation = glm::angleAxis(bend, glm::vec3(0, 0, 1));
    TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, glm::vec3(1.2f, 0.0f, 0.0f));
    const float elbowY = job.midPosition.y;
    ASSERT_GT(std::abs(elbowY), 0.1f);
    const Solved r = apply(s, pose, job, 0, 1);
    EXPECT_VEC3_NEAR(at(r, 1), glm::vec3(0.6f, elbowY > 0.0f ? 0.8f : -0.8f, 0.0f), 1e-5f);
  }
}

TEST(TwoBoneJob, UnreachableStraightensTowardsTarget) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
  const Solved r = apply(s, pose, jobFor(s, pose, 0, 1, 2, glm::vec3(0.0f, 3.0f, 4.0f)), 0, 1);  // 5 away, reach 2
  EXPECT_FALSE(r.reached);
  EXPECT_VEC3_NEAR(at(r, 1), glm::vec3(0.0f, 0.6f, 0.8f), 1e-5f);
  EXPECT_VEC3_NEAR(at(r, 2), glm::vec3(0.0f, 1.2f, 1.6f), 1e-5f);
  // Too close to reach with unequal bones (|l1 - l2| = 0.5): folded, end 0.5 towards it.
  const Skeleton u = planarArm(1.0f, 0.5f);
  Pose folded = Pose::rest(u);
  folded.local[1].rotation = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
  const Solved f = apply(u, folded, jobFor(u, folded, 0, 1, 2, glm::vec3(0.0f, 0.2f, 0.0f)), 0, 1);
  EXPECT_FALSE(f.reached);
  EXPECT_VEC3_NEAR(at(f, 2), glm::vec3(0.0f, 0.5f, 0.0f), 1e-5f);
  EXPECT_VEC3_NEAR(at(f, 1), glm::vec3(0.0f, 1.0f, 0.0f), 1e-5f);
}

TEST(TwoBoneJob, DegenerateInputsGiveFiniteUnitCorrections) {
  struct Case {
    const char* what;
    float l1, l2, bend;
    glm::vec3 target, pole;
  };
  const Case cases[] = {
      {"target at the start joint", 1.0f, 1.0f, 0.6f, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f)},
      {"target at the start, no pole", 1.0f, 0.7f, 0.6f, glm::vec3(0.0f), glm::vec3(0.0f)},
      {"straight arm, target on its line", 1.0f, 1.0f, 0.0f, glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f)},
      {"straight arm, pole on the line", 1.0f, 1.0f, 0.0f, glm::vec3(-1.5f, 0.0f, 0.0f), glm::vec3(3.0f, 0.0f, 0.0f)},
      {"zero-length upper bone", 0.0f, 1.0f, 0.3f, glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f)},
      {"zero-length lower bone", 1.0f, 0.0f, 0.3f, glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)},
      {"both bones zero", 0.0f, 0.0f, 0.3f, glm::vec3(1.0f, 1.0f, 1.0f), glm::vec3(0.0f)},
  };
  for (const Case& k : cases) {
    const Skeleton s = planarArm(k.l1, k.l2);
    Pose pose = Pose::rest(s);
    pose.local[1].rotation = glm::angleAxis(k.bend, glm::vec3(0, 0, 1));
    TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, k.target);
    job.pole = k.pole;
    const Solved r = apply(s, pose, job, 0, 1);
    EXPECT_TRUE(finite(r.startCorrection) && finite(r.midCorrection)) << k.what;
    EXPECT_NEAR(glm::length(r.startCorrection), 1.0f, 1e-5f) << k.what;
    EXPECT_NEAR(glm::length(r.midCorrection), 1.0f, 1e-5f) << k.what;
    // Bone lengths never change; a reachable target is reached.
    EXPECT_NEAR(glm::length(at(r, 1) - at(r, 0)), k.l1, 1e-5f) << k.what;
    EXPECT_NEAR(glm::length(at(r, 2) - at(r, 1)), k.l2, 1e-5f) << k.what;
    const float dist = glm::length(k.target);
    if (k.l1 > 0.0f && k.l2 > 0.0f && dist >= std::abs(k.l1 - k.l2) && dist <= k.l1 + k.l2) {
      SCOPED_TRACE(k.what);
      EXPECT_VEC3_NEAR(at(r, 2), k.target, 1e-5f);
    }
  }
}

TEST(TwoBoneJob, WeightSlerpsFromIdentity) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[0].rotation = glm::angleAxis(0.4f, glm::normalize(glm::vec3(1, 2, 0)));
  pose.local[1].rotation = glm::angleAxis(0.9f, glm::vec3(0, 0, 1));
  TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, glm::vec3(0.3f, 1.1f, 0.8f));
  job.pole = glm::vec3(0.0f, 0.0f, 1.0f);
  const Solved full = apply(s, pose, job, 0, 1);
  job.weight = 0.0f;
  const Solved none = apply(s, pose, job, 0, 1);
  EXPECT_SAME_ROTATION(none.startCorrection, glm::quat(1, 0, 0, 0), 1e-6f);
  EXPECT_SAME_ROTATION(none.midCorrection, glm::quat(1, 0, 0, 0), 1e-6f);
  job.weight = 0.5f;
  const Solved half = apply(s, pose, job, 0, 1);
  // Half the angle about the same axis (the correction's square root).
  for (auto [h, f] : {std::pair{half.startCorrection, full.startCorrection}, std::pair{half.midCorrection, full.midCorrection}}) {
    const glm::quat fp = f.w < 0.0f ? -f : f;
    const float angle = 2.0f * std::atan2(glm::length(glm::vec3(fp.x, fp.y, fp.z)), fp.w);
    const glm::vec3 axis = glm::normalize(glm::vec3(fp.x, fp.y, fp.z));
    EXPECT_GT(angle, 0.1f);
    EXPECT_SAME_ROTATION(h, glm::angleAxis(0.5f * angle, axis), 1e-6f);
    EXPECT_SAME_ROTATION(h * h, f, 1e-6f);
  }
  EXPECT_VEC3_NEAR(at(full, 2), glm::vec3(0.3f, 1.1f, 0.8f), 1e-5f);
}

TEST(TwoBoneJob, SoftenStopsShortOfFullExtension) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
  TwoBoneIkJob job = jobFor(s, pose, 0, 1, 2, glm::vec3(2.0f, 0.0f, 0.0f));  // exactly at full reach
  job.soften = 0.05f;  // 0.1 of the reach 2
  const Solved r = apply(s, pose, job, 0, 1);
  // Softening starts at da = 1.9; the end goes to 1.9 + 0.1 (1 - e^-(2 - 1.9)/0.1).
  EXPECT_NEAR(glm::length(at(r, 2)), 1.9f + 0.1f * (1.0f - std::exp(-1.0f)), 1e-5f);
  EXPECT_NEAR(at(r, 2).y, 0.0f, 1e-5f);
  EXPECT_FALSE(r.reached);
  // Closer than da: softening leaves the target alone.
  job.target = glm::vec3(1.5f, 0.0f, 0.0f);
  const Solved near = apply(s, pose, job, 0, 1);
  EXPECT_TRUE(near.reached);
  EXPECT_VEC3_NEAR(at(near, 2), job.target, 1e-5f);
}

TEST(TwoBoneJob, ValidateRejectsBadInputsAndRunWritesNothing) {
  glm::quat a(0.0f, 1.0f, 0.0f, 0.0f), b = a;
  TwoBoneIkJob job;
  job.midPosition = glm::vec3(1, 0, 0);
  job.endPosition = glm::vec3(2, 0, 0);
  EXPECT_FALSE(job.validate().empty());  // no outputs
  job.startCorrection = &a;
  job.midCorrection = &b;
  EXPECT_TRUE(job.validate().empty()) << job.validate();
  const auto rejects = [&](auto change) {
    TwoBoneIkJob bad = job;
    change(bad);
    EXPECT_FALSE(bad.validate().empty());
    EXPECT_FALSE(bad.run());
    EXPECT_EQ(a, glm::quat(0.0f, 1.0f, 0.0f, 0.0f));
    EXPECT_EQ(b, glm::quat(0.0f, 1.0f, 0.0f, 0.0f));
  };
  rejects([](TwoBoneIkJob& j) { j.weight = 1.5f; });
  rejects([](TwoBoneIkJob& j) { j.weight = std::nanf(""); });
  rejects([](TwoBoneIkJob& j) { j.soften = -0.1f; });
  rejects([](TwoBoneIkJob& j) { j.target.x = std::nanf(""); });
  rejects([](TwoBoneIkJob& j) { j.pole.y = INFINITY; });
  rejects([](TwoBoneIkJob& j) { j.midPosition.z = INFINITY; });
  rejects([](TwoBoneIkJob& j) { j.startRotation = glm::quat(2.0f, 0.0f, 0.0f, 0.0f); });
  rejects([](TwoBoneIkJob& j) { j.twistAngle = std::nanf(""); });
}

// The job with inputs from FK of a pose, corrections applied by hand, against solveTwoBone
// on the same pose; and both against the triangle's geometry. The arm hangs under a
// turned parent so that local and model space differ.
TEST(TwoBoneJob, MatchesSolveTwoBoneOnRandomPoses) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const int cases = test::propertyCases(2000);
  int checked = 0;
  for (int k = 0; k < cases; ++k) {
    const Skeleton s = test::makeChain(4, &rng);  // joint 0 is the parent; 1-2-3 the arm
    const Pose pose = test::randomPose(s, rng, 2.0f);
    Pose other = test::randomPose(s, rng, 2.0f);
    other.local[0] = pose.local[0];  // the arm's start stays put: the target is reachable
    const glm::vec3 target = test::worldPosition(s, other, 3);
    const glm::vec3 pole(unit(rng), unit(rng), unit(rng));

    TwoBoneIkJob job = jobFor(s, pose, 1, 2, 3, target);
    job.pole = pole - job.startPosition;
    const Solved r = apply(s, pose, job, 1, 2);

    Pose solved = pose;
    IkProblem p;
    p.skeleton = &s;
    p.pose = &solved;
    IkTarget t;
    t.effector = 3;
    t.root = 1;
    t.position = target;
    t.hasPole = true;
    t.pole = pole;
    p.targets.push_back(t);
    const IkResult ik = solveTwoBone(p, IkSettings{});
    ASSERT_TRUE(ik.message.empty()) << ik.message;
    // Where the triangle is ill-conditioned (nearly straight or folded, or the pole nearly
    // on the target line) the two paths' inputs, FK by matrices here and by quaternions in
    // solveTwoBone, differ by float rounding that the geometry amplifies; skip those.
    const glm::vec3 pa = job.startPosition;
    const float l1 = glm::length(job.midPosition - pa), l2 = glm::length(job.endPosition - job.midPosition);
    const float d = glm::length(target - pa);
    const glm::vec3 u = (target - pa) / d;
    const float x = (l1 * l1 + d * d - l2 * l2) / (2.0f * d);  // the elbow's distance along u
    const float h2 = l1 * l1 - x * x;                           // squared distance off the line
    glm::vec3 side = job.pole - glm::dot(job.pole, u) * u;
    if (h2 < 1e-2f * l1 * l1 || glm::length(side) < 1e-2f) continue;
    side = glm::normalize(side);
    const glm::vec3 elbow = pa + x * u + std::sqrt(h2) * side;
    SCOPED_TRACE("case " + std::to_string(k));
    const std::vector<glm::mat4> w = computeWorld(s, solved);
    for (int j = 0; j < 4; ++j) EXPECT_VEC3_NEAR(at(r, j), glm::vec3(w[j][3]), 1e-5f);
    // The geometry, independently: the end on the target, the elbow on the law-of-cosines
    // circle on the pole's side of the start-target line.
    EXPECT_VEC3_NEAR(at(r, 3), target, 1e-4f);
    EXPECT_VEC3_NEAR(at(r, 2), elbow, 1e-4f);
    EXPECT_TRUE(r.reached);
    ++checked;
  }
  EXPECT_GT(checked, cases / 2);
}

}  // namespace
}  // namespace kinema
