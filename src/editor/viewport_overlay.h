#pragma once
#include "editor/editor_state.h"
#include "editor/viewport_tools.h"

namespace kinema {

// The viewport's 2D overlay drawn into ImGui's background draw list (under the panels):
// the rotate gizmo's rings, IK target handles, the hover ring, the box being dragged.
// Call between ImGui::NewFrame() and ImGui::Render().
void drawViewportOverlay(const EditorState& state, const ViewportGeometry& geometry);

// Colours every selected joint's bones and sphere like the renderer's single selection.
struct SkeletonDrawList;
void colorSelection(const EditorState& state, SkeletonDrawList& list);

}  // namespace kinema
