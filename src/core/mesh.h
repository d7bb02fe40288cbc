#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace kinema {

// Most influences a vertex keeps (glTF allows any number of JOINTS_n/WEIGHTS_n sets).
constexpr int kMaxInfluences = 8;

// One blend shape of a primitive: per-vertex deltas added to the bind-pose attributes.
// normalDeltas is empty when the file gives none.
struct MorphTarget {
  std::vector<glm::vec3> positionDeltas;
  std::vector<glm::vec3> normalDeltas;
};

// A triangle list with one material. Vertex attributes are flat arrays of vertexCount().
struct MeshPrimitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // empty when the file gives none
  std::vector<glm::vec2> texcoords;  // TEXCOORD_0, or empty
  std::vector<uint32_t> indices;     // 3 per triangle (strips and fans are expanded)
  // Skinning influences, kMaxInfluences per vertex, largest weight first, zero padded,
  // weights summing to 1. Joint numbers index the Skin's `joints`, not the skeleton.
  // Both empty when the primitive is not skinned.
  std::vector<uint16_t> influenceJoints;
  std::vector<float> influenceWeights;
  std::vector<MorphTarget> targets;
  int material = -1;  // index into Scene::materials, or -1 (default grey)

  int vertexCount() const { return static_cast<int>(positions.size()); }
  bool skinned() const { return !influenceWeights.empty(); }
};

struct Mesh {
  std::string name;
  std::vector<MeshPrimitive> primitives;
  std::vector<float> morphWeights;       // default weight of each morph target
  std::vector<std::string> targetNames;  // glTF extras.targetNames, or empty
};

// Inverse bind matrices and the joints they belong to (glTF skin).
struct Skin {
  std::string name;
  std::vector<int> joints;               // skeleton joint indices
  std::vector<glm::mat4> inverseBind;    // one per joint (identity when the file has none)
  int skeletonRoot = -1;                 // skeleton joint index of glTF `skeleton`, or -1
};

// How a skinned instance blends its joints: linear blend (glTF's formula, the default) or
// dual quaternions (keeps volume on twisted limbs; a Kinema option, not in glTF).
enum class SkinningMethod { LinearBlend, DualQuaternion };

// A joint (a glTF node) that shows a mesh, deformed by a skin when it has one.
// morphWeights overrides the mesh's defaults when non-empty (glTF node.weights).
struct MeshInstance {
  int joint = -1;
  int mesh = -1;
  int skin = -1;
  std::vector<float> morphWeights;
  SkinningMethod skinning = SkinningMethod::LinearBlend;
};

// Display-only material: glTF pbrMetallicRoughness base colour factor and texture.
struct Material {
  std::string name;
  glm::vec4 baseColor{1.0f};
  int baseColorImage = -1;  // index into Scene::images (TextureImage), or -1
  bool doubleSided = false;
};

// A decoded RGBA8 image (glTF base-colour textures).
struct TextureImage {
  std::string name;
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, first row at the top
};

}  // namespace kinema
