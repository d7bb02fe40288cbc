#include "render/skeleton_draw_list.h"

#include <algorithm>
#include <string>

#include "render/camera.h"

namespace kinema {

glm::mat4 boneMatrix(const glm::vec3& head, const glm::vec3& tail, const glm::vec3& rollHint) {
  const glm::vec3 d = tail - head;
  const float length = glm::length(d);
  const glm::vec3 y = d / length;
  // Gram-Schmidt the hint against the bone; fall back to any perpendicular when parallel.
  glm::vec3 x = rollHint - y * glm::dot(rollHint, y);
  if (glm::length(x) < 1e-4f) {
    const glm::vec3 other = std::abs(y.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    x = other - y * glm::dot(other, y);
  }
  x = glm::normalize(x);
  const glm::vec3 z = glm::cross(x, y);  // right-handed: x cross y = z
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x * length, 0.0f);
  m[1] = glm::vec4(y * length, 0.0f);
  m[2] = glm::vec4(z * length, 0.0f);
  m[3] = glm::vec4(head, 1.0f);
  return m;
}

std::string SkeletonDrawJob::validate() const {
  if (!parents || !world) return "skeleton drawing needs parents and world transforms";
  if (parents->size() != world->size()) return "skeleton drawing: parents and world transforms differ in count";
  for (size_t i = 0; i < parents->size(); ++i) {
    const int p = (*parents)[i];
    if (p < -1 || p >= static_cast<int>(i)) return "skeleton drawing: joint " + std::to_string(i) + " has a bad parent";
  }
  if (shownJoints && !shownJoints->empty() && shownJoints->size() != parents->size())
    return "skeleton drawing: the shown-joint flags and the joints differ in count";
  if (looseJoints && !looseJoints->empty() && looseJoints->size() != parents->size())
    return "skeleton drawing: the loose-joint flags and the joints differ in count";
  return {};
}

std::vector<char> skinJointMask(const Scene& scene) {
  std::vector<char> mask;
  if (scene.skins.empty()) return mask;
  mask.assign(static_cast<size_t>(scene.skeleton.size()), 0);
  for (const Skin& skin : scene.skins)
    for (int j : skin.joints)
      if (j >= 0 && j < static_cast<int>(mask.size())) mask[j] = 1;
  return mask;
}

bool SkeletonDrawJob::run(SkeletonDrawList& out) const {
  out = SkeletonDrawList{};
  if (!validate().empty()) return false;
  const std::vector<int>& par = *parents;
  const std::vector<glm::mat4>& w = *world;
  const int n = static_cast<int>(par.size());
  auto pos = [&w](int i) { return glm::vec3(w[i][3]); };
  const bool filtered = shownJoints && !shownJoints->empty();
  auto shown = [&](int i) { return !filtered || (*shownJoints)[i] != 0; };
  // Each joint's nearest shown ancestor, in one forward pass (parents come first).
  std::vector<int> drawnParent(n, -1);
  // Loose: the link from the nearest shown ancestor is not a bone, because the joint or a
  // hidden joint between them moves on its own.
  const bool anyLoose = looseJoints && !looseJoints->empty();
  std::vector<char> looseLink(n, 0);
  for (int i = 0; i < n; ++i) {
    const int p = par[i];
    drawnParent[i] = p < 0 ? -1 : shown(p) ? p : drawnParent[p];
    if (anyLoose && p >= 0) looseLink[i] = (*looseJoints)[i] != 0 || (!shown(p) && looseLink[p] != 0);
  }

  // Joint radius: a tenth of the shortest bone touching the joint (Blender's proportion),
  // capped by the skeleton's size so tiny or huge bones stay readable. The size is taken in
  // steps (steadySceneRadius), so a pose that moves a hand leaves the other joints' spheres
  // as they were (and a partial redraw to the part that moved: SceneDamageJob).
  Bounds shownBounds;
  for (int i = 0; i < n; ++i)
    if (shown(i)) shownBounds.add(pos(i));
  const float size = steadySceneRadius(shownBounds.radius());
  std::vector<float> shortest(n, 0.0f);
  for (int i = 0; i < n; ++i) {
    const int p = drawnParent[i];
    if (p < 0 || !shown(i)) continue;
    const float len = glm::length(pos(i) - pos(p));
    if (len <= size * 1e-4f) continue;
    if (looseLink[i]) {
      out.relationships.push_back({pos(p), pos(i), style.relationship, p, i});
      continue;
    }
    for (int j : {i, p}) shortest[j] = shortest[j] == 0.0f ? len : std::min(shortest[j], len);
    out.boneMatrices.push_back(boneMatrix(pos(p), pos(i), glm::vec3(w[p][0])));
    out.boneColors.push_back(p == selectedJoint ? style.selectedBone : style.bone);
    out.boneParents.push_back(p);
    out.boneChildren.push_back(i);
  }
  for (int i = 0; i < n; ++i) {
    if (!shown(i)) continue;
    const float r = std::clamp(shortest[i] > 0.0f ? shortest[i] * 0.1f : size * 0.02f, size * 0.008f, size * 0.025f);
    glm::mat4 m(r);
    m[3] = glm::vec4(pos(i), 1.0f);
    out.jointMatrices.push_back(m);
    out.jointColors.push_back(i == selectedJoint ? style.selectedJoint : style.joint);
    out.joints.push_back(i);
  }
  return true;
}

SkeletonDrawList keepJoints(const SkeletonDrawList& list, const std::vector<char>& keep) {
  SkeletonDrawList out;
  const auto kept = [&keep](int joint) {
    return joint >= 0 && joint < static_cast<int>(keep.size()) && keep[joint] != 0;
  };
  for (size_t b = 0; b < list.boneMatrices.size(); ++b) {
    if (b >= list.boneParents.size() || !kept(list.boneParents[b])) continue;
    out.boneMatrices.push_back(list.boneMatrices[b]);
    out.boneColors.push_back(b < list.boneColors.size() ? list.boneColors[b] : glm::vec4(1.0f));
    out.boneParents.push_back(list.boneParents[b]);
    out.boneChildren.push_back(b < list.boneChildren.size() ? list.boneChildren[b] : -1);
  }
  for (const SkeletonDrawList::Relationship& r : list.relationships)
    if (kept(r.parent)) out.relationships.push_back(r);
  for (size_t i = 0; i < list.jointMatrices.size(); ++i) {
    if (i >= list.joints.size() || !kept(list.joints[i])) continue;
    out.jointMatrices.push_back(list.jointMatrices[i]);
    out.jointColors.push_back(i < list.jointColors.size() ? list.jointColors[i] : glm::vec4(1.0f));
    out.joints.push_back(list.joints[i]);
  }
  return out;
}

}  // namespace kinema
