#pragma once
#include <string>
#include <utility>
#include <vector>

#include "anim/clip.h"
#include "anim/clip_keying.h"
#include "editor/model/key_preferences.h"

namespace kinema {

class Document;

// The editor's commands, each one undo step. `clip` may name no clip yet: the first key
// creates "Action" and `clip` is set to its index.
std::string insertKeys(Document& doc, int& clip, float time, const std::vector<int>& joints,
                       const KeyPreferences& preferences);
std::string insertKeysOnAllJoints(Document& doc, int& clip, float time, const KeyPreferences& preferences);
std::string deleteKeys(Document& doc, int clip, float time, const std::vector<int>& joints);
// Keys `value` at `time` on the Scalar channel (`joint`, `property`) of clips[clip], made
// when missing (non-joint channels: morph weights "weights/K", deformer parameters
// "deformers/NAME/PARAM"; anim/scalar_property.h). One undo step named `label`; `clip`
// naming no clip yet creates "Action" (the active clip) and is set to it.
std::string keyScalarProperty(Document& doc, int& clip, int joint, const std::string& property, float time, float value,
                              const KeyPreferences& preferences, const std::string& label);
// Several Scalar properties of one joint keyed at `time` in one undo step (each pair: the
// property and its value), as keyScalarProperty does for one.
std::string keyScalarProperties(Document& doc, int& clip, int joint,
                                const std::vector<std::pair<std::string, float>>& values, float time,
                                const KeyPreferences& preferences, const std::string& label);

}  // namespace kinema
