#include "sim/ragdoll_bodies.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "core/math.h"
#include "retarget/bone_map.h"

namespace kinema {
namespace {


float distanceToSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

// The rotation part of an affine matrix whose columns may carry a scale.
glm::mat3 rigidRotation(const glm::mat4& m) {
  glm::mat3 r(m);
  for (int c = 0; c < 3; ++c) {
    const float len = glm::length(r[c]);
    if (len > 0.0f) r[c] /= len;
  }
  return r;
}

}  // namespace

std::string RagdollBodiesJob::validate() const {
  if (!skeleton || !pose || !bodies) return "RagdollBodiesJob: skeleton, pose and bodies are needed";
  if (root < 0 || root >= skeleton->size()) return "RagdollBodiesJob: the root is not a joint of the skeleton";
  if (!(totalMass > 0.0f) || !std::isfinite(totalMass)) return "RagdollBodiesJob: the mass must be above 0";
  if ((meshes != nullptr) != (skins != nullptr) || (skins != nullptr) != (instances != nullptr))
    return "RagdollBodiesJob: meshes, skins and instances go together";
  if (std::string e = pose->validate(*skeleton); !e.empty()) return "RagdollBodiesJob: " + e;
  return "";
}

bool RagdollBodiesJob::run() const {
  if (!validate().empty()) return false;
  const Skeleton& s = *skeleton;
  const std::vector<glm::mat4> world = computeWorld(s, *pose);
  std::vector<int> bodyOf(static_cast<size_t>(s.size()), -1);
  std::vector<RagdollBody>& out = *bodies;
  out.clear();
  std::vector<glm::vec3> headWorld, tailWorld;
  std::vector<float> spread;  // mean distance of a branching joint's children from its bone
  // Parents come before children, so one forward pass finds each body's parent body.
  for (int j = root; j < s.size(); ++j) {
    if (!s.isInSubtree(j, root)) continue;
    glm::vec3 sum(0.0f);
    int children = 0;
    for (int c = j + 1; c < s.size(); ++c)
      if (s.parents[c] == j) sum += glm::vec3(world[c][3]), ++children;
    if (children == 0) continue;
    RagdollBody b;
    b.joint = j;
    b.parentBody = j == root ? -1 : bodyOf[s.parents[j]];
    const glm::vec3 head(world[j][3]);
    const glm::vec3 tail = sum / static_cast<float>(children);
    b.tail = glm::transpose(rigidRotation(world[j])) * (tail - head);
    bodyOf[j] = static_cast<int>(out.size());
    out.push_back(b);
    headWorld.push_back(head);
    tailWorld.push_back(tail);
    float sideways = 0.0f;
    for (int c = j + 1; c < s.size() && children > 1; ++c)
      if (s.parents[c] == j) sideways += distanceToSegment(glm::vec3(world[c][3]), head, tail) / static_cast<float>(children);
    spread.push_back(sideways);
  }
  // Sizes: a fifth of the bone, or the skin's mean distance from the bone where it has some.
  float longest = 0.0f;
  for (const RagdollBody& b : out) longest = std::max(longest, glm::length(b.tail));
  std::vector<double> skinSum(out.size(), 0.0);
  std::vector<int> skinCount(out.size(), 0);
  if (meshes) {
    for (const MeshInstance& inst : *instances) {
      if (inst.skin < 0 || inst.skin >= static_cast<int>(skins->size()) || inst.mesh < 0 ||
          inst.mesh >= static_cast<int>(meshes->size()))
        continue;
      const Skin& skin = (*skins)[inst.skin];
      for (const MeshPrimitive& prim : (*meshes)[inst.mesh].primitives) {
        if (!prim.skinned()) continue;
        for (int v = 0; v < prim.vertexCount(); ++v) {
          const int sj = prim.influenceJoints[static_cast<size_t>(v) * kMaxInfluences];  // the largest weight
          if (sj >= static_cast<int>(skin.joints.size())) continue;
          const int joint = skin.joints[sj];
          if (joint < 0 || joint >= s.size() || bodyOf[joint] < 0) continue;
          const int b = bodyOf[joint];
          // The vertex where the skin puts it in this pose: world * inverse bind * bind position.
          const glm::vec3 p(world[joint] * (skin.inverseBind[sj] * glm::vec4(prim.positions[v], 1.0f)));
          skinSum[b] += distanceToSegment(p, headWorld[b], tailWorld[b]);
          ++skinCount[b];
        }
      }
    }
  }
  double volume = 0.0;
  std::vector<double> volumes(out.size());
  for (size_t b = 0; b < out.size(); ++b) {
    const float length = glm::length(out[b].tail);
    float r = length > 0.0f ? 0.2f * length : 0.1f * longest;
    if (skinCount[b] > 0) r = static_cast<float>(skinSum[b] / skinCount[b]);
    // A branching joint (hips, chest) reaches out to its children: a short bone there would
    // make a light body between heavy ones, which the constraint solver cannot hold.
    r = std::max(r, spread[b]);
    // Not thinner than a twentieth of the longest bone, nor much fatter than the bone is long
    // unless it branches (a capsule much wider than long rolls like a ball), and never zero.
    r = std::clamp(r, 0.05f * longest, std::max({0.5f * length, spread[b], 0.05f * longest}));
    if (!(r > 0.0f)) r = 0.01f;
    out[b].radius = r;
    volumes[b] = 3.14159265358979 * r * r * (length + 4.0 / 3.0 * r);
    volume += volumes[b];
  }
  // By volume, but no body under 2 % of the whole (then scaled back to the total): a toe a
  // hundredth of its leg's mass is torn past its limits by the solver on landing.
  double sum = 0.0;
  for (size_t b = 0; b < out.size(); ++b) {
    volumes[b] = std::max(volumes[b] / volume, 0.02);
    sum += volumes[b];
  }
  for (size_t b = 0; b < out.size(); ++b) out[b].mass = static_cast<float>(totalMass * volumes[b] / sum);
  return true;
}

std::vector<JointLimit> ragdollJointLimits(const Skeleton& s, const IkRig& rig) {
  std::vector<JointLimit> limits(static_cast<size_t>(s.size()));
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  auto restRotation = [&](int j) { return rigidRotation(world[j]); };
  auto childOf = [&](int j) {
    for (int c = j + 1; c < s.size(); ++c)
      if (s.parents[c] == j) return c;
    return -1;
  };
  // The bone's direction in the joint's rest frame (to its first child), or +Y.
  auto boneAxis = [&](int j) {
    const int c = childOf(j);
    const glm::vec3 d = c >= 0 ? s.rest[c].translation : glm::vec3(0.0f);
    return glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0.0f, 1.0f, 0.0f);
  };
  // Joints with neither a stored limit nor a human range (a tail, a prop) turn freely: an
  // invented cone there would start broken whenever the animation (or a spring chain) has
  // already bent the joint past it.
  if (Result<HumanoidReading> h = findHumanoid(s)) {
    const HumanoidMap& m = h->bones;
    // The body's forward: up x (right hip -> left hip), Y up.
    glm::vec3 forward(0.0f, 0.0f, 1.0f);
    if (m.has(HumanoidBone::LeftUpperLeg) && m.has(HumanoidBone::RightUpperLeg)) {
      const glm::vec3 side(world[m[HumanoidBone::LeftUpperLeg]][3] - world[m[HumanoidBone::RightUpperLeg]][3]);
      const glm::vec3 f = glm::cross(side, glm::vec3(0.0f, 1.0f, 0.0f));
      if (glm::length(f) > 0.0f) forward = glm::normalize(f);
    }
    auto cone = [&](HumanoidBone b, float coneDeg, float twistDeg) {
      if (m.has(b)) limits[m[b]] = JointLimit::cone(boneAxis(m[b]), coneDeg * kDegree, -twistDeg * kDegree, twistDeg * kDegree);
    };
    // A hinge that swings the bone towards `towards` (world) by 0 to maxDeg.
    auto hinge = [&](HumanoidBone b, const glm::vec3& towards, float maxDeg) {
      if (!m.has(b)) return;
      const int j = m[b];
      const glm::mat3 r = restRotation(j);
      const glm::vec3 bone = r * boneAxis(j);
      glm::vec3 axis = glm::cross(bone, towards);
      if (!(glm::length(axis) > 1e-4f)) return;
      axis = glm::transpose(r) * glm::normalize(axis);  // into the joint's rest frame
      limits[j] = JointLimit::hinge(axis, 0.0f, maxDeg * kDegree);
    };
    for (HumanoidBone b : {HumanoidBone::Spine, HumanoidBone::Chest, HumanoidBone::UpperChest}) cone(b, 20.0f, 15.0f);
    cone(HumanoidBone::Neck, 35.0f, 30.0f);
    cone(HumanoidBone::Head, 30.0f, 30.0f);
    for (HumanoidBone b : {HumanoidBone::LeftShoulder, HumanoidBone::RightShoulder}) cone(b, 15.0f, 10.0f);
    for (HumanoidBone b : {HumanoidBone::LeftUpperArm, HumanoidBone::RightUpperArm}) cone(b, 80.0f, 60.0f);
    for (HumanoidBone b : {HumanoidBone::LeftHand, HumanoidBone::RightHand}) cone(b, 50.0f, 20.0f);
    for (HumanoidBone b : {HumanoidBone::LeftUpperLeg, HumanoidBone::RightUpperLeg}) cone(b, 60.0f, 30.0f);
    for (HumanoidBone b : {HumanoidBone::LeftFoot, HumanoidBone::RightFoot}) cone(b, 30.0f, 10.0f);
    for (HumanoidBone b : {HumanoidBone::LeftToes, HumanoidBone::RightToes}) cone(b, 20.0f, 5.0f);
    hinge(HumanoidBone::LeftLowerLeg, -forward, 150.0f);  // knees fold backwards
    hinge(HumanoidBone::RightLowerLeg, -forward, 150.0f);
    hinge(HumanoidBone::LeftLowerArm, forward, 150.0f);  // elbows fold forwards
    hinge(HumanoidBone::RightLowerArm, forward, 150.0f);
  }
  for (int j = 0; j < s.size(); ++j)
    if (const JointLimit* l = rig.limitOf(j)) limits[j] = *l;
  return limits;
}

}  // namespace kinema
