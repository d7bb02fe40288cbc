#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "io/scene.h"

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

// Deforms every mesh instance of a posed scene: morph targets, then skinning (linear blend
// or dual quaternion, per instance) with glTF semantics; an unskinned instance is moved by
// its joint's world transform. The CPU reference the GPU path is tested against.
struct SceneDeformationJob {
  const Scene* scene = nullptr;
  const std::vector<glm::mat4>* world = nullptr;                 // one per skeleton joint
  const std::vector<std::vector<float>>* morphWeights = nullptr;  // optional, per instance
  bool skinnedOnly = false;  // true: only skinned instances (what `kinema skin` prints)
  std::vector<DeformedPrimitive>* out = nullptr;  // one entry per instance x primitive, in order

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
