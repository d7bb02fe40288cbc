#pragma once
#include <string>

#include "editor/model/document.h"
#include "editor/model/editor_state.h"
#include "editor/model/key_preferences.h"

namespace kinema {

// Shape sliders (issue 22): the weight of each morph target of a mesh instance, set by hand
// and keyed like a joint channel, as Blender's shape key values. A keyed weight is a Scalar
// channel "weights/K" on the instance's joint (anim/scalar_property.h), so the timeline, the
// dope sheet and the curve editor show it with the joints' channels.

// How many morph targets the instance's mesh has (its first primitive's); 0 for a bad index.
int shapeCount(const Document& doc, int instance);
// The target's name (the mesh's target name, else "Shape K").
std::string shapeName(const Document& doc, int instance, int target);
// The weight the slider shows at `time` in `clip`: the clip's channel when it animates the
// target, else the instance's weight, else the mesh's default (sampleMorphWeights' order).
float shapeWeightAt(const Document& doc, int clip, double time, int instance, int target);

// Sets the instance's own weight of a target (one undo step; the instance's weights are
// made from the mesh's defaults first). A weight is any finite number (0..1 is the usual
// range, as in Blender's slider; outside it extrapolates).
std::string setShapeWeight(Document& doc, int instance, int target, float weight);
// Keys `weight` for the target at `time` into clips[clip] (one undo step); `clip` naming
// no clip yet creates "Action" (the active clip) and is set to it.
std::string keyShapeWeight(Document& doc, int& clip, int instance, int target, float time, float weight,
                           const KeyPreferences& preferences);
// Keys every shape of every mesh instance at `time` with the weight it shows there
// (shapeWeightAt), one undo step per shape. Returns "" or the first error; `keyed` gets
// how many keys were written.
std::string keyAllShapeWeights(Document& doc, int& clip, float time, const KeyPreferences& preferences, int& keyed);
// True when clips[clip] has a channel for the target (the slider then keys what it is set to).
bool shapeAnimated(const Document& doc, int clip, int instance, int target);

// "Apply Deformer as Shape" (Blender's "Apply as Shape Key"): deformer `deformer` of the
// instance's stack becomes a morph target named after it (BakeDeformersJob at the rest pose:
// the world displacement it adds there, taken back through the skinning) and leaves the
// stack; the new shape's weight is 0, as in Blender, so its slider brings the effect back.
// One undo step.
std::string applyDeformerAsShape(Document& doc, int instance, int deformer);

// The editor's actions at the playhead, with the auto-key preferences; they return the
// status line. The slider: keys when the shape is animated in the clip or auto-key is on,
// else sets the instance's weight. "Insert Shape Keys": keyAllShapeWeights.
std::string moveShapeSlider(EditorState& state, int instance, int target, float weight);
std::string keyAllShapes(EditorState& state);

}  // namespace kinema
