// Analytic two-bone IK (seed 002's law-of-cosines triangle): the triangle root-middle-
// target fixes where the middle joint goes, on the pole's side of the root-target line;
// the root and then the middle joint turn their bones there by minimal rotations.
// Joints between root, middle and effector stay rigid. No allocation on the way.
#include <algorithm>
#include <cmath>

#include "ik/ik_chain.h"

namespace kinema {

namespace {

constexpr int kMaxDepth = 64;

glm::quat rotationOf(const glm::mat4& m) {
  const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])));
  return ik_detail::renormalize(glm::quat_cast(r));
}

// World matrices of `root`'s parent and of every joint from root down to `effector`.
struct PathWorld {
  int joints[kMaxDepth];
  glm::mat4 world[kMaxDepth];
  glm::quat rotation[kMaxDepth];  // world rotations, by quaternion products (no matrix decomposition)
  glm::mat4 parentOfRoot{1.0f};
  glm::quat parentOfRootRotation{1.0f, 0.0f, 0.0f, 0.0f};
  int count = 0;

  bool compute(const Skeleton& s, const Pose& pose, const glm::mat4& placement, int root, int effector) {
    int up[kMaxDepth];
    int n = 0;
    for (int j = effector; j >= 0; j = s.parents[j]) {
      if (n == kMaxDepth) return false;
      up[n++] = j;
    }
    glm::mat4 w = placement;
    glm::quat q = placement == glm::mat4(1.0f) ? glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : rotationOf(placement);
    count = 0;
    bool inPath = false;
    for (int i = n - 1; i >= 0; --i) {
      if (up[i] == root) {
        inPath = true;
        parentOfRoot = w;
        parentOfRootRotation = q;
      }
      w = multiplyAffineLocal(w, pose.local[up[i]]);
      q = q * pose.local[up[i]].rotation;
      if (inPath) {
        joints[count] = up[i];
        rotation[count] = ik_detail::renormalize(q);
        world[count++] = w;
      }
    }
    return inPath;
  }
  static glm::mat4 multiplyAffineLocal(const glm::mat4& parent, const Transform& t) {
    const glm::mat4 l = t.toMatrix();
    glm::mat4 r;
    for (int c = 0; c < 3; ++c) r[c] = parent[0] * l[c].x + parent[1] * l[c].y + parent[2] * l[c].z;
    r[3] = parent[0] * l[3].x + parent[1] * l[3].y + parent[2] * l[3].z + parent[3];
    return r;
  }
  int indexOf(int joint) const {
    for (int i = 0; i < count; ++i)
      if (joints[i] == joint) return i;
    return -1;
  }
};

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
    PathWorld path;
    if (!path.compute(s, pose, problem.rootTransform, a, c)) {
      out.message = "two-bone: the chain from '" + s.names[a] + "' is deeper than " + std::to_string(kMaxDepth) + " joints";
      out.converged = false;
      return out;
    }
    const int ib = path.indexOf(b), ic = path.count - 1;
    const glm::vec3 pa(path.world[0][3]), pb(path.world[ib][3]), pc(path.world[ic][3]);
    const glm::quat rap = path.parentOfRootRotation;
    const glm::quat rbp = ib > 0 ? path.rotation[ib - 1] : path.parentOfRootRotation;
    if (settings.trace) {
      IkTrace& t = *settings.trace;
      if (t.joints.empty()) t.joints.assign(path.joints, path.joints + path.count);
      IkTraceEntry e;
      e.step = IkStep::Start;
      e.error = glm::length(pc - target.position);
      for (int i = 0; i < path.count; ++i) e.positions.push_back(glm::vec3(path.world[i][3]));
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
    glm::vec3 u = dist > 1e-12f ? toTarget / dist : pc - pa;
    if (glm::dot(u, u) < 1e-20f) u = pb - pa;
    if (glm::dot(u, u) < 1e-20f) u = glm::vec3(0.0f, 1.0f, 0.0f);
    u = glm::normalize(u);
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
      const glm::vec3 elbow = pa + l1 * (cosA * u + sinA * w), hand = pa + d * u;
      // Minimal rotations (no spurious roll): the root turns its bone onto the elbow,
      // then the middle joint turns its bone onto the hand.
      deltaA = fromToRotation(pb - pa, elbow - pa);
      const glm::vec3 pc1 = pa + deltaA * (pc - pa);
      deltaB = fromToRotation(pc1 - elbow, hand - elbow);
    } else {
      deltaA = fromToRotation(pc - pa, u);  // a zero-length bone: only aiming is possible
    }
    applyWorldDelta(pose.local[a].rotation, rap, deltaA);
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
      const glm::quat rcp = path.rotation[ic - 1];
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
      finalC = glm::vec3(path.world[ic][3]);
    }
    const float err = glm::length(finalC - target.position);
    out.error = std::max(out.error, err);
    if (!(err <= settings.tolerance)) out.converged = false;
    if (settings.trace) {
      IkTraceEntry e;
      e.iteration = 1;
      e.step = IkStep::TwoBone;
      e.error = err;
      for (int i = 0; i < path.count; ++i) e.positions.push_back(glm::vec3(path.world[i][3]));
      settings.trace->entries.push_back(std::move(e));
    }
  }
  return out;
}

}  // namespace kinema
