#include "editor/viewport/mesh_picking.h"

#include <limits>

#include "editor/viewport/picking.h"

namespace kinema {

namespace {

// The skeleton joint with the largest weight on vertex v (influences are sorted largest
// first, so the first slot); -1 when the skin data does not say.
int heaviestJoint(const Scene& scene, const MeshInstance& instance, const MeshPrimitive& p, int v) {
  if (!p.skinned() || instance.skin < 0 || instance.skin >= static_cast<int>(scene.skins.size())) return instance.joint;
  const Skin& skin = scene.skins[instance.skin];
  const size_t slot = static_cast<size_t>(v) * kMaxInfluences;
  if (slot >= p.influenceJoints.size()) return -1;
  int best = -1;
  float bestWeight = -1.0f;
  for (int k = 0; k < kMaxInfluences && slot + k < p.influenceWeights.size(); ++k) {
    const float w = p.influenceWeights[slot + k];
    if (w > bestWeight) {
      bestWeight = w;
      best = p.influenceJoints[slot + k];
    }
  }
  return best >= 0 && best < static_cast<int>(skin.joints.size()) ? skin.joints[best] : -1;
}

}  // namespace

MeshPick pickMeshJoint(const Scene& scene, const std::vector<DeformedPrimitive>& deformed, const PickRay& ray) {
  MeshPick best;
  float bestT = std::numeric_limits<float>::max();
  for (const DeformedPrimitive& d : deformed) {
    if (d.instance < 0 || d.instance >= static_cast<int>(scene.meshInstances.size())) continue;
    const MeshInstance& instance = scene.meshInstances[d.instance];
    if (instance.mesh < 0 || instance.mesh >= static_cast<int>(scene.meshes.size())) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    if (d.primitive < 0 || d.primitive >= static_cast<int>(mesh.primitives.size())) continue;
    const MeshPrimitive& p = mesh.primitives[d.primitive];
    const size_t n = d.positions.size();
    for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
      const uint32_t ia = p.indices[t], ib = p.indices[t + 1], ic = p.indices[t + 2];
      if (ia >= n || ib >= n || ic >= n) continue;
      const float hit = rayTriangleDistance(ray, d.positions[ia], d.positions[ib], d.positions[ic]);
      if (hit < 0.0f || hit >= bestT) continue;
      // The triangle's corner nearest the hit point decides the joint.
      const glm::vec3 at = ray.at(hit);
      uint32_t v = ia;
      for (uint32_t c : {ib, ic})
        if (glm::length(d.positions[c] - at) < glm::length(d.positions[v] - at)) v = c;
      const int joint = heaviestJoint(scene, instance, p, static_cast<int>(v));
      if (joint < 0) continue;
      bestT = hit;
      best.joint = joint;
      best.distance = hit;
      best.instance = d.instance;
      best.primitive = d.primitive;
      best.vertex = static_cast<int>(v);
    }
  }
  return best;
}

MeshPick pickMeshJointAt(const Scene& scene, const std::vector<glm::mat4>& world, const PickRay& ray) {
  if (scene.meshInstances.empty()) return {};
  std::vector<DeformedPrimitive> deformed;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.out = &deformed;
  if (!job.run()) return {};
  return pickMeshJoint(scene, deformed, ray);
}

}  // namespace kinema
