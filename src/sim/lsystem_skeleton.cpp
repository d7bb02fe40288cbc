#include "sim/lsystem_skeleton.h"

#include <cmath>

#include "core/forward_kinematics.h"
#include "core/pose.h"

namespace kinema {

namespace {

struct TurtleState {
  glm::vec3 position{0.0f};
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
  int joint = 0;
};

void addInfluence(MeshPrimitive& p, int joint) {
  for (int k = 0; k < kMaxInfluences; ++k) {
    p.influenceJoints.push_back(static_cast<uint16_t>(k == 0 ? joint : 0));
    p.influenceWeights.push_back(k == 0 ? 1.0f : 0.0f);
  }
}

}  // namespace

std::string LSystemTurtleJob::validate() const {
  if (!std::isfinite(angleDegrees)) return "the angle is not a finite number";
  if (!(segmentLength > 0.0f) || !std::isfinite(segmentLength))
    return "the segment length must be a positive finite number of metres";
  long depth = 0;
  size_t segments = 0;
  for (size_t i = 0; i < symbols.size(); ++i) {
    if (symbols[i] == '[') ++depth;
    if (symbols[i] == ']' && --depth < 0) return "']' at symbol " + std::to_string(i + 1) + " closes no '['";
    if (symbols[i] == 'f') ++segments;
  }
  if (depth != 0) return std::to_string(depth) + " '[' never closed";
  if (segments + 1 > maxJoints)
    return "the string has " + std::to_string(segments) + " segments, more than the " + std::to_string(maxJoints - 1) +
           " joints allowed (use fewer generations)";
  return "";
}

bool LSystemTurtleJob::run(std::string& error) {
  skeleton = Skeleton();
  leaves.clear();
  if (error = validate(); !error.empty()) return false;
  const float angle = glm::radians(static_cast<float>(angleDegrees));
  const glm::quat turnLeft = glm::angleAxis(angle, glm::vec3(0, 0, 1));
  const glm::quat turnRight = glm::angleAxis(-angle, glm::vec3(0, 0, 1));
  // Each joint's rest world frame, to express the next child's rest relative to it.
  std::vector<glm::vec3> worldPosition{glm::vec3(0.0f)};
  std::vector<glm::quat> worldRotation{glm::quat(1, 0, 0, 0)};
  skeleton.addJoint("root", -1, Transform::identity());
  TurtleState turtle;
  std::vector<TurtleState> stack;
  int segment = 0;
  for (char c : symbols) {
    switch (c) {
      case 'f': {
        const glm::vec3 next = turtle.position + turtle.orientation * glm::vec3(0.0f, segmentLength, 0.0f);
        const int parent = turtle.joint;
        const glm::quat parentInverse = glm::inverse(worldRotation[parent]);
        Transform local;
        local.translation = parentInverse * (next - worldPosition[parent]);
        local.rotation = glm::normalize(parentInverse * turtle.orientation);
        turtle.joint = skeleton.addJoint("seg_" + std::to_string(++segment), parent, local);
        turtle.position = next;
        worldPosition.push_back(next);
        worldRotation.push_back(turtle.orientation);
        break;
      }
      case '+': turtle.orientation = glm::normalize(turtle.orientation * turnLeft); break;
      case '-': turtle.orientation = glm::normalize(turtle.orientation * turnRight); break;
      case '[': stack.push_back(turtle); break;
      case ']':
        turtle = stack.back();
        stack.pop_back();
        break;
      case '@': leaves.push_back({turtle.joint, turtle.position, turtle.orientation}); break;
      default: break;  // non-terminals and other symbols draw nothing
    }
  }
  return true;
}

std::string LSystemTubeJob::validate() const {
  if (!skeleton) return "no skeleton";
  if (std::string bad = skeleton->validate(); !bad.empty()) return bad;
  if (!(radius > 0.0f) || !std::isfinite(radius)) return "the tube radius must be a positive finite number";
  if (sides < 3 || sides > 64) return "the tube needs 3 to 64 sides, found " + std::to_string(sides);
  if (!(leafSize >= 0.0f) || !std::isfinite(leafSize)) return "the leaf size must be >= 0";
  if (leaves)
    for (const LSystemLeaf& l : *leaves)
      if (l.joint < 0 || l.joint >= skeleton->size()) return "a leaf names a joint the skeleton lacks";
  return "";
}

bool LSystemTubeJob::run(std::string& error) {
  primitive = MeshPrimitive();
  skin = Skin();
  if (error = validate(); !error.empty()) return false;
  const Skeleton& s = *skeleton;
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  skin.name = "plant";
  for (int j = 0; j < s.size(); ++j) {
    skin.joints.push_back(j);
    skin.inverseBind.push_back(glm::inverse(world[j]));
  }
  MeshPrimitive& p = primitive;
  const float step = 6.283185307f / static_cast<float>(sides);
  for (int c = 1; c < s.size(); ++c) {
    const int parent = s.parents[c];
    const glm::vec3 start(world[parent][3]), end(world[c][3]);
    // The ring's axes: the child's frame (its Y runs along the segment, from the turtle).
    const glm::vec3 u = glm::normalize(glm::vec3(world[c][0])), v = glm::normalize(glm::vec3(world[c][2]));
    const uint32_t base = static_cast<uint32_t>(p.positions.size());
    for (int k = 0; k < sides; ++k) {
      const float a = step * static_cast<float>(k);
      const glm::vec3 n = std::cos(a) * u + std::sin(a) * v;
      for (const glm::vec3& centre : {start, end}) {
        p.positions.push_back(centre + radius * n);
        p.normals.push_back(n);
        addInfluence(p, parent);
      }
    }
    for (int k = 0; k < sides; ++k) {
      const uint32_t a0 = base + 2 * k, b0 = a0 + 1;
      const uint32_t a1 = base + 2 * ((k + 1) % sides), b1 = a1 + 1;
      p.indices.insert(p.indices.end(), {a0, b0, a1, a1, b0, b1});  // outward (see the winding note in the header)
    }
  }
  if (leaves && leafSize > 0.0f) {
    const float w = 0.3f * leafSize;
    for (const LSystemLeaf& leaf : *leaves) {
      const glm::vec3 corners[4] = {{0, 0, 0}, {w, 0.5f * leafSize, 0}, {0, leafSize, 0}, {-w, 0.5f * leafSize, 0}};
      for (int side = 0; side < 2; ++side) {
        const uint32_t base = static_cast<uint32_t>(p.positions.size());
        const glm::vec3 normal = leaf.orientation * glm::vec3(0, 0, side == 0 ? 1.0f : -1.0f);
        for (const glm::vec3& corner : corners) {
          p.positions.push_back(leaf.position + leaf.orientation * corner);
          p.normals.push_back(normal);
          addInfluence(p, leaf.joint);
        }
        if (side == 0) p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        else p.indices.insert(p.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
      }
    }
  }
  return true;
}

}  // namespace kinema
