// Analytic two-bone IK (seed 002's law-of-cosines triangle): the triangle root-middle-
// target fixes where the middle joint goes, on the pole's side of the root-target line;
// the root and then the middle joint turn their bones there by minimal rotations.
// Joints between root, middle and effector stay rigid. No allocation on the way.
#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "ik/ik_chain.h"

namespace kinema {

namespace {

constexpr int kMaxDepth = 64;

glm::quat rotationOf(const glm::mat4& m) {
  const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])));
  return ik_detail::renormalize(glm::quat_cast(r));
}

// World positions and rotations of `root`'s parent and of every joint from root down to
// `effector`. Rigid paths (no scale, placement without scale) use quaternion products only;
// any scale falls back to affine matrices. Rotations are renormalised where they are read.
struct PathWorld {
  int joints[kMaxDepth];
  glm::vec3 position[kMaxDepth];
  glm::quat rotation[kMaxDepth];  // world rotations (products of unit quaternions)
  glm::quat parentOfRootRotation{1.0f, 0.0f, 0.0f, 0.0f};
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
        if (up[i] == root) {
          inPath = true;
          parentOfRootRotation = q;
        }
        p += q * t.translation;
        q = q * t.rotation;
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
      if (up[i] == root) {
        inPath = true;
        parentOfRootRotation = q;
      }
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

// The rotation taking unit vector a onto unit vector b (half-way quaternion: one square
// root, where fromToRotation also measures and divides both inputs).
glm::quat unitFromTo(const glm::vec3& a, const glm::vec3& b) {
  const float d = glm::dot(a, b);
  if (d < -0.999999f) return fromToRotation(a, b);  // opposite: any perpendicular axis
  const glm::vec3 c = glm::cross(a, b);
  const glm::quat q(1.0f + d, c.x, c.y, c.z);
  return q * (1.0f / std::sqrt(glm::dot(q, q)));
}

glm::vec3 anyPerpendicular(const glm::vec3& v) {
  const glm::vec3 a = std::abs(v.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::cross(v, a);
}

// Turns joint `local` by the world rotation `delta` given its parent's world rotation.
void applyWorldDelta(glm::quat& local, const glm::quat& parentRot, const glm::quat& delta) {
  local = ik_detail::renormalize(glm::conjugate(parentRot) * delta * parentRot * local);
}

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
    const glm::quat rap = ik_detail::renormalize(path.parentOfRootRotation);
    const glm::quat rbp = ik_detail::renormalize(ib > 0 ? path.rotation[ib - 1] : path.parentOfRootRotation);
    if (settings.trace) {
      IkTrace& t = *settings.trace;
      if (t.joints.empty()) t.joints.assign(path.joints, path.joints + path.count);
      IkTraceEntry e;
      e.step = IkStep::Start;
      e.error = glm::length(pc - target.position);
      for (int i = 0; i < path.count; ++i) e.positions.push_back(path.position[i]);
      t.entries.push_back(std::move(e));
    }
    const float l1 = glm::length(pb - pa), l2 = glm::length(pc - pb);
    glm::vec3 toTarget = target.position - pa;
    float dist = glm::length(toTarget);
    // Soft IK: approach full extension exponentially, so the elbow does not snap straight.
    const float soften = std::min(settings.twoBoneSoften, l1 + l2);
    if (soften > 0.0f && dist > l1 + l2 - soften && dist > 0.0f) {
      const float da = l1 + l2 - soften;
      const float softened = da + soften * (1.0f - std::exp(-(dist - da) / soften));
      toTarget *= softened / dist;
      dist = softened;
    }
    const float d = std::clamp(dist, std::abs(l1 - l2), l1 + l2);

    // Where the middle joint must go: on the circle the law of cosines allows, on the
    // pole's side of the root-target line (without a pole: the side it is on now).
    glm::vec3 u;
    if (dist > 1e-12f) {
      u = toTarget / dist;  // unit already
    } else {
      u = pc - pa;
      if (glm::dot(u, u) < 1e-20f) u = pb - pa;
      if (glm::dot(u, u) < 1e-20f) u = glm::vec3(0.0f, 1.0f, 0.0f);
      u = glm::normalize(u);
    }
    glm::vec3 side = target.hasPole ? target.pole - pa : pb - pa;
    side -= glm::dot(side, u) * u;
    if (glm::dot(side, side) < 1e-20f) {
      side = pb - pa - glm::dot(pb - pa, u) * u;
      if (glm::dot(side, side) < 1e-20f) side = anyPerpendicular(u);
    }
    const glm::vec3 w = glm::normalize(side);
    glm::quat deltaA(1.0f, 0.0f, 0.0f, 0.0f), deltaB(1.0f, 0.0f, 0.0f, 0.0f);
    if (l1 > 1e-12f && l2 > 1e-12f && d > 1e-12f) {
      const float cosA = std::clamp((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f);
      const float sinA = std::sqrt(std::max(0.0f, 1.0f - cosA * cosA));
      const glm::vec3 elbowDir = cosA * u + sinA * w;  // unit
      const glm::vec3 elbow = pa + l1 * elbowDir, hand = pa + d * u;
      // Minimal rotations (no spurious roll): the root turns its bone onto the elbow,
      // then the middle joint turns its bone onto the hand. Both bones keep their length
      // (l1, l2), so their directions are unit vectors after one division each.
      deltaA = unitFromTo((pb - pa) * (1.0f / l1), elbowDir);
      const glm::vec3 pc1 = pa + deltaA * (pc - pa);
      deltaB = unitFromTo((pc1 - elbow) * (1.0f / l2), (hand - elbow) * (1.0f / l2));
    } else {
      deltaA = fromToRotation(pc - pa, u);  // a zero-length bone: only aiming is possible
    }
    // The root's new local rotation from its world one: conj(parent) * delta * world.
    pose.local[a].rotation = ik_detail::renormalize(glm::conjugate(rap) * (deltaA * path.rotation[0]));
    applyWorldDelta(pose.local[b].rotation, ik_detail::renormalize(deltaA * rbp), deltaB);
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
      effectorParentRot = ik_detail::renormalize(deltaB * deltaA * rcp);
      pose.local[c].rotation = ik_detail::renormalize(glm::conjugate(effectorParentRot) * ik_detail::renormalize(target.orientation));
      if (problem.rig)
        if (const JointLimit* l = problem.rig->limitOf(c))
          pose.local[c].rotation = applyJointLimit(*l, s.rest[c].rotation, pose.local[c].rotation);
    }
    // Where the effector ended: pb moved by deltaA, then pc about the new pb by deltaB.
    const glm::vec3 pb1 = pa + deltaA * (pb - pa);
    glm::vec3 finalC = pb1 + deltaB * (pa + deltaA * (pc - pa) - pb1);
    if (limited || settings.trace) {
      path.compute(s, pose, problem.rootTransform, a, c);
      finalC = path.position[ic];
    }
    const float err = glm::length(finalC - target.position);
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
