#pragma once
#include <string>

namespace kinema {

// What a Scalar channel (ChannelTarget::Scalar) animates, read from its `property` path.
// Non-joint channels all go through here, so a new kind is one more case, not a new channel
// type: the clip model, the keying code, the views and the files treat every Scalar channel
// alike (one float per key on a joint, or on no joint).
//   "weights/K"             the weight of morph target K (0..999999999) of every mesh instance
//                           on the channel's joint (glTF's morph weight animation)
//   "deformers/NAME/PARAM"  parameter PARAM (deformerParameters: "angle", "factor",
//                           "offset.x", "point.12.y"...) of the deformer called NAME in the
//                           stacks of the mesh instances on the channel's joint
//   "ik/targets/K/position.C" component C (x, y or z) of the world position of saved IK
//                           target K (Scene::ik.targets, 0..999999999): the evaluation's IK
//                           stage moves the target there and solves it (its chain and solver)
// Any other text is a property Kinema keeps in files but does not evaluate.
enum class ScalarPropertyKind { Other, MorphWeight, DeformerParameter, IkTargetPosition };

struct ScalarProperty {
  ScalarPropertyKind kind = ScalarPropertyKind::Other;
  int morphTarget = -1;     // MorphWeight
  std::string deformer;     // DeformerParameter: the deformer's name (non-empty, no '/')
  std::string parameter;    // DeformerParameter: the parameter's name (non-empty)
  int ikTarget = -1;        // IkTargetPosition: the target's index
  int component = -1;       // IkTargetPosition: 0, 1, 2 for x, y, z
};

ScalarProperty parseScalarProperty(const std::string& property);
std::string morphWeightProperty(int target);
std::string deformerParameterProperty(const std::string& deformer, const std::string& parameter);
std::string ikTargetPositionProperty(int target, int component);

}  // namespace kinema
