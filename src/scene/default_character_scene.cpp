#include "scene/default_character_scene.h"

#include <map>

#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "skin/default_body_mesh.h"
#include "skin/default_face_shapes.h"

namespace kinema {

namespace {

// The part of a joint's name before ".L"/".R".
std::string baseName(const std::string& name) {
  const size_t dot = name.rfind('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

}  // namespace

// Each radius is the width of the band where the joint's bone blends into a neighbour:
// wide along the spine (it bends as a whole), a hand's width at elbows, knees and the
// shoulder, small at the ends (a childless end joint only ties with its parent's bone tip).
std::vector<float> defaultCharacterCapsuleRadii(const Skeleton& skeleton) {
  static const std::map<std::string, float> radius = {
      {"Hips", 0.10f},      {"Spine", 0.08f},     {"Chest", 0.08f},    {"UpperChest", 0.07f},
      {"Neck", 0.05f},      {"Head", 0.05f},      {"HeadTop", 0.01f},  {"Shoulder", 0.05f},
      {"UpperArm", 0.06f},  {"LowerArm", 0.05f},  {"Hand", 0.04f},     {"Fingertip", 0.01f},
      {"UpperLeg", 0.10f},  {"LowerLeg", 0.06f},  {"Foot", 0.04f},     {"Toe", 0.03f},
      {"ToeTip", 0.01f},
  };
  std::vector<float> radii;
  for (const std::string& name : skeleton.names) {
    const auto it = radius.find(baseName(name));
    radii.push_back(it == radius.end() ? 0.05f : it->second);
  }
  return radii;
}

Scene makeDefaultCharacterScene() {
  Scene scene;
  scene.source = "default character";
  scene.skeleton = makeDefaultCharacter();
  const Skeleton& s = scene.skeleton;
  const std::vector<glm::mat4> restWorld = computeWorld(s, Pose::rest(s));

  // The body is generated in the T-pose's world space, which is the bind space.
  MeshPrimitive body = makeDefaultBodyMesh();
  AutomaticWeightsJob weights;
  weights.skeleton = &s;
  weights.bindWorld = &restWorld;
  weights.positions = &body.positions;
  weights.method = AutomaticWeightsMethod::Capsule;
  weights.capsuleRadius = defaultCharacterCapsuleRadii(s);
  weights.maxInfluences = 4;
  weights.outJoints = &body.influenceJoints;
  weights.outWeights = &body.influenceWeights;
  weights.run();  // inputs made above, always valid
  body.material = 0;
  addDefaultFaceShapes(body);  // jaw_open, smile, brow_raise, blink: morph targets at weight 0

  Material clay;
  clay.name = "Clay";
  clay.baseColor = glm::vec4(0.78f, 0.66f, 0.56f, 1.0f);
  scene.materials.push_back(clay);

  Mesh mesh;
  mesh.name = "Body";
  mesh.primitives.push_back(std::move(body));
  mesh.targetNames = kDefaultFaceShapeNames;
  mesh.morphWeights.assign(kDefaultFaceShapeNames.size(), 0.0f);
  scene.meshes.push_back(std::move(mesh));

  Skin skin;
  skin.name = "Body";
  for (int j = 0; j < s.size(); ++j) {
    skin.joints.push_back(j);
    skin.inverseBind.push_back(glm::inverse(restWorld[j]));
  }
  skin.skeletonRoot = 0;
  scene.skins.push_back(std::move(skin));

  MeshInstance instance;
  instance.joint = 0;
  instance.mesh = 0;
  instance.skin = 0;
  scene.meshInstances.push_back(instance);
  return scene;
}

bool bindMeshWithAutomaticWeights(Scene& scene, int meshInstance, AutomaticWeightsMethod method,
                                  std::string& error) {
  const int instances = static_cast<int>(scene.meshInstances.size());
  if (meshInstance < 0 || meshInstance >= instances) {
    error = "mesh instance " + std::to_string(meshInstance) + " does not exist (the scene has " +
            std::to_string(instances) + ")";
    return false;
  }
  const MeshInstance& instance = scene.meshInstances[meshInstance];
  const std::string which = "mesh instance " + std::to_string(meshInstance);
  if (instance.skin >= 0) {
    error = which + " is already skinned (skin " + std::to_string(instance.skin) + ")";
    return false;
  }
  if (instance.mesh < 0 || instance.mesh >= static_cast<int>(scene.meshes.size())) {
    error = which + " shows no mesh";
    return false;
  }
  const Skeleton& s = scene.skeleton;
  if (const std::string problem = s.validate(); !problem.empty() || s.empty()) {
    error = "the skeleton cannot be bound to: " + (problem.empty() ? std::string("it has no joints") : problem);
    return false;
  }
  if (instance.joint >= s.size()) {
    error = which + " sits on joint " + std::to_string(instance.joint) + ", which does not exist";
    return false;
  }

  const std::vector<glm::mat4> restWorld = computeWorld(s, Pose::rest(s));
  const glm::mat4 meshWorld = instance.joint >= 0 ? restWorld[instance.joint] : glm::mat4(1.0f);
  Mesh bound = scene.meshes[instance.mesh];
  for (size_t k = 0; k < bound.primitives.size(); ++k) {
    MeshPrimitive& prim = bound.primitives[k];
    std::vector<glm::vec3> world;
    world.reserve(prim.positions.size());
    for (const glm::vec3& p : prim.positions) world.push_back(glm::vec3(meshWorld * glm::vec4(p, 1.0f)));
    AutomaticWeightsJob job;
    job.skeleton = &s;
    job.bindWorld = &restWorld;
    job.positions = &world;
    job.method = method;
    job.maxInfluences = 4;
    job.outJoints = &prim.influenceJoints;
    job.outWeights = &prim.influenceWeights;
    if (const std::string problem = job.validate(); !problem.empty()) {
      error = which + ", primitive " + std::to_string(k) + ": " + problem;
      return false;
    }
    job.run();
  }

  // Other instances of the same mesh stay unskinned: they get the original.
  bool shared = false;
  for (int i = 0; i < instances; ++i)
    shared = shared || (i != meshInstance && scene.meshInstances[i].mesh == instance.mesh);
  int meshIndex = instance.mesh;
  if (shared) {
    meshIndex = static_cast<int>(scene.meshes.size());
    scene.meshes.push_back(std::move(bound));
  } else {
    scene.meshes[meshIndex] = std::move(bound);
  }

  // Skinning ignores the instance's own transform (glTF), so the inverse bind matrices
  // carry it: joint world x inverse bind = meshWorld at rest, where the mesh stood.
  Skin skin;
  skin.name = scene.meshes[meshIndex].name.empty() ? "Automatic weights" : scene.meshes[meshIndex].name;
  for (int j = 0; j < s.size(); ++j) {
    skin.joints.push_back(j);
    skin.inverseBind.push_back(glm::inverse(restWorld[j]) * meshWorld);
  }
  MeshInstance& target = scene.meshInstances[meshInstance];
  target.mesh = meshIndex;
  target.skin = static_cast<int>(scene.skins.size());
  scene.skins.push_back(std::move(skin));
  error.clear();
  return true;
}

}  // namespace kinema
