#include "editor/model/property_keying.h"

#include "editor/model/deformer_edits.h"
#include "editor/model/editor_state.h"
#include "editor/model/shape_keys.h"
#include "editor/model/timeline.h"

namespace kinema {

std::string keyHoveredProperty(EditorState& state) {
  const HoveredProperty h = state.hoveredProperty;  // a copy: the edits below do not keep a reference into the state
  Document& doc = state.doc;
  const int clip = state.hasMotion() ? state.clip : -1;
  const float time = static_cast<float>(state.time);
  std::string error, what;
  switch (h.kind) {
    case HoveredProperty::Kind::None: return "Insert Keyframe: no keyable property under the mouse";
    case HoveredProperty::Kind::ShapeWeight: {
      const float weight = shapeWeightAt(doc, clip, state.time, h.instance, h.target);
      error = keyShapeWeight(doc, state.clip, h.instance, h.target, time, weight, doc.autoKey.preferences);
      what = shapeName(doc, h.instance, h.target);
      break;
    }
    case HoveredProperty::Kind::DeformerParameter: {
      const float value = deformerValueAt(doc, clip, state.time, h.instance, h.deformer, h.parameter);
      error = keyDeformerValue(doc, state.clip, h.instance, h.deformer, h.parameter, time, value, doc.autoKey.preferences);
      const DeformerStack* stack = doc.scene().deformerStack(static_cast<size_t>(h.instance));
      what = (stack && h.deformer >= 0 && h.deformer < static_cast<int>(stack->deformers.size())
                  ? stack->deformers[h.deformer].name + " "
                  : std::string()) +
             h.parameter;
      break;
    }
  }
  syncDocumentPlayhead(state);
  return error.empty() ? "Inserted a key on " + what + " on frame " + std::to_string(currentFrame(state)) : error;
}

}  // namespace kinema
