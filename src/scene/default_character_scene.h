#pragma once
#include <string>

#include "scene/scene.h"
#include "skin/automatic_weights.h"

namespace kinema {

// The default character as a scene: makeDefaultCharacter()'s skeleton, the generated body
// (makeDefaultBodyMesh) bound to it with capsule automatic weights (top 4) through a skin
// listing every joint in order, a clay material, and one mesh instance on the root joint.
// The body carries the face's expression shapes as morph targets (addDefaultFaceShapes:
// jaw_open, smile, brow_raise, blink), all at weight 0.
Scene makeDefaultCharacterScene();

// The per-joint capsule radii (metres) the default character is bound with: how far from
// each bone the blend into its neighbours reaches (see AutomaticWeightsJob).
std::vector<float> defaultCharacterCapsuleRadii(const Skeleton& skeleton);

// Binds an unskinned mesh instance to the scene's skeleton at its rest pose: computes
// automatic weights for every primitive (at most 4 influences) and adds a skin listing every
// joint, with inverse bind matrices chosen so the rest pose shows the mesh where it stood.
// A mesh shared with other instances is copied first, so they stay as they were. Returns
// false with a one-line `error` (and changes nothing) when the instance cannot be bound.
bool bindMeshWithAutomaticWeights(Scene& scene, int meshInstance, AutomaticWeightsMethod method,
                                  std::string& error);

}  // namespace kinema
