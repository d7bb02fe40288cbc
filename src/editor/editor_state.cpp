#include "editor/editor_state.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"

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

double EditorState::duration() const { return hasMotion() ? scene.clips[clip].duration() : 0.0; }

double EditorState::frameTime() const {
  return hasMotion() && scene.clips[clip].frameTime > 0 ? scene.clips[clip].frameTime : 1.0 / 30.0;
}

long long EditorState::frameCount() const {
  return static_cast<long long>(std::llround(duration() / frameTime())) + 1;
}

bool EditorState::isSelected(int joint) const {
  return std::find(selection.begin(), selection.end(), joint) != selection.end();
}

std::string EditorState::documentName() const {
  const std::string& p = path.empty() ? scene.source : path;
  if (p.empty()) return "untitled";
  const size_t slash = p.find_last_of("/\\");
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

void evaluateEditorPose(EditorState& state) {
  if (state.pose.size() != state.scene.skeleton.size()) {
    state.pose = Pose::rest(state.scene.skeleton);
    state.sampleClip = true;
  }
  // The clip drives the pose while it plays or when the time was moved; edits stay otherwise.
  if (state.hasMotion() && (state.playing || state.sampleClip)) {
    state.pose = Pose::rest(state.scene.skeleton);
    sampleClip(state.scene.clips[state.clip], static_cast<float>(state.time), state.pose);
  }
  state.sampleClip = false;
  computeWorld(state.scene.skeleton, state.pose, state.world);
}

void advancePlayback(EditorState& state, double dt) {
  if (!state.playing || !state.hasMotion()) return;
  // Playback runs over the clip's range (0 .. duration unless the file sets one).
  const Clip& clip = state.scene.clips[state.clip];
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

void setSelection(EditorState& state, const std::vector<int>& joints) {
  state.selection = joints;
  state.activeJoint = joints.empty() ? -1 : joints.back();
}

void toggleSelection(EditorState& state, int joint) {
  auto it = std::find(state.selection.begin(), state.selection.end(), joint);
  if (it != state.selection.end()) {
    state.selection.erase(it);
    state.activeJoint = state.selection.empty() ? -1 : state.selection.back();
  } else {
    state.selection.push_back(joint);
    state.activeJoint = joint;
  }
}

}  // namespace kinema
