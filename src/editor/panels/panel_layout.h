#pragma once
#include <imgui.h>

#include "editor/model/editor_layout.h"
#include "editor/model/editor_state.h"

namespace kinema {

// The panels' rectangles come from state.layout (model/editor_layout.h), computed by the
// window each frame from the window size, the splitters (Edit > Preferences keeps them) and
// the font. Scripts and the e2e tests find widgets by name (item_names.h), not by pixels.
constexpr float kOutlinerIndent = 12.0f;  // at UI scale 1
// The playhead line in the timeline and its contact lanes: Blender's playhead blue.
constexpr ImU32 kPlayheadColor = IM_COL32(71, 114, 179, 255);
// The docked panels never come to the front: floating windows stay over them, and the
// splitters (panel_splitters.cpp) over their edges.
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

// A size in pixels at UI scale 1 (what the panels were drawn for), at this frame's scale.
inline float scaled(const EditorState& state, float pixelsAtScale1) { return pixelsAtScale1 * state.layout.metrics.scale; }
inline ImVec2 scaled(const EditorState& state, ImVec2 pixelsAtScale1) {
  return ImVec2(scaled(state, pixelsAtScale1.x), scaled(state, pixelsAtScale1.y));
}

// The layout again with this frame's panels under the 3D view (a menu may have opened the
// dope sheet since the window laid out the frame).
inline void relayoutPanels(EditorState& state) {
  const ImVec2 d = ImGui::GetIO().DisplaySize;
  state.layout = computeEditorLayout(d.x, d.y, state.preferences.panels, state.bottomPanels(), state.layout.metrics);
}

// Places the next ImGui window on `r`.
inline void placeNextWindow(const PanelRect& r) {
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
}

}  // namespace kinema
