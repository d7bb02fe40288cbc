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
  glm::dvec3 world;  // double, so rest offsets like 1.05 - 0.95 come out as 0.1f
};

}  // namespace

Skeleton makeDefaultCharacter() {
  std::vector<JointSpec> specs = {
      {"Hips", "", {0.0, 0.95, 0.0}},
      {"Spine", "Hips", {0.0, 1.05, 0.0}},
      {"Chest", "Spine", {0.0, 1.20, 0.0}},
      {"UpperChest", "Chest", {0.0, 1.33, 0.0}},
      {"Neck", "UpperChest", {0.0, 1.50, 0.0}},
      {"Head", "Neck", {0.0, 1.60, 0.01}},
      {"HeadTop", "Head", {0.0, 1.80, 0.01}},
  };
  for (const char* side : {".L", ".R"}) {
    const double x = side[1] == 'L' ? 1.0 : -1.0;  // the character's left is +X
    const std::string s = side;
    const std::vector<JointSpec> limbs = {
        {"Shoulder" + s, "UpperChest", {x * 0.03, 1.45, 0.0}},
        {"UpperArm" + s, "Shoulder" + s, {x * 0.17, 1.45, 0.0}},
        {"LowerArm" + s, "UpperArm" + s, {x * 0.45, 1.45, 0.0}},
        {"Hand" + s, "LowerArm" + s, {x * 0.71, 1.45, 0.0}},
        {"Fingertip" + s, "Hand" + s, {x * 0.89, 1.45, 0.0}},
        {"UpperLeg" + s, "Hips", {x * 0.09, 0.92, 0.0}},
        {"LowerLeg" + s, "UpperLeg" + s, {x * 0.09, 0.50, 0.01}},
        {"Foot" + s, "LowerLeg" + s, {x * 0.09, 0.08, -0.02}},
        {"Toe" + s, "Foot" + s, {x * 0.09, 0.02, 0.11}},
        {"ToeTip" + s, "Toe" + s, {x * 0.09, 0.02, 0.19}},
    };
    specs.insert(specs.end(), limbs.begin(), limbs.end());
  }
  Skeleton skeleton;
  std::vector<glm::dvec3> world;
  for (const JointSpec& j : specs) {
    const int parent = j.parent.empty() ? -1 : skeleton.find(j.parent);
    const glm::dvec3 origin = parent < 0 ? glm::dvec3(0.0) : world[parent];
    skeleton.addJoint(j.name, parent, Transform::fromTranslation(glm::vec3(j.world - origin)));
    world.push_back(j.world);
  }
  return skeleton;
}

}  // namespace kinema
