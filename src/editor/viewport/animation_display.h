#pragma once
#include <vector>

#include "editor/model/editor_state.h"
#include "editor/model/motion_path.h"
#include "editor/model/onion_skin.h"
#include "render/overlay_draw_list.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

// The viewport drawing of the onion skin, the motion path and the motion-control ticks,
// built each frame from EditorState (window-free: the renderer draws what these fill).

// One draw list per ghost, every bone and joint in the ghost's tint (joints a shade darker).
// `shownJoints` as in SkeletonDrawJob (empty: every joint).
std::vector<SkeletonDrawList> buildGhostDrawLists(const std::vector<int>& parents, const std::vector<char>& shownJoints,
                                                  const std::vector<GhostFrame>& ghosts,
                                                  const std::vector<std::vector<glm::mat4>>& poses);

// The path as a polyline with a dot at every frame, a larger one where the joint is keyed.
void addMotionPathOverlay(const MotionPath& path, const glm::vec4& color, OverlayDrawList& out);

// Tick marks at equal times along a translation path (world points), as short screen-sized
// diamonds; the first and last are larger.
void addMotionControlTicks(const std::vector<glm::vec3>& points, OverlayDrawList& out);

// What the editor draws this frame for the three features, and what it reports in the dump.
struct AnimationDisplay {
  std::vector<GhostFrame> ghosts;
  // Drawn as bodies (ghostsShowBodies): each ghost's joints and morph weights, for the mesh
  // renderer; else as bones: one draw list per ghost.
  bool ghostBodies = false;
  std::vector<std::vector<glm::mat4>> ghostPoses;
  std::vector<std::vector<std::vector<float>>> ghostMorphWeights;
  std::vector<SkeletonDrawList> ghostLists;
  MotionPath path;
  std::vector<glm::vec3> ticks;  // world positions of the motion-control ticks
  // What `path` was computed from (it is recomputed only when one of these changes).
  struct PathKey {
    long long changes = -1;
    int clip = -1, joint = -1;
    long long first = 0, last = -1;
    size_t channels = 0;
    float duration = -1.0f;
    bool operator==(const PathKey& o) const {
      return changes == o.changes && clip == o.clip && joint == o.joint && first == o.first && last == o.last &&
             channels == o.channels && duration == o.duration;
    }
  } pathKey;
};

// Fills `display` from the state (ghosts of state.clip around state.time, the active joint's
// path and ticks) and appends the path and ticks to `overlay`. Keep `display` from frame to
// frame: the motion path is recomputed only when the document, clip, joint or range changed.
void buildAnimationDisplay(const EditorState& state, const std::vector<char>& shownJoints, AnimationDisplay& display,
                           OverlayDrawList& overlay);

}  // namespace kinema
