#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace kinema {

// Colours of the skeleton drawing (linear RGB 0..1, alpha 1). Blender-like defaults.
struct SkeletonStyle {
  glm::vec4 bone{0.72f, 0.72f, 0.74f, 1.0f};
  glm::vec4 joint{0.32f, 0.34f, 0.40f, 1.0f};
  glm::vec4 selectedBone{1.0f, 0.62f, 0.20f, 1.0f};
  glm::vec4 selectedJoint{1.0f, 0.55f, 0.10f, 1.0f};
  // Dashed relationship lines to joints not connected to their parent (loose_joints.h).
  glm::vec4 relationship{0.78f, 0.78f, 0.80f, 1.0f};
  // Bones drawn x-ray over a (usually light) body: a blue that stands out from skin tones,
  // 60% opaque so the body shows through; the selection stays opaque so it stands out.
  static SkeletonStyle xRay() {
    SkeletonStyle s;
    s.bone = glm::vec4(0.30f, 0.52f, 0.95f, 0.6f);
    s.joint = glm::vec4(0.12f, 0.20f, 0.45f, 0.6f);
    s.relationship = glm::vec4(0.55f, 0.70f, 1.0f, 0.9f);
    return s;
  }
};

// What the renderer draws for a posed skeleton, computed on the CPU from FK output only.
// Bones: one octahedron per (parent, child) pair, as instance matrices that take the unit
// bone of makeOctahedralBone() to the segment parent -> child. Joints: one sphere each.
struct SkeletonDrawList {
  std::vector<glm::mat4> boneMatrices;
  std::vector<glm::vec4> boneColors;
  std::vector<int> boneParents;   // per bone: its head joint (picking selects it)
  std::vector<int> boneChildren;  // per bone: its tail joint
  std::vector<glm::mat4> jointMatrices;  // translate(position) * scale(radius)
  std::vector<glm::vec4> jointColors;
  std::vector<int> joints;  // per sphere: its joint (spheres of joints not shown are left out)
  // Relationship lines, drawn thin and dashed in place of a bone to a joint that is not
  // connected to its parent: from the parent's position to the joint's (world space).
  struct Relationship {
    glm::vec3 from{0.0f}, to{0.0f};
    glm::vec4 color{1.0f};
    int parent = -1, child = -1;
  };
  std::vector<Relationship> relationships;
};

// The part of a drawing that shows the joints `keep` flags (one flag per skeleton joint):
// their spheres and the bones that leave them (a bone belongs to its head joint, as picking
// and the selection colours have it), with their colours. The viewport draws the selection
// alone this way while the bones are hidden.
SkeletonDrawList keepJoints(const SkeletonDrawList& list, const std::vector<char>& keep);

// Inputs of buildSkeletonDrawList, ozz-job style.
struct SkeletonDrawJob {
  const std::vector<int>* parents = nullptr;       // parents[i] < i, -1 for roots
  const std::vector<glm::mat4>* world = nullptr;   // one world transform per joint
  int selectedJoint = -1;                          // highlighted with its outgoing bones; -1 = none
  SkeletonStyle style;
  // Optional, one flag per joint: draw only these joints, with a bone from each to its
  // nearest drawn ancestor (skinJointMask: a glTF character's skin joints, not its mesh
  // and helper nodes). Null or empty: every joint.
  const std::vector<char>* shownJoints = nullptr;
  // Optional, one flag per joint (looseJoints): 1 where the joint is not connected to its
  // parent, so a dashed relationship line stands for the bone to it. Null or empty: none.
  const std::vector<char>* looseJoints = nullptr;
  // Empty when usable; otherwise what is wrong (missing arrays, sizes differ, bad parent).
  std::string validate() const;
  // Fills `out`; returns false (and leaves `out` empty) when validate() fails.
  bool run(SkeletonDrawList& out) const;
};

// One flag per skeleton joint: 1 for the joints of any of the scene's skins. Empty when the
// scene has no skins (BVH, bare skeletons), which SkeletonDrawJob reads as "every joint".
std::vector<char> skinJointMask(const Scene& scene);

// The instance matrix of a bone from `head` to `tail`: maps (0,0,0) to head, (0,1,0) to tail,
// scales uniformly by the length, and turns the waist's X axis towards `rollHint` (the
// parent joint's X axis, so octahedra twist with the joint) where that is not parallel to the bone.
glm::mat4 boneMatrix(const glm::vec3& head, const glm::vec3& tail, const glm::vec3& rollHint);

}  // namespace kinema
