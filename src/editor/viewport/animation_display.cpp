#include "editor/viewport/animation_display.h"

#include <algorithm>

#include "editor/model/motion_control.h"
#include "editor/model/timeline.h"
#include "evaluation/scene_deformation.h"

namespace kinema {

std::vector<SkeletonDrawList> buildGhostDrawLists(const std::vector<int>& parents, const std::vector<char>& shownJoints,
                                                  const std::vector<GhostFrame>& ghosts,
                                                  const std::vector<std::vector<glm::mat4>>& poses) {
  std::vector<SkeletonDrawList> out;
  for (size_t g = 0; g < ghosts.size() && g < poses.size(); ++g) {
    SkeletonDrawJob job;
    job.parents = &parents;
    job.world = &poses[g];
    job.shownJoints = &shownJoints;
    job.style.bone = ghosts[g].color;
    job.style.joint = glm::vec4(glm::vec3(ghosts[g].color) * 0.6f, ghosts[g].color.a);
    SkeletonDrawList list;
    if (job.run(list)) out.push_back(std::move(list));
  }
  return out;
}

void addMotionPathOverlay(const MotionPath& path, const glm::vec4& color, OverlayDrawList& out) {
  if (path.points.empty()) return;
  const glm::vec4 line(glm::vec3(color) * 0.8f, color.a);
  out.addPolyline(path.points, false, line, 2.0f);
  for (size_t i = 0; i < path.points.size(); ++i) {
    // Keyed frames: a larger dot in the path's colour (mocap keys every frame: a bead chain);
    // other frames: a small white dot. No outlines, which would turn dense paths black.
    out.addHandle(path.points[i], path.keyed[i] ? 3.5f : 2.0f, path.keyed[i] ? color : glm::vec4(1.0f),
                  OverlayDrawList::HandleShape::Disc);
    out.handles.back().outline.a = 0.0f;
  }
}

void addMotionControlTicks(const std::vector<glm::vec3>& points, OverlayDrawList& out) {
  const glm::vec4 color(1.0f, 0.30f, 0.85f, 1.0f);  // magenta: apart from the path's yellow
  if (points.size() >= 2) out.addPolyline(points, false, glm::vec4(glm::vec3(color) * 0.7f, 0.8f), 1.0f);
  for (size_t i = 0; i < points.size(); ++i) {
    const bool end = i == 0 || i + 1 == points.size();
    out.addHandle(points[i], end ? 5.0f : 3.5f, color, OverlayDrawList::HandleShape::Diamond);
  }
}


void buildAnimationDisplay(const EditorState& state, const std::vector<char>& shownJoints, AnimationDisplay& display,
                           OverlayDrawList& overlay) {
  display.ghosts.clear();
  display.ghostBodies = false;
  display.ghostPoses.clear();
  display.ghostMorphWeights.clear();
  display.ghostLists.clear();
  display.ticks.clear();
  if (!state.hasMotion()) {
    display.path = MotionPath{};
    display.pathKey = {};
    return;
  }
  const Scene& scene = state.doc.scene();
  const Clip& clip = scene.clips[state.clip];
  const FrameGrid grid = scene.frameGrid(state.clip);
  const long long current = grid.nearestFrame(state.time);
  if (state.onionSkin.enabled) {
    display.ghosts = ghostFrames(state.onionSkin, current, grid.nearestFrame(clip.duration()) + 1);
    EvaluationStages stages;  // as the timeline evaluates the current frame (timeline.cpp)
    stages.dynamics = state.liveSprings.enabled;
    const IkRig rig = state.doc.savedRig();
    display.ghostPoses =
        ghostPoses(scene, state.clip, display.ghosts, stages, rangeStartFrame(state), state.doc.changeCount(), &rig);
    display.ghostBodies = ghostsShowBodies(state.onionSkin, scene);
    if (display.ghostBodies) {
      for (const GhostFrame& g : display.ghosts)
        display.ghostMorphWeights.push_back(sampleMorphWeights(scene, state.clip, grid.frameToTime(g.frame)));
    } else {
      display.ghostLists = buildGhostDrawLists(scene.skeleton.parents, shownJoints, display.ghosts, display.ghostPoses);
    }
  }
  const int joint = state.doc.selection.active();
  if (state.motionPath.enabled && joint >= 0) {
    long long first = 0, last = -1;
    motionPathRange(state.motionPath, clip, grid, current, first, last);
    const AnimationDisplay::PathKey key{state.doc.changeCount(), state.clip, joint, first, last,
                                        clip.channels.size(), clip.duration()};
    if (!(key == display.pathKey)) {
      const IkRig rig = state.doc.savedRig();
      display.path = computeMotionPath(scene, state.clip, joint, first, last, &rig);
      display.pathKey = key;
    }
    addMotionPathOverlay(display.path, state.motionPath.color, overlay);
  } else {
    display.path = MotionPath{};
    display.pathKey = {};
  }
  const MotionControlSettings& mc = state.motionControl;
  if (mc.windowOpen && mc.showTicks && joint >= 0) {
    const int index = translationChannelIndex(clip, joint);
    if (index >= 0) {
      const Channel& path = clip.channels[index];
      const int frames = static_cast<int>(grid.nearestFrame(path.endTime()) - grid.nearestFrame(path.startTime()));
      display.ticks = equalTimeTicks(path, mc.profile, std::clamp(frames, 1, 2000));
      // The channel is in the parent's space: placed by the parent's current world transform.
      const int parent = scene.skeleton.parents[joint];
      if (parent >= 0 && parent < static_cast<int>(state.world().size()))
        for (glm::vec3& p : display.ticks) p = glm::vec3(state.world()[parent] * glm::vec4(p, 1.0f));
      addMotionControlTicks(display.ticks, overlay);
    }
  }
}

}  // namespace kinema
