#include "core/default_character.h"

#include <string>
#include <vector>

namespace kinema {

namespace {

// A joint of the T-pose given by its world position (metres); the rest translation is
// the difference to its parent's position.
struct JointSpec {
  std::string name;
  std::string parent;  // empty for the root
  glm::vec3 world;
};

}  // namespace

Skeleton makeDefaultCharacter() {
  std::vector<JointSpec> specs = {
      {"Hips", "", {0.0f, 0.95f, 0.0f}},
      {"Spine", "Hips", {0.0f, 1.05f, 0.0f}},
      {"Chest", "Spine", {0.0f, 1.20f, 0.0f}},
      {"UpperChest", "Chest", {0.0f, 1.33f, 0.0f}},
      {"Neck", "UpperChest", {0.0f, 1.50f, 0.0f}},
      {"Head", "Neck", {0.0f, 1.60f, 0.01f}},
      {"HeadTop", "Head", {0.0f, 1.80f, 0.01f}},
  };
  for (const char* side : {".L", ".R"}) {
    const float x = side[1] == 'L' ? 1.0f : -1.0f;  // the character's left is +X
    const std::string s = side;
    const std::vector<JointSpec> limbs = {
        {"Shoulder" + s, "UpperChest", {x * 0.03f, 1.45f, 0.0f}},
        {"UpperArm" + s, "Shoulder" + s, {x * 0.17f, 1.45f, 0.0f}},
        {"LowerArm" + s, "UpperArm" + s, {x * 0.45f, 1.45f, 0.0f}},
        {"Hand" + s, "LowerArm" + s, {x * 0.71f, 1.45f, 0.0f}},
        {"Fingertip" + s, "Hand" + s, {x * 0.89f, 1.45f, 0.0f}},
        {"UpperLeg" + s, "Hips", {x * 0.09f, 0.92f, 0.0f}},
        {"LowerLeg" + s, "UpperLeg" + s, {x * 0.09f, 0.50f, 0.01f}},
        {"Foot" + s, "LowerLeg" + s, {x * 0.09f, 0.08f, -0.02f}},
        {"Toe" + s, "Foot" + s, {x * 0.09f, 0.02f, 0.11f}},
        {"ToeTip" + s, "Toe" + s, {x * 0.09f, 0.02f, 0.19f}},
    };
    specs.insert(specs.end(), limbs.begin(), limbs.end());
  }
  Skeleton skeleton;
  std::vector<glm::vec3> world;
  for (const JointSpec& j : specs) {
    const int parent = j.parent.empty() ? -1 : skeleton.find(j.parent);
    const glm::vec3 origin = parent < 0 ? glm::vec3(0.0f) : world[parent];
    skeleton.addJoint(j.name, parent, Transform::fromTranslation(j.world - origin));
    world.push_back(j.world);
  }
  return skeleton;
}

}  // namespace kinema
