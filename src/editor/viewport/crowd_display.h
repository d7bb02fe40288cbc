#pragma once
// The crowd in the viewport (issue 24): every member of the active crowd posed at the
// playhead (as bodies through the mesh renderer's ghost path when the crowd is of the
// document's own character and its meshes are on the GPU, else as bones), the obstacles and
// the goal on the ground, and one member's impulse vectors in the seed's figure's manner.
// Built each frame from EditorState (the run itself is cached: crowd_edits.h).
#include <vector>

#include "editor/model/editor_state.h"
#include "render/overlay_draw_list.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

struct CrowdDisplay {
  // Drawn as bodies (the window hands them to the mesh renderer as ghosts): each member's joints
  // (pointing into state.crowds.preview.world), in `tint`.
  std::vector<const std::vector<glm::mat4>*> bodies;
  glm::vec4 tint{0.62f, 0.70f, 0.82f, 1.0f};
  std::vector<SkeletonDrawList> bones;
  std::vector<std::vector<float>> noMorphs;  // the members' morph weights: the meshes' defaults
  float radius = 0.0f;                       // how far from the origin the crowd reaches (model units)
};

// Brings the preview to the playhead and fills `display` (cleared first; empty when the crowd
// is not drawn). `meshesOnGpu`: the document's meshes are uploaded.
void buildCrowdDisplay(EditorState& state, const std::vector<char>& shownJoints, bool meshesOnGpu, CrowdDisplay& display);
// The obstacles, the goal and the debug member's impulses as overlay lines.
void addCrowdOverlay(const EditorState& state, OverlayDrawList& overlay);

}  // namespace kinema
