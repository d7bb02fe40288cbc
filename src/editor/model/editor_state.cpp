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
    case ModalTool::LatticeGrab: return "lattice-grab";
  }
  return "none";
}

double EditorState::duration() const { return hasMotion() ? doc.scene().clips[clip].duration() : 0.0; }

void evaluateEditorPose(EditorState& state) {
  if (state.wasPlaying && !state.playing) state.sampleClip = true;  // paused: edit from this frame
  state.wasPlaying = state.playing;
  followDocumentClip(state);  // after undo / redo of a clip list change: the document's active clip
  syncDocumentPlayhead(state);
  const EditorState::SampledAt now{state.clip, state.time, state.doc.poseRevision(), state.doc.changeCount()};
  if (state.sampleClip || (state.playing && !(now == state.sampledAt))) {
    poseAtPlayhead(state);
    state.sampledAt = {state.clip, state.time, state.doc.poseRevision(), state.doc.changeCount()};
  }
  state.sampleClip = false;
}

void advancePlayback(EditorState& state, double dt) { advanceTimeline(state, dt); }

UserPreferences currentPreferences(const EditorState& state) {
  UserPreferences p = state.preferences;
  p.loop = state.loop;
  p.keys = state.doc.autoKey.preferences;
  return p;
}

void applyPreferences(EditorState& state, const UserPreferences& p) {
  state.preferences = p;
  state.loop = p.loop;
  state.doc.autoKey.preferences = p.keys;
}

}  // namespace kinema
