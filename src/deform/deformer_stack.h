#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/mesh.h"
#include "deform/axis_deformers.h"
#include "deform/ffd_lattice.h"
#include "deform/soft_selection.h"

namespace kinema {

enum class DeformerType { Lattice, Bend, Twist, Taper, SoftPull };
const char* toString(DeformerType type);
bool fromString(const std::string& s, DeformerType& out);

// One entry of a mesh's deformer stack. Deformers act on the mesh after morph targets and
// skinning, in world space (metres), each in its own space: the world, or a joint's when
// parentJoint >= 0 (then the deformer moves with that joint: its space is
// world[parentJoint] * inverse(parentRest), parentRest being the joint's world matrix when the
// deformer was placed). Exactly one of lattice / axis / pull is used, by `type`.
struct Deformer {
  std::string name;
  DeformerType type = DeformerType::Lattice;
  bool enabled = true;
  int parentJoint = -1;
  glm::mat4 parentRest{1.0f};
  // Per primitive of the mesh: empty (full effect on every vertex), or one weight in [0, 1]
  // per vertex (a vertex group): each vertex moves by weight times the deformer's offset.
  std::vector<std::vector<float>> weights;
  FfdLattice lattice;  // Lattice
  AxisDeformer axis;   // Bend, Twist, Taper (axis.kind matches type)
  SoftPull pull;       // SoftPull

  // Empty when usable; otherwise one sentence naming the problem (not its owner's place).
  std::string validate(int jointCount) const;
};

// A mesh's deformers, applied in order.
struct DeformerStack {
  std::vector<Deformer> deformers;

  bool empty() const { return deformers.empty(); }
  // The deformer called `name`, or null.
  const Deformer* find(const std::string& name) const;
  Deformer* find(const std::string& name);
  // Empty when the stack can deform `mesh` on a skeleton of `jointCount` joints: every
  // deformer valid (Deformer::validate), named (non-empty, no '/', unique in the stack: the
  // name is how animation channels find it, "deformers/NAME/PARAM"), with no more weight
  // lists than the mesh has primitives and each non-empty list one weight per vertex.
  // Otherwise one sentence starting "deformer K ('name'): ".
  std::string validate(const Mesh& mesh, int jointCount) const;
};

// The keyable parameters of a deformer, by name: Bend/Twist "angle" (radians), Taper
// "factor", SoftPull "offset.x|y|z" (metres), Lattice "point.N.x|y|z" (metres, N the flat
// index FfdLattice::index). Keys on them are Scalar channels (see docs/kinema-format.md).
std::vector<std::string> deformerParameters(const Deformer& deformer);
bool getDeformerParameter(const Deformer& deformer, const std::string& name, float& value);
bool setDeformerParameter(Deformer& deformer, const std::string& name, float value);

// Where the deformer's space sits in the world (identity for a world-parented deformer).
// `world` holds one model-space matrix per joint; null or short counts as no parent.
glm::mat4 deformerFrame(const Deformer& deformer, const std::vector<glm::mat4>* world);

// Runs a stack on one primitive's vertices (skinned, world space): every enabled deformer in
// order, each blending by its weights for `primitive`. In-place (out == positions) allowed.
struct DeformerStackJob {
  const DeformerStack* stack = nullptr;
  int primitive = 0;                              // which entry of each deformer's weights
  const glm::vec3* positions = nullptr;
  int count = 0;
  const std::vector<glm::mat4>* world = nullptr;  // needed when a deformer has a parent joint
  glm::vec3* outPositions = nullptr;

  std::string validate() const;
  bool run() const;
};

// Area-weighted vertex normals of a triangle list (each triangle's cross product added to its
// three corners, then normalised; a vertex on no triangle keeps +Y). What a deformed mesh is
// shaded with, since the deformers do not carry normals.
void computeVertexNormals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                          std::vector<glm::vec3>& normals);

// "Apply deformer as shape": the morph target that takes `before` to `after` (position deltas;
// normal deltas from the two meshes' area-weighted normals when `indices` is given).
MorphTarget shapeFromDeformation(const std::vector<glm::vec3>& before, const std::vector<glm::vec3>& after,
                                 const std::vector<uint32_t>& indices);

}  // namespace kinema
