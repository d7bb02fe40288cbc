// Analytic two-bone IK on a pose: walks FK to the three joints, hands their model-space
// transforms to TwoBoneIkJob (the law-of-cosines geometry, ik/two_bone_job.cpp) and
// applies its corrections. Joints between root, middle and effector stay rigid.
#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "ik/ik_chain.h"
#include "ik/two_bone_job.h"

namespace kinema {

namespace {

constexpr int kMaxDepth = 64;

glm::quat rotationOf(const glm::mat4& m) {
  const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])));
  return ik_detail::renormalize(glm::quat_cast(r));
}

// World positions and rotations of every joint from root down to
// `effector`. Rigid paths (no scale, placement without scale) use quaternion products only;
// any scale falls back to affine matrices. Rotations are renormalised where they are read.
struct PathWorld {
  int joints[kMaxDepth];
  glm::vec3 position[kMaxDepth];
  glm::quat rotation[kMaxDepth];  // world rotations (products of unit quaternions)
  int count = 0;

  bool compute(const Skeleton& s, const Pose& pose, const glm::mat4& placement, int root, int effector) {
    int up[kMaxDepth];
    int n = 0;
    bool rigid = true;
    for (int j = effector; j >= 0; j = s.parents[j]) {
      if (n == kMaxDepth) return false;
      up[n++] = j;
      rigid = rigid && pose.local[j].scale == glm::vec3(1.0f);
    }
    const bool identity = placement == glm::mat4(1.0f);
    if (!identity) {
      const glm::mat3 l(placement);
      const glm::mat3 ltl = glm::transpose(l) * l;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) rigid = rigid && std::abs(ltl[a][b] - (a == b ? 1.0f : 0.0f)) < 1e-6f;
    }
    glm::quat q = identity ? glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : rotationOf(placement);
    count = 0;
    bool inPath = false;
    if (rigid) {
      glm::vec3 p = identity ? glm::vec3(0.0f) : glm::vec3(placement[3]);
      for (int i = n - 1; i >= 0; --i) {
        const Transform& t = pose.local[up[i]];
        if (up[i] == root) inPath = true;
        p += ik_detail::rotate(q, t.translation);
        q = ik_detail::mul(q, t.rotation);
        if (inPath) {
          joints[count] = up[i];
          rotation[count] = q;
          position[count++] = p;
        }
      }
      return inPath;
    }
    glm::mat4 w = placement;
    for (int i = n - 1; i >= 0; --i) {
      const Transform& t = pose.local[up[i]];
      if (up[i] == root) inPath = true;
      w = multiplyAffine(w, t.toMatrix());
      q = ik_detail::renormalize(q * t.rotation);
      if (inPath) {
        joints[count] = up[i];
        rotation[count] = q;
        position[count++] = glm::vec3(w[3]);
      }
    }
    return inPath;
  }
  int indexOf(int joint) const {
    for (int i = 0; i < count; ++i)
      if (joints[i] == joint) return i;
    return -1;
  }
};

}  // namespace

IkResult solveTwoBone(const IkProblem& problem, const IkSettings& settings) {
  IkResult out;
  out.message = problem.validate(true);
  if (!out.message.empty()) return out;
  const Skeleton& s = *problem.skeleton;
  Pose& pose = *problem.pose;
  out.iterations = 1;
  out.converged = true;
  for (const IkTarget& target : problem.targets) {
    const int c = target.effector;
    const int b = target.mid >= 0 ? target.mid : s.parents[c];
    const int a = ikRootOf(s, target, true);
    for (int j = c; j >= 0; j = s.parents[j]) {
      ik_detail::makeUnit(pose.local[j].rotation);
      if (j == a) break;
    }
    PathWorld path;
    if (!path.compute(s, pose, problem.rootTransform, a, c)) {
      out.message = "two-bone: the chain from '" + s.names[a] + "' is deeper than " + std::to_string(kMaxDepth) + " joints";
      out.converged = false;
      return out;
    }
    const int ib = path.indexOf(b), ic = path.count - 1;
    const glm::vec3 pa = path.position[0], pb = path.position[ib], pc = path.position[ic];
    if (settings.trace) {
      IkTrace& t = *settings.trace;
      if (t.joints.empty()) t.joints.assign(path.joints, path.joints + path.count);
      IkTraceEntry e;
      e.step = IkStep::Start;
      e.error = distanceInDouble(pc, target.position);
      for (int i = 0; i < path.count; ++i) e.positions.push_back(path.position[i]);
      t.entries.push_back(std::move(e));
    }
    // The job does the geometry; the path gives it model-space inputs.
    const glm::quat ra = ik_detail::renormalize(path.rotation[0]);
    const glm::quat rb = ik_detail::renormalize(path.rotation[ib]);
    glm::quat correctionA, correctionB, deltaA, deltaB;
    TwoBoneIkJob job;
    job.startPosition = pa;
    job.startRotation = ra;
    job.midPosition = pb;
    job.midRotation = rb;
    job.endPosition = pc;
    job.target = target.position;
    if (target.hasPole) job.pole = target.pole - pa;  // zero: bend to the current side
    if (settings.twoBoneSoften > 0.0f) {
      const float reach = glm::length(pb - pa) + glm::length(pc - pb);
      if (reach > 0.0f) job.soften = std::min(settings.twoBoneSoften / reach, 1.0f);
    }
    job.startCorrection = &correctionA;
    job.midCorrection = &correctionB;
    job.startTurn = &deltaA;
    job.midTurn = &deltaB;
    job.runUnchecked();  // inputs come from a validated problem
    pose.local[a].rotation = ik_detail::renormalize(ik_detail::mul(pose.local[a].rotation, correctionA));
    pose.local[b].rotation = ik_detail::renormalize(ik_detail::mul(pose.local[b].rotation, correctionB));
    // The world turns behind the corrections: of the start joint, and of everything from
    // the mid joint down (the mid's own turn after the start's).
    const glm::quat deltaBA = ik_detail::mul(deltaA, deltaB);
    glm::quat effectorParentRot(1.0f, 0.0f, 0.0f, 0.0f);
    bool limited = false;
    if (problem.rig) {
      for (int j : {a, b}) {
        if (const JointLimit* l = problem.rig->limitOf(j)) {
          pose.local[j].rotation = applyJointLimit(*l, s.rest[j].rotation, pose.local[j].rotation);
          limited = true;
        }
      }
    }
    if (target.hasOrientation) {
      const glm::quat rcp = ik_detail::renormalize(path.rotation[ic - 1]);
      // The effector's parent turned with the root, then with the middle joint.
      effectorParentRot = ik_detail::renormalize(ik_detail::mul(deltaBA, rcp));
      pose.local[c].rotation = ik_detail::renormalize(glm::conjugate(effectorParentRot) * ik_detail::renormalize(target.orientation));
      if (problem.rig)
        if (const JointLimit* l = problem.rig->limitOf(c))
          pose.local[c].rotation = applyJointLimit(*l, s.rest[c].rotation, pose.local[c].rotation);
    }
    // Where the effector ended: pb turned about pa by deltaA, pc about pb by deltaBA.
    glm::vec3 finalC = pa + ik_detail::rotate(deltaA, pb - pa) + ik_detail::rotate(deltaBA, pc - pb);
    if (limited || settings.trace) {
      path.compute(s, pose, problem.rootTransform, a, c);
      finalC = path.position[ic];
    }
    const float err = distanceInDouble(finalC, target.position);
    out.error = std::max(out.error, err);
    if (!(err <= settings.tolerance)) out.converged = false;
    if (settings.trace) {
      IkTraceEntry e;
      e.iteration = 1;
      e.step = IkStep::TwoBone;
      e.error = err;
      for (int i = 0; i < path.count; ++i) e.positions.push_back(path.position[i]);
      settings.trace->entries.push_back(std::move(e));
    }
  }
  return out;
}

}  // namespace kinema
