#pragma once
#include <string>

namespace kinema {

struct EditorState;

// The keyable field under the mouse in the Properties panel (issue 22): I there keys that
// property at the playhead, as Blender's I over a property does. The panel sets it each
// frame it draws a hovered field (and clears it first), so the keys of the next frame see
// what the user saw.
struct HoveredProperty {
  enum class Kind { None, ShapeWeight, DeformerParameter };
  Kind kind = Kind::None;
  int instance = -1;      // the mesh instance
  int target = -1;        // ShapeWeight: the morph target
  int deformer = -1;      // DeformerParameter: the index in the instance's stack
  std::string parameter;  // DeformerParameter: "angle", "point.4.y"... (deformerParameters)

  bool valid() const { return kind != Kind::None; }
};

// Keys the hovered property with the value it shows at the playhead (shapeWeightAt,
// deformerValueAt): one undo step. Returns the status line ("" never: it says what it keyed
// or why it could not).
std::string keyHoveredProperty(EditorState& state);

}  // namespace kinema
