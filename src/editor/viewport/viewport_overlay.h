#pragma once
#include "editor/model/editor_state.h"
#include "editor/viewport/viewport_tools.h"
#include "render/overlay_draw_list.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

// What the viewport draws over the skeleton this frame (editor-viewport's overlay builder):
// the rotate gizmo on the active joint, IK target handles, the selected joints' limit
// shapes, the box being dragged, the R-mode line from the pivot to the mouse, and in lattice
// edit mode the lattice's cage.
void buildViewportOverlay(const EditorState& state, const ViewportView& view, const ViewportTools& tools,
                          OverlayDrawList& out);

// Colours every selected joint and its outgoing bones like the renderer's single selection,
// and the hovered joint lighter.
void colorSelection(const EditorState& state, SkeletonDrawList& list);

// With the bones hidden (ViewOptions::showBones off) the selection is still drawn: `out`
// gets the selected joints and the bones leaving them from `list` (coloured by
// colorSelection), which the window draws x-ray over the body, as Blender shows the
// selected bones of a hidden armature. Returns false (out empty) when the bones are shown
// or nothing selected is drawn.
bool hiddenBonesSelection(const EditorState& state, const SkeletonDrawList& list, SkeletonDrawList& out);

}  // namespace kinema
