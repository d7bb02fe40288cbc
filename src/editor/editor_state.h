#pragma once
#include <vector>

#include "io/scene.h"
#include "render/camera.h"

namespace kinema {

// Everything the editor shows and edits, owned by the caller (no globals). Panels read and
// write it; evaluateEditorPose() turns it into world transforms. Later editor features
// (undo, gizmos, keyframing) add their state here.
struct EditorState {
  Scene scene;
  int clip = 0;            // the clip the timeline plays, when the scene has clips
  double time = 0.0;       // seconds
  bool playing = false;
  bool loop = true;        // playback wraps at the clip's end (sampling itself always clamps)
  int selectedJoint = -1;  // -1: nothing selected
  OrbitCamera camera;
  bool showGrid = true;

  // Derived each frame from the fields above.
  Pose pose;
  std::vector<glm::mat4> world;

  bool hasMotion() const { return clip >= 0 && clip < static_cast<int>(scene.clips.size()); }
  double duration() const;       // the clip's length in seconds, 0 without motion
  double frameTime() const;      // the clip's frame time, or 1/30 s
  long long frameCount() const;  // frames on the clip's grid, at least 1
};

// Samples the current clip at state.time into state.pose and runs FK into state.world.
void evaluateEditorPose(EditorState& state);
// Advances playback by dt seconds (wrapping or stopping at the end).
void advancePlayback(EditorState& state, double dt);

}  // namespace kinema
