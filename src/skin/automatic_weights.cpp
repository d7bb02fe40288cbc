#include "skin/automatic_weights.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mesh.h"

namespace kinema {

namespace {

// A bone as the weights see it: a segment (a == b for a childless joint's point) owned by
// `joint`, with the radius its influence falls off over.
struct BoneSegment {
  int joint = 0;
  glm::vec3 a{0.0f}, b{0.0f};
  float radius = 1.0f;
};

float distanceToSegment(const glm::vec3& p, const BoneSegment& s) {
  const glm::vec3 ab = s.b - s.a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - s.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (s.a + t * ab));
}

glm::vec3 originOf(const glm::mat4& m) { return glm::vec3(m[3]); }

std::vector<BoneSegment> boneSegments(const AutomaticWeightsJob& job) {
  const Skeleton& s = *job.skeleton;
  const std::vector<glm::mat4>& world = *job.bindWorld;
  std::vector<bool> hasChild(s.size(), false);
  for (int j = 0; j < s.size(); ++j)
    if (s.parents[j] >= 0) hasChild[s.parents[j]] = true;
  std::vector<BoneSegment> bones;
  for (int j = 0; j < s.size(); ++j) {
    const int parent = s.parents[j];
    const glm::vec3 here = originOf(world[j]);
    if (parent >= 0) {
      // The bone parent -> j moves with the parent joint.
      const glm::vec3 from = originOf(world[parent]);
      const float length = glm::length(here - from);
      const float r = job.capsuleRadius.empty() ? job.capsuleRadiusScale * length : job.capsuleRadius[parent];
      bones.push_back({parent, from, here, r});
    }
    if (!hasChild[j]) {
      // A childless joint is a point; its reach comes from the bone that leads to it.
      float r = job.capsuleRadius.empty() ? 0.0f : job.capsuleRadius[j];
      if (job.capsuleRadius.empty() && parent >= 0) r = job.capsuleRadiusScale * glm::length(here - originOf(world[parent]));
      if (!(r > 0.0f)) r = 1.0f;  // a lone joint or one sitting on its parent: any reach will do
      bones.push_back({j, here, here, r});
    }
  }
  return bones;
}

struct Influence {
  int joint;
  float weight;
};

}  // namespace

std::string AutomaticWeightsJob::validate() const {
  if (!skeleton) return "no skeleton";
  if (skeleton->empty()) return "the skeleton has no joints";
  if (!bindWorld) return "no bind-pose world matrices";
  if (static_cast<int>(bindWorld->size()) != skeleton->size())
    return "bindWorld has " + std::to_string(bindWorld->size()) + " matrices for " +
           std::to_string(skeleton->size()) + " joints";
  if (skeleton->size() > std::numeric_limits<uint16_t>::max() + 1)
    return "more joints than a 16-bit joint index can name";
  if (!positions) return "no positions";
  if (!outJoints || !outWeights) return "no output arrays";
  if (maxInfluences < 1 || maxInfluences > kMaxInfluences)
    return "maxInfluences must be 1.." + std::to_string(kMaxInfluences);
  if (!capsuleRadius.empty()) {
    if (static_cast<int>(capsuleRadius.size()) != skeleton->size())
      return "capsuleRadius has " + std::to_string(capsuleRadius.size()) + " entries for " +
             std::to_string(skeleton->size()) + " joints";
    for (size_t j = 0; j < capsuleRadius.size(); ++j)
      if (!(capsuleRadius[j] > 0.0f) || !std::isfinite(capsuleRadius[j]))
        return "capsuleRadius[" + std::to_string(j) + "] must be positive and finite";
  } else if (!(capsuleRadiusScale > 0.0f) || !std::isfinite(capsuleRadiusScale)) {
    return "capsuleRadiusScale must be positive and finite";
  }
  if (!(inverseDistancePower > 0.0f) || !std::isfinite(inverseDistancePower))
    return "inverseDistancePower must be positive and finite";
  for (const glm::mat4& m : *bindWorld)
    if (!isFinite(glm::vec3(m[3]))) return "a bind-pose world matrix is not finite";
  for (size_t i = 0; i < positions->size(); ++i)
    if (!isFinite((*positions)[i])) return "positions[" + std::to_string(i) + "] is not finite";
  return {};
}

// Which bones may pull a vertex, and how much. The seed's capsule weight (r - d) / r with d
// the distance to the bone fails on a body: a surface vertex lies about a limb's thickness
// from its own bone, so a thick torso capsule that overlaps the thin upper arm in the
// T-pose outweighs the arm's own bone at the shoulder, and the hips outweigh the thigh.
// We therefore measure d as the excess over the nearest bone's distance, d_j - d_nearest:
// the nearest bone always weighs 1 (dominant, so no vertex is unweighted), and a neighbour
// takes weight only within its radius of being as near - the band around an elbow, a
// knee or a spine joint where two bones are almost equally close. A hand vertex is 0.6 m
// further from the torso than from its own bones, far outside any radius, so it never
// feels the torso. Radii are per joint (capsuleRadius) so the blend bands can be set where
// the limbs are thick or thin.
bool AutomaticWeightsJob::run() const {
  if (!validate().empty()) return false;
  const std::vector<BoneSegment> bones = boneSegments(*this);
  const int joints = skeleton->size();
  const size_t count = positions->size();
  outJoints->assign(count * kMaxInfluences, 0);
  outWeights->assign(count * kMaxInfluences, 0.0f);

  std::vector<float> distance(bones.size());
  std::vector<float> jointWeight(joints);
  std::vector<Influence> influences;
  influences.reserve(joints);
  for (size_t v = 0; v < count; ++v) {
    const glm::vec3 p = (*positions)[v];
    float nearest = std::numeric_limits<float>::infinity();
    int nearestJoint = 0;
    for (size_t b = 0; b < bones.size(); ++b) {
      distance[b] = distanceToSegment(p, bones[b]);
      // Strictly nearer only: at a tie the earlier bone (a parent before its child) wins.
      if (distance[b] < nearest) {
        nearest = distance[b];
        nearestJoint = bones[b].joint;
      }
    }
    std::fill(jointWeight.begin(), jointWeight.end(), 0.0f);
    switch (method) {
      case AutomaticWeightsMethod::Nearest:
        jointWeight[nearestJoint] = 1.0f;
        break;
      case AutomaticWeightsMethod::Capsule:
        for (size_t b = 0; b < bones.size(); ++b) {
          const float w = 1.0f - (distance[b] - nearest) / bones[b].radius;
          if (w > 0.0f) jointWeight[bones[b].joint] = std::max(jointWeight[bones[b].joint], w);
        }
        jointWeight[nearestJoint] = 1.0f;
        break;
      case AutomaticWeightsMethod::InverseDistance:
        // (d_nearest / d)^power: proportional to 1 / d^power and finite. A vertex on a bone
        // (d = 0) is that bone's alone; weights under 1e-5 of the nearest's are dropped.
        for (size_t b = 0; b < bones.size(); ++b) {
          const float w = nearest > 0.0f ? std::pow(nearest / distance[b], inverseDistancePower)
                                         : (distance[b] == 0.0f ? 1.0f : 0.0f);
          if (w >= 1e-5f) jointWeight[bones[b].joint] = std::max(jointWeight[bones[b].joint], w);
        }
        jointWeight[nearestJoint] = 1.0f;
        break;
    }
    influences.clear();
    for (int j = 0; j < joints; ++j)
      if (jointWeight[j] > 0.0f) influences.push_back({j, jointWeight[j]});
    // Largest first; the nearest bone leads a tie so it stays the dominant one.
    std::sort(influences.begin(), influences.end(), [&](const Influence& x, const Influence& y) {
      if (x.weight != y.weight) return x.weight > y.weight;
      if ((x.joint == nearestJoint) != (y.joint == nearestJoint)) return x.joint == nearestJoint;
      return x.joint < y.joint;
    });
    const size_t kept = std::min(influences.size(), static_cast<size_t>(maxInfluences));
    float sum = 0.0f;
    for (size_t k = 0; k < kept; ++k) sum += influences[k].weight;
    for (size_t k = 0; k < kept; ++k) {
      (*outJoints)[v * kMaxInfluences + k] = static_cast<uint16_t>(influences[k].joint);
      (*outWeights)[v * kMaxInfluences + k] = influences[k].weight / sum;
    }
  }
  return true;
}

}  // namespace kinema
