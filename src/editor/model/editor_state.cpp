#include "editor/model/editor_state.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"

namespace kinema {

const char* modalToolName(ModalTool tool) {
  switch (tool) {
    case ModalTool::None: return "none";
    case ModalTool::Rotate: return "rotate";
    case ModalTool::Grab: return "grab";
    case ModalTool::BoxSelect: return "box-select";
    case ModalTool::IkDrag: return "ik-drag";
    case ModalTool::GizmoDrag: return "gizmo-drag";
    case ModalTool::Navigate: return "navigate";
  }
  return "none";
}

double EditorState::duration() const { return hasMotion() ? doc.scene().clips[clip].duration() : 0.0; }

double EditorState::frameTime() const {
  return hasMotion() && doc.scene().clips[clip].frameTime > 0 ? doc.scene().clips[clip].frameTime : 1.0 / 30.0;
}

long long EditorState::frameCount() const {
  return static_cast<long long>(std::llround(duration() / frameTime())) + 1;
}

void evaluateEditorPose(EditorState& state) {
  if (state.wasPlaying && !state.playing) state.sampleClip = true;  // paused: edit from this frame
  state.wasPlaying = state.playing;
  syncAutoKey(state);
  if (state.hasMotion() && (state.sampleClip || state.playing)) {
    // Joints the clip does not animate keep their pose (Blender re-evaluates the action).
    Pose pose = state.doc.pose();
    sampleClip(state.doc.scene().clips[state.clip], static_cast<float>(state.time), pose);
    state.doc.setAnimatedPose(pose);
  }
  state.sampleClip = false;
  state.world = state.doc.worldTransforms();
}

void advancePlayback(EditorState& state, double dt) { advanceTimeline(state, dt); }

}  // namespace kinema
