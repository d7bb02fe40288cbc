#pragma once

namespace kinema {

// What sits under the 3D view: the timeline strip, and above it the animation editor area
// (dope sheet or curve editor, one at a time, as in Blender's bottom editor).
constexpr float kTimelineHeight = 40.0f;  // the timeline strip
constexpr float kAnimationEditorHeight = 260.0f;
struct BottomPanels {
  bool timeline = false;
  bool animationEditor = false;
  bool contactLanes = false;  // the active clip's foot contacts, a strip over the timeline
};
inline float bottomPanelsHeight(BottomPanels b) {
  return (b.timeline ? kTimelineHeight : 0.0f) + (b.animationEditor ? kAnimationEditorHeight : 0.0f);
}

}  // namespace kinema
