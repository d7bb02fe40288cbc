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

}  // namespace kinema
