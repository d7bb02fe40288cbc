// The dope sheet (Blender's): the edited clip's keys as diamonds, one row per keyed joint
// under a summary row, frames across. Drawn in the animation editor area under the 3D view
// (EditorState::layout.animationEditor, model/editor_layout.h); the model and the edits are in dope_sheet.h.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include "editor/model/key_codes.h"

#include "editor/commands/animation_editor_commands.h"
#include "editor/panels/dope_sheet_panel.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

constexpr float kDopeSheetDiamondRadius = 5.0f;   // half the diagonal, pixels
constexpr float kHitRadius = 7.0f;       // a click this near a diamond takes it
constexpr float kDragThreshold = 3.0f;   // pixels before a press becomes a drag

ImU32 rgba(int r, int g, int b, int a = 255) { return IM_COL32(r, g, b, a); }

// Ruler spacing: the smallest of 1, 2, 5, 10, 20, 50, ... frames that leaves `minPixels` between labels.
long long tickStep(double pixelsPerFrame, double minPixels) {
  for (long long base = 1;; base *= 10)
    for (long long m : {1, 2, 5})
      if (base * m * pixelsPerFrame >= minPixels || base > 1000000) return base * m;
}

void drawDiamond(ImDrawList* dl, ImVec2 c, float r, ImU32 fill, ImU32 outline) {
  const ImVec2 p[4] = {{c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}};
  dl->AddConvexPolyFilled(p, 4, fill);
  dl->AddPolyline(p, 4, outline, ImDrawFlags_Closed, 1.0f);
}

// The keys of a running gesture (G's move: Enter drops, Esc cancels; Esc ends a mouse drag
// of keys). Every other key over the dope sheet is a command (animation_editor_commands.cpp).
void handleModalKeys(EditorState& state, DopeSheetState& ds) {
  const ImGuiIO& io = ImGui::GetIO();
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
  if (ds.gesture == DopeSheetState::Gesture::GrabKeys) {
    if (pressed(keys::ESCAPE)) {
      ds.move.cancel(state.doc, ds.selection);
      ds.gesture = DopeSheetState::Gesture::None;
      showDopeSheetFrame(state);
    } else if (pressed(keys::ENTER) || pressed(keys::KP_ENTER)) {
      ds.move.commit(state.doc);
      ds.gesture = DopeSheetState::Gesture::None;
      reportDopeSheetEdit(state, "", "Moved keys");
    }
    return;
  }
  if (ds.gesture != DopeSheetState::Gesture::None && pressed(keys::ESCAPE) && ds.move.active()) {
    ds.move.cancel(state.doc, ds.selection);
    ds.gesture = DopeSheetState::Gesture::None;
    showDopeSheetFrame(state);
  }
}

// Mouse gestures: click / Shift-click select, drags move keys or draw a box, the wheel
// zooms about the mouse (Shift+wheel scrolls rows), middle drag pans, the ruler scrubs.
void handleMouse(EditorState& state, const std::vector<DopeSheetRow>& rows, DopeSheetState& ds,
                 bool hovered, const PanelRect& rulerRect) {
  const ImGuiIO& io = ImGui::GetIO();
  const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
  DopeSheetView& view = ds.view;
  using G = DopeSheetState::Gesture;
  const double framesMoved = (mouse.x - ds.pressMouse.x) / view.pixelsPerFrame;

  if (ds.gesture == G::GrabKeys) {
    ds.move.update(state.doc, ds.selection, framesMoved);
    if (ImGui::IsMouseClicked(0)) {
      ds.move.commit(state.doc);
      ds.gesture = G::None;
      reportDopeSheetEdit(state, "", "Moved keys");
    } else if (ImGui::IsMouseClicked(1)) {
      ds.move.cancel(state.doc, ds.selection);
      ds.gesture = G::None;
      showDopeSheetFrame(state);
    }
    return;
  }
  if (ds.gesture == G::Pan) {
    if (!ImGui::IsMouseDown(2)) ds.gesture = G::None;
    view.firstFrame -= io.MouseDelta.x / view.pixelsPerFrame;
    return;
  }
  if (ds.gesture == G::Press || ds.gesture == G::Box || ds.gesture == G::DragKeys) {
    if (ds.gesture == G::DragKeys && ImGui::IsMouseClicked(1)) {
      ds.move.cancel(state.doc, ds.selection);
      ds.gesture = G::None;
      showDopeSheetFrame(state);
      return;
    }
    const bool moved = glm::length(mouse - ds.pressMouse) > kDragThreshold;
    if (ds.gesture == G::Press && moved) {
      int row = -1;
      float time = 0.0f;
      if (hitKeyColumn(rows, view, timelineGrid(state), ds.pressMouse, kHitRadius, row, time)) {
        const std::string error = ds.move.begin(state.doc, state.clip, ds.selection);
        if (!error.empty()) {
          showEditorError(state, error);
          ds.gesture = G::None;
          return;
        }
        ds.gesture = G::DragKeys;
      } else {
        ds.gesture = G::Box;
      }
    }
    if (ds.gesture == G::DragKeys) ds.move.update(state.doc, ds.selection, framesMoved);
    if (ImGui::IsMouseReleased(0)) {
      if (ds.gesture == G::DragKeys) {
        ds.move.commit(state.doc);
        reportDopeSheetEdit(state, "", "Moved keys");
      } else if (ds.gesture == G::Box) {
        const std::vector<KeyColumn> inside =
            columnsInBox(timelineGrid(state), rows, view.xToFrame(ds.pressMouse.x), view.xToFrame(mouse.x), view.rowAt(ds.pressMouse.y),
                         view.rowAt(mouse.y));
        ds.selection.box(inside, io.KeyShift || ds.pressExtend ? BoxSelectMode::Extend
                                 : io.KeyCtrl                 ? BoxSelectMode::Subtract
                                                              : BoxSelectMode::Replace);
      } else {
        // A click: on a diamond select it (Shift: toggle), on nothing deselect all.
        int row = -1;
        float time = 0.0f;
        if (hitKeyColumn(rows, view, timelineGrid(state), ds.pressMouse, kHitRadius, row, time)) {
          if (!ds.pressExtend) ds.selection.set(columnsOfCell(rows, row, time));
        } else if (!ds.pressExtend) {
          ds.selection.clear();
        }
      }
      ds.gesture = G::None;
    }
    return;
  }
  if (!hovered) return;
  // Scrubbing: a press or drag in the ruler sets the current frame.
  const bool inRuler = mouse.y >= rulerRect.y && mouse.y < rulerRect.y + rulerRect.h && mouse.x >= view.x;
  if (inRuler && ImGui::IsMouseDown(0)) {
    const long long frame = std::max(0LL, std::llround(view.xToFrame(mouse.x)));
    if (frame != currentFrame(state) || state.playing) {
      state.playing = false;
      goToFrame(state, frame);  // the timeline's frame -> time, so both show the same frame
    }
    return;
  }
  if (io.MouseWheel != 0.0f) {
    if (io.KeyShift) {
      view.firstRow = std::clamp(view.firstRow - static_cast<int>(io.MouseWheel), 0,
                                 std::max(0, static_cast<int>(rows.size()) - 1));
    } else {
      view.zoomAt(mouse.x, std::pow(1.15, io.MouseWheel));
    }
  }
  if (ImGui::IsMouseClicked(2)) {
    ds.gesture = G::Pan;
    return;
  }
  // A click on a joint's name selects the joint (Shift: toggles), as the outliner does.
  if (ImGui::IsMouseClicked(0) && mouse.x < view.x && mouse.y >= view.y) {
    const int row = view.rowAt(mouse.y);
    if (row >= 1 && row < static_cast<int>(rows.size())) {
      if (io.KeyShift) state.doc.selection.shiftClick(rows[row].joint);
      else state.doc.selection.click(rows[row].joint);
    }
    return;
  }
  if (ImGui::IsMouseClicked(0) && mouse.x >= view.x && mouse.y >= view.y) {
    ds.gesture = G::Press;
    ds.pressMouse = mouse;
    ds.pressExtend = io.KeyShift;
    int row = -1;
    float time = 0.0f;
    if (hitKeyColumn(rows, view, timelineGrid(state), mouse, kHitRadius, row, time)) {
      const std::vector<KeyColumn> cell = columnsOfCell(rows, row, time);
      // Pressing an unselected diamond selects it (Shift: adds it); pressing a selected
      // one keeps the selection, so that a drag moves all of it.
      if (ds.pressExtend) ds.selection.click(cell, true);
      else if (!ds.selection.containsAll(cell)) ds.selection.set(cell);
    }
  }
}

}  // namespace

void drawDopeSheetPanel(EditorState& state) {
  if (state.animationEditor != AnimationEditorKind::DopeSheet) return;
  const PanelRect r = state.layout.animationEditor;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("Dope Sheet", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                                          ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar();
  recordWindow("Dope Sheet");  // names left of dope_sheet.view's x, the ruler above its y
  DopeSheetState& ds = state.dopeSheet;
  DopeSheetView& view = ds.view;
  view.x = r.x + kDopeSheetNameWidth;
  view.y = r.y + kDopeSheetRulerHeight;
  view.width = std::max(r.w - kDopeSheetNameWidth, 1.0f);
  view.height = std::max(r.h - kDopeSheetRulerHeight, 1.0f);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  if (!state.hasMotion()) {
    ImGui::SetCursorPos(ImVec2(12, 10));
    ImGui::TextDisabled("Dope Sheet: no animation. Open a file with motion or key a pose.");
    ImGui::End();
    return;
  }
  const Clip& clip = state.doc.scene().clips[state.clip];
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  // Undo, redo, other edits or another file may have taken selected keys away.
  if (!ds.move.active()) ds.selection.prune(rows);
  const long long changeBefore = state.doc.changeCount();
  const bool hovered = ImGui::IsWindowHovered();
  const PanelRect ruler{view.x, r.y, view.width, kDopeSheetRulerHeight};
  if (hovered || ds.gesture != DopeSheetState::Gesture::None) {
    handleModalKeys(state, ds);
    handleMouse(state, rows, ds, hovered, ruler);
  }
  // After this frame's edits (the rows again only when there were some).
  if (!state.hasMotion()) {
    ImGui::End();
    return;
  }
  const Clip& shown = state.doc.scene().clips[state.clip];
  const FrameGrid grid = timelineGrid(state);
  std::vector<DopeSheetRow> edited;
  if (state.doc.changeCount() != changeBefore) edited = dopeSheetRows(shown);
  const std::vector<DopeSheetRow>& shownRows = state.doc.changeCount() != changeBefore ? edited : rows;

  // Background: the key area, alternating rows, the names column, the ruler.
  const float right = r.x + r.w, bottom = r.y + r.h;
  dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(right, bottom), true);
  dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(right, bottom), rgba(42, 42, 42));
  // The clip's playback range, lighter (Blender darkens outside the scene's range).
  const double x0 = view.frameToX(grid.timeToFrame(shown.playStart())), x1 = view.frameToX(grid.timeToFrame(shown.playEnd()));
  dl->AddRectFilled(ImVec2(std::max(float(x0), view.x), view.y), ImVec2(std::min(float(x1), right), bottom), rgba(52, 52, 52));
  for (int i = 0; i < static_cast<int>(shownRows.size()); ++i) {
    const float cy = view.rowCenterY(i), top = cy - view.rowHeight * 0.5f;
    if (top + view.rowHeight < view.y || top > bottom) continue;
    if (i % 2 == 1) dl->AddRectFilled(ImVec2(r.x, top), ImVec2(right, top + view.rowHeight), rgba(255, 255, 255, 10));
    if (i == 0) dl->AddRectFilled(ImVec2(r.x, top), ImVec2(right, top + view.rowHeight), rgba(70, 80, 100, 120));
  }
  // Frame grid and ruler labels.
  const long long step = tickStep(view.pixelsPerFrame, 40.0);
  const long long firstTick = static_cast<long long>(std::floor(view.firstFrame / step)) * step;
  dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(right, view.y), rgba(30, 30, 30));
  for (long long f = firstTick; view.frameToX(double(f)) < right; f += step) {
    const float x = static_cast<float>(view.frameToX(double(f)));
    if (x < view.x) continue;
    dl->AddLine(ImVec2(x, view.y), ImVec2(x, bottom), rgba(255, 255, 255, 18));
    dl->AddLine(ImVec2(x, view.y - 5), ImVec2(x, view.y), rgba(160, 160, 160));
    char label[24];
    std::snprintf(label, sizeof label, "%lld", f);
    dl->AddText(ImVec2(x + 2, r.y + 2), rgba(170, 170, 170), label);
  }
  // Diamonds: selected orange, others light grey; the summary's a little larger.
  dl->PushClipRect(ImVec2(view.x, view.y), ImVec2(right, bottom), true);
  const double firstVisible = view.xToFrame(view.x - 10), lastVisible = view.xToFrame(right + 10);
  for (int i = 0; i < static_cast<int>(shownRows.size()); ++i) {
    const float cy = view.rowCenterY(i);
    if (cy < view.y || cy > bottom + view.rowHeight) continue;
    const std::vector<float>& times = shownRows[i].times;
    auto it = std::lower_bound(times.begin(), times.end(), grid.frameToTime(static_cast<long long>(std::floor(firstVisible))));
    for (; it != times.end() && grid.timeToFrame(*it) <= lastVisible; ++it) {
      const bool selected = ds.selection.containsAll(columnsOfCell(shownRows, i, *it));
      const float x = static_cast<float>(view.frameToX(grid.timeToFrame(*it)));
      drawDiamond(dl, ImVec2(x, cy), i == 0 ? kDopeSheetDiamondRadius + 1 : kDopeSheetDiamondRadius,
                  selected ? rgba(255, 160, 40) : rgba(205, 205, 205), rgba(0, 0, 0, 200));
    }
  }
  // The box being drawn.
  if (ds.gesture == DopeSheetState::Gesture::Box) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const ImVec2 lo(std::min(ds.pressMouse.x, m.x), std::min(ds.pressMouse.y, m.y)),
        hi(std::max(ds.pressMouse.x, m.x), std::max(ds.pressMouse.y, m.y));
    dl->AddRectFilled(lo, hi, rgba(255, 255, 255, 25));
    dl->AddRect(lo, hi, rgba(255, 255, 255, 160));
  }
  dl->PopClipRect();
  // The current frame: a blue line with its number in the ruler.
  const double frameNow = grid.timeToFrame(state.time);
  const float xNow = static_cast<float>(view.frameToX(frameNow));
  if (xNow >= view.x && xNow <= right) {
    dl->AddLine(ImVec2(xNow, view.y), ImVec2(xNow, bottom), rgba(70, 140, 255), 2.0f);
    char label[24];
    std::snprintf(label, sizeof label, "%lld", currentFrame(state));  // the timeline's number
    const ImVec2 size = ImGui::CalcTextSize(label);
    dl->AddRectFilled(ImVec2(xNow - size.x / 2 - 4, r.y + 1), ImVec2(xNow + size.x / 2 + 4, view.y - 1),
                      rgba(70, 140, 255), 3.0f);
    dl->AddText(ImVec2(xNow - size.x / 2, r.y + 3), rgba(255, 255, 255), label);
  }
  // Joint names over the left column.
  dl->AddRectFilled(ImVec2(r.x, view.y), ImVec2(view.x, bottom), rgba(36, 36, 36));
  dl->AddText(ImVec2(r.x + 8, r.y + 3), rgba(150, 150, 150), shown.name.empty() ? "Dope Sheet" : shown.name.c_str());
  for (int i = 0; i < static_cast<int>(shownRows.size()); ++i) {
    const float cy = view.rowCenterY(i);
    if (cy < view.y || cy > bottom) continue;
    const int joint = shownRows[i].joint;
    const bool jointSelected = joint >= 0 && state.doc.selection.isSelected(joint);
    const char* name = joint < 0 ? "Summary" : state.doc.skeleton().names[joint].c_str();
    dl->AddText(ImVec2(r.x + (joint < 0 ? 8 : 18), cy - 7),
                jointSelected ? rgba(255, 200, 120) : joint < 0 ? rgba(220, 220, 220) : rgba(190, 190, 190), name);
  }
  dl->AddLine(ImVec2(view.x, r.y), ImVec2(view.x, bottom), rgba(20, 20, 20));
  dl->PopClipRect();
  ImGui::End();
}

}  // namespace kinema
