#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace kinema {

// One primitive of a mesh instance after morph targets and skinning, in world space.
struct DeformedPrimitive {
  int instance = -1;   // index into Scene::meshInstances
  int primitive = -1;  // index into the mesh's primitives
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty when the primitive has none
};

// The morph weights of every mesh instance at `time` in `clip`: the clip's "weights/K"
// Scalar channels on the instance's joint where present, else the instance's own weights,
// else the mesh's defaults (glTF order of precedence). clip < 0: no animation.
std::vector<std::vector<float>> sampleMorphWeights(const Scene& scene, int clip, double time);

// True when some instance's stack (`stacks`, per instance) has an enabled deformer.
bool anyDeformerActive(const std::vector<DeformerStack>& stacks);

// The deformer stacks of every mesh instance at `time` in `clip` (one per instance; empty
// stacks for instances without deformers): the scene's stacks with each parameter that a
// Scalar channel "deformers/NAME/PARAM" on the instance's joint animates set to the channel's
// value (clamped to its keys), the others as saved. clip < 0: the saved stacks.
std::vector<DeformerStack> sampleDeformerStacks(const Scene& scene, int clip, double time);

// Deforms every mesh instance of a posed scene: morph targets, then skinning (linear blend
// or dual quaternion, per instance) with glTF semantics (an unskinned instance is moved by
// its joint's world transform), then the instance's deformer stack in world space
// (DeformerStackJob), whose primitives are then shaded with area-weighted normals
// (computeVertexNormals; a primitive without normals keeps none). The CPU reference the GPU
// path is tested against.
struct SceneDeformationJob {
  const Scene* scene = nullptr;
  const std::vector<glm::mat4>* world = nullptr;                 // one per skeleton joint
  const std::vector<std::vector<float>>* morphWeights = nullptr;  // optional, per instance
  // Optional, per instance (sampleDeformerStacks); null: the scene's own stacks.
  const std::vector<DeformerStack>* deformers = nullptr;
  bool skinnedOnly = false;  // true: only skinned instances (what `kinema skin` prints)
  // true: only instances whose deformer stack has an enabled deformer (what the GPU renderer
  // takes from the CPU, MeshFrame::deformed).
  bool withDeformersOnly = false;
  std::vector<DeformedPrimitive>* out = nullptr;  // one entry per instance x primitive, in order

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
