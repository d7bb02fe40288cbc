#include "editor/editor_state.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "editor/pose_edits.h"

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
  if (state.hasMotion() && state.sampleClip && !state.playing) {
    const std::string error = poseFromClip(state.doc, state.clip, state.time);
    if (!error.empty()) state.statusMessage = error;
  }
  state.sampleClip = false;
  if (state.hasMotion() && state.playing) {
    Pose pose = Pose::rest(state.doc.skeleton());
    sampleClip(state.doc.scene().clips[state.clip], static_cast<float>(state.time), pose);
    computeWorld(state.doc.skeleton(), pose, state.world);
  } else {
    state.world = state.doc.worldTransforms();
  }
}

void advancePlayback(EditorState& state, double dt) {
  if (!state.playing || !state.hasMotion()) return;
  // Playback runs over the clip's range (0 .. duration unless the file sets one).
  const Clip& clip = state.doc.scene().clips[state.clip];
  const double start = clip.playStart(), end = clip.playEnd();
  state.time += dt;
  if (state.time < start) state.time = start;
  if (state.time <= end) return;
  if (state.loop && end > start) {
    state.time = start + std::fmod(state.time - start, end - start);
  } else {
    state.time = end;
    state.playing = false;
  }
}

}  // namespace kinema
