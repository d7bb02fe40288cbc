// The modal questions and messages of a session: the file dialog, "Discard unsaved
// changes?", "Recover unsaved work?", the error popup and the controls help.
#include <imgui.h>

#include <ctime>

#include "editor/panels/dope_sheet_panel.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/compare_panel.h"

namespace kinema {

namespace {

constexpr ImGuiWindowFlags kModalFlags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings;

void centreNextWindow() {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
}

std::string localTime(double unixSeconds) {
  const std::time_t t = static_cast<std::time_t>(unixSeconds);
  std::tm tm{};
  if (!localtime_r(&t, &tm)) return "an earlier session";
  char text[64];
  std::strftime(text, sizeof(text), "%Y-%m-%d %H:%M:%S", &tm);
  return text;
}

const char* pendingVerb(PendingFileAction action) {
  switch (action) {
    case PendingFileAction::New: return "starting a new document";
    case PendingFileAction::Open:
    case PendingFileAction::OpenPath: return "opening another file";
    case PendingFileAction::Quit: return "quitting";
    case PendingFileAction::None: break;
  }
  return "continuing";
}

void discardModal(EditorState& state) {
  PanelState& p = state.panels;
  if (p.askDiscard) {
    ImGui::OpenPopup("Discard unsaved changes?");
    p.askDiscard = false;
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Discard unsaved changes?", nullptr, kModalFlags)) return;
  ImGui::Text("%s has changes that are not saved.", documentTitle(state).c_str());
  ImGui::Text("Discard them before %s?", pendingVerb(p.pending));
  const bool discard = ImGui::Button("Discard", ImVec2(110, 0));
  recordItem("Discard unsaved changes?/Discard");
  if (discard) {
    ImGui::CloseCurrentPopup();
    runPendingFileAction(state);
  }
  ImGui::SameLine();
  const bool saveFirst = ImGui::Button("Save first", ImVec2(110, 0));
  recordItem("Discard unsaved changes?/Save first");
  if (saveFirst) {
    ImGui::CloseCurrentPopup();
    const bool inPlace = canSaveInPlace(state.doc);
    requestSave(state);
    // Saved in place: go on. Without a .kinema path Save As asks for one first; the action
    // goes on once that save succeeds (and is dropped if the dialog is cancelled).
    if (inPlace) {
      if (!state.doc.dirty()) runPendingFileAction(state);
      else p.pending = PendingFileAction::None;  // the save failed: its error is showing
    } else {
      p.resumeAfterSaveAs = true;
    }
  }
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel", ImVec2(110, 0));
  recordItem("Discard unsaved changes?/Cancel");
  if (cancel || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    ImGui::CloseCurrentPopup();
    p.pending = PendingFileAction::None;
  }
  ImGui::EndPopup();
}

void recoveryModal(EditorState& state) {
  PanelState& p = state.panels;
  if (p.askRecovery && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) {
    ImGui::OpenPopup("Recover unsaved work?");
    p.askRecovery = false;
  }
  if (!p.recovery) return;
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Recover unsaved work?", nullptr, kModalFlags)) return;
  const RecoverableSession& session = *p.recovery;
  ImGui::Text("Recover unsaved work from %s?", localTime(session.time).c_str());
  ImGui::TextDisabled("%s", session.originalPath.empty() ? "(a new document)" : session.originalPath.c_str());
  ImGui::TextDisabled("autosave: %s", session.recoveryPath.c_str());
  ImGui::TextDisabled("Enter recovers, Esc discards");
  if (ImGui::Button("Recover", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) {
    ImGui::CloseCurrentPopup();
    acceptRecovery(state);
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
    declineRecovery(state);
  }
  ImGui::EndPopup();
}

void errorPopup(EditorState& state) {
  PanelState& p = state.panels;
  if (p.errors.empty()) return;
  if (!ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::OpenPopup("Error");
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Error", nullptr, kModalFlags)) return;
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
  ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", p.errors.front().c_str());
  ImGui::PopTextWrapPos();
  if (p.errors.size() > 1) ImGui::TextDisabled("(%d more)", static_cast<int>(p.errors.size() - 1));
  // Keys count from the frame after it appears: the Enter that confirmed a file dialog must
  // not also dismiss the error it caused.
  const bool key = !ImGui::IsWindowAppearing() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                                                   ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false));
  if (ImGui::Button("OK", ImVec2(110, 0)) || key) {
    p.errors.erase(p.errors.begin());
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void helpWindow(EditorState& state) {
  if (!state.panels.showHelp) return;
  centreNextWindow();
  ImGui::Begin("Controls", &state.panels.showHelp, kModalFlags);
  const char* rows[][2] = {
      {"Left click", "select a joint (Shift: add / toggle)"},
      {"Left drag on empty space", "box select"},
      {"Middle drag / Alt+left drag", "orbit"},
      {"Shift+middle drag", "pan"},
      {"Wheel", "zoom"},
      {"R, then X/Y/Z", "rotate the selection (constrained)"},
      {"G", "move the root joint"},
      {"Alt+R", "clear rotation"},
      {"Drag a ring of the gizmo", "rotate about that axis"},
      {"Drag an IK target handle", "move the target, the chain follows"},
      {"Numpad 1 / 3 / 7 (Ctrl: opposite)", "front / right / top view"},
      {"Numpad 5", "perspective / orthographic"},
      {"F / Home", "frame selected / all"},
      {"Ctrl+Z / Ctrl+Shift+Z", "undo / redo"},
      {"Ctrl+C / Ctrl+V / Ctrl+Shift+V", "copy / paste / paste flipped pose"},
      {"Ctrl+N / Ctrl+O / Ctrl+S / Ctrl+Shift+S", "new / open / save / save as"},
      {"Double-click a joint in the outliner", "rename it"},
      {"Shift+F6", "curve editor: click / drag keys and handles, wheel zoom, Home fit"},
      {"Dope sheet (View menu): click / drag keys", "select (Shift: toggle) / move, snapped to frames"},
      {"Dope sheet: drag on empty space, A / Alt+A", "box select, select all / none"},
      {"Dope sheet: G, X, Ctrl+C / Ctrl+V", "move, delete, copy / paste at the current frame"},
      {"Space / Left, Right / Shift+Left, Right", "play, pause / step a frame / jump to start, end"},
      {"Drag in the timeline's ruler", "scrub"},
      {"I / Alt+I", "insert / delete keys of the selected joints at the current frame"},
      {"Timeline: Auto-key", "record every posing edit as keys (same undo step)"},
  };
  if (ImGui::BeginTable("##controls", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& row : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row[1]);
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace

void drawSessionDialogs(EditorState& state) {
  PanelState& p = state.panels;
  std::string chosen;
  if (drawFileDialog(p.fileDialog, p.recent.entries(), chosen)) finishFileDialog(state, chosen);
  if (p.resumeAfterSaveAs && !p.fileDialog.visible) {
    p.resumeAfterSaveAs = false;
    if (!state.doc.dirty()) runPendingFileAction(state);  // saved: New / Open / Quit goes on
    else p.pending = PendingFileAction::None;             // cancelled or failed
  }
  discardModal(state);
  recoveryModal(state);
  errorPopup(state);
  helpWindow(state);
}

void drawEditorPanels(EditorState& state, float fps) {
  tickEditorSession(state, ImGui::GetTime());
  if (state.compare.active) {  // Teach > Compare Solvers covers the side panels and the 3D view
    drawMainMenuBar(state);
    drawComparePanel(state);
    drawStatusBar(state, fps);
    drawSessionDialogs(state);
    return;
  }
  drawMainMenuBar(state);
  drawOutlinerPanel(state);
  drawHistoryPanel(state);
  drawPropertiesPanel(state);
  drawIkTargetsPanel(state);
  drawStatusBar(state, fps);
  drawTimelinePanel(state);
  drawCurveEditorPanel(state);
  drawDopeSheetPanel(state);
  drawAnimationDisplayWindows(state);
  drawSessionDialogs(state);
}

}  // namespace kinema
