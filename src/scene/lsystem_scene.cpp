#include "scene/lsystem_scene.h"

#include "sim/lsystem_skeleton.h"

namespace kinema {

Result<Scene> makeLSystemScene(const std::string& symbols, double angleDegrees, float segmentLength, float radius) {
  LSystemTurtleJob turtle;
  turtle.symbols = symbols;
  turtle.angleDegrees = angleDegrees;
  turtle.segmentLength = segmentLength;
  std::string error;
  if (!turtle.run(error)) return Result<Scene>::failure(error);
  LSystemTubeJob tube;
  tube.skeleton = &turtle.skeleton;
  tube.leaves = &turtle.leaves;
  tube.radius = radius > 0.0f ? radius : 0.1f * segmentLength;
  tube.leafSize = 0.4f * segmentLength;
  if (!tube.run(error)) return Result<Scene>::failure(error);
  Scene scene;
  scene.skeleton = std::move(turtle.skeleton);
  if (!tube.primitive.positions.empty()) {
    Mesh mesh;
    mesh.name = "plant";
    tube.primitive.material = 0;
    mesh.primitives.push_back(std::move(tube.primitive));
    scene.meshes.push_back(std::move(mesh));
    scene.skins.push_back(std::move(tube.skin));
    Material bark;
    bark.name = "plant";
    bark.baseColor = glm::vec4(0.35f, 0.55f, 0.25f, 1.0f);
    bark.doubleSided = true;
    scene.materials.push_back(bark);
    MeshInstance instance;
    instance.joint = 0;
    instance.mesh = 0;
    instance.skin = 0;
    scene.meshInstances.push_back(instance);
  }
  return scene;
}

}  // namespace kinema
