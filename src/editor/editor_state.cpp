#include "editor/editor_state.h"

#include <cmath>

#include "core/forward_kinematics.h"

namespace kinema {

double EditorState::duration() const { return hasMotion() ? scene.clips[clip].duration() : 0.0; }

double EditorState::frameTime() const {
  return hasMotion() && scene.clips[clip].frameTime > 0 ? scene.clips[clip].frameTime : 1.0 / 30.0;
}

long long EditorState::frameCount() const {
  return static_cast<long long>(std::llround(duration() / frameTime())) + 1;
}

void evaluateEditorPose(EditorState& state) {
  state.pose = Pose::rest(state.scene.skeleton);
  if (state.hasMotion()) sampleClip(state.scene.clips[state.clip], static_cast<float>(state.time), state.pose);
  computeWorld(state.scene.skeleton, state.pose, state.world);
}

void advancePlayback(EditorState& state, double dt) {
  if (!state.playing || !state.hasMotion()) return;
  const double length = state.duration();
  state.time += dt;
  if (state.time <= length) return;
  if (state.loop && length > 0) {
    state.time = std::fmod(state.time, length);
  } else {
    state.time = length;
    state.playing = false;
  }
}

}  // namespace kinema
