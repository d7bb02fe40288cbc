#pragma once
#include <vector>

#include "editor/viewport/viewport_view.h"
#include "scene/scene.h"
#include "evaluation/scene_deformation.h"

namespace kinema {

// A click on a skinned body without x-ray bones: the nearest triangle of the deformed meshes
// under the ray, and the skeleton joint with the largest weight at the hit triangle's vertex
// nearest the hit point (an unskinned instance: the joint it hangs from).
struct MeshPick {
  int joint = -1;  // -1: the ray crosses no mesh
  float distance = 0.0f;  // along the ray
  int instance = -1, primitive = -1, vertex = -1;
  bool hit() const { return joint >= 0; }
};

// `deformed` as SceneDeformationJob writes it for `scene` (same instance x primitive order).
MeshPick pickMeshJoint(const Scene& scene, const std::vector<DeformedPrimitive>& deformed, const PickRay& ray);

// Deforms the scene's meshes at the pose `world` on the CPU, then pickMeshJoint.
MeshPick pickMeshJointAt(const Scene& scene, const std::vector<glm::mat4>& world, const PickRay& ray);

}  // namespace kinema
