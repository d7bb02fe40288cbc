#pragma once
#include <imgui.h>

#include "editor/model/bottom_panels.h"

namespace kinema {

// The editor's fixed panel layout (pixels, origin top left): outliner and history on the
// left, properties and IK targets on the right, the status bar along the bottom, the
// viewport in between. Scripts and the e2e tests find widgets by name (item_names.h), not by
// these pixels, so the layout may change.
struct PanelRect {
  float x, y, w, h;
};

constexpr float kMenuBarHeight = 19.0f;  // ImGui 1.86's default font and frame padding
constexpr float kStatusBarHeight = 24.0f;
constexpr float kLeftColumnWidth = 250.0f;
constexpr float kRightColumnWidth = 310.0f;
constexpr float kOutlinerIndent = 12.0f;
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

inline float panelAreaHeight(ImVec2 display) { return display.y - kMenuBarHeight - kStatusBarHeight; }

inline PanelRect outlinerRect(ImVec2 display) {
  return {0.0f, kMenuBarHeight, kLeftColumnWidth, panelAreaHeight(display) * 0.62f};
}
inline PanelRect historyRect(ImVec2 display) {
  const PanelRect o = outlinerRect(display);
  return {0.0f, o.y + o.h, kLeftColumnWidth, panelAreaHeight(display) - o.h};
}
inline PanelRect propertiesRect(ImVec2 display) {
  return {display.x - kRightColumnWidth, kMenuBarHeight, kRightColumnWidth, panelAreaHeight(display) * 0.55f};
}
inline PanelRect ikTargetsRect(ImVec2 display) {
  const PanelRect pr = propertiesRect(display);
  return {pr.x, pr.y + pr.h, kRightColumnWidth, panelAreaHeight(display) - pr.h};
}
inline PanelRect statusBarRect(ImVec2 display) {
  return {0.0f, display.y - kStatusBarHeight, display.x, kStatusBarHeight};
}
// The 3D view (Blender's view region): the free area between the columns, the menu bar and
// the status bar (and the bottom panels when shown); at least 1 px each way so a tiny
// window still has a camera aspect.
inline PanelRect viewportRect(ImVec2 display, BottomPanels bottom) {
  const float w = display.x - kLeftColumnWidth - kRightColumnWidth,
              h = panelAreaHeight(display) - bottomPanelsHeight(bottom);
  return {kLeftColumnWidth, kMenuBarHeight, w > 1.0f ? w : 1.0f, h > 1.0f ? h : 1.0f};
}
inline PanelRect viewportRect(ImVec2 display, bool withTimeline = false) {
  BottomPanels b;
  b.timeline = withTimeline;
  return viewportRect(display, b);
}
// The timeline (Blender's): a strip just above the status bar, as wide as the 3D view.
inline PanelRect timelineRect(ImVec2 display) {
  const float w = display.x - kLeftColumnWidth - kRightColumnWidth;
  return {kLeftColumnWidth, display.y - kStatusBarHeight - kTimelineHeight, w > 1.0f ? w : 1.0f, kTimelineHeight};
}
// The dope sheet / curve editor: between the 3D view and the timeline, as wide as the view.
inline PanelRect animationEditorRect(ImVec2 display, BottomPanels bottom) {
  const PanelRect v = viewportRect(display, bottom);
  return {v.x, v.y + v.h, v.w, kAnimationEditorHeight};
}

}  // namespace kinema
