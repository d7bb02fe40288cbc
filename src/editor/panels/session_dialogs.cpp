// The modal questions and messages of a session: the file dialog, "Discard unsaved
// changes?", "Recover unsaved work?", the error popup and Help > Controls.
#include <imgui.h>

#include <algorithm>
#include <ctime>

#include "editor/commands/controls_help.h"
#include "editor/panels/dope_sheet_panel.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/compare_panel.h"
#include "editor/panels/panel_layout.h"

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
  const bool discard = ImGui::Button("Discard", ImVec2(ImGui::GetFontSize() * 8.0f, 0));
  recordItem("Discard unsaved changes?/Discard");
  if (discard) {
    ImGui::CloseCurrentPopup();
    runPendingFileAction(state);
  }
  ImGui::SameLine();
  const bool saveFirst = ImGui::Button("Save first", ImVec2(ImGui::GetFontSize() * 8.0f, 0));
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
  const bool cancel = ImGui::Button("Cancel", ImVec2(ImGui::GetFontSize() * 8.0f, 0));
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
  if (ImGui::Button("Recover", ImVec2(ImGui::GetFontSize() * 8.0f, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) {
    ImGui::CloseCurrentPopup();
    acceptRecovery(state);
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard", ImVec2(ImGui::GetFontSize() * 8.0f, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
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
  // Wrapped within the window, however large the text (the UI scale) and small the window.
  ImGui::PushTextWrapPos(std::min(ImGui::GetFontSize() * 40.0f, ImGui::GetIO().DisplaySize.x * 0.8f));
  ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", p.errors.front().c_str());
  ImGui::PopTextWrapPos();
  if (p.errors.size() > 1) ImGui::TextDisabled("(%d more)", static_cast<int>(p.errors.size() - 1));
  // Keys count from the frame after it appears: the Enter that confirmed a file dialog must
  // not also dismiss the error it caused.
  const bool key = !ImGui::IsWindowAppearing() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                                                   ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false));
  if (ImGui::Button("OK", ImVec2(ImGui::GetFontSize() * 8.0f, 0)) || key) {
    p.errors.erase(p.errors.begin());
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Help > Controls: every command with its keys in the active keymap, by where the keys
// apply, and the mouse gestures (controls_help.h) — generated, never a list of its own.
void helpWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.panels.showHelp || !ctx.keymap) return;
  centreNextWindow();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(display.x * 0.9f, display.y * 0.85f));
  ImGui::Begin("Controls", &state.panels.showHelp, kModalFlags);
  if (const std::string keymap = userKeymapPath(); !keymap.empty())
    ImGui::TextDisabled("Keys can be rebound in %s (docs/editor-panels.md)", keymap.c_str());
  for (const ControlGroup& group : controlsTable(*ctx.keymap)) {
    if (!ImGui::CollapsingHeader(group.title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
    if (!ImGui::BeginTable(group.title.c_str(), 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) continue;
    for (const ControlRow& row : group.rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.keys.empty() ? "-" : row.keys.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.action.c_str());
      if (!row.hint.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", row.hint.c_str());
      }
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", row.id.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace

void drawSessionDialogs(CommandContext& ctx) {
  EditorState& state = ctx.state;
  PanelState& p = state.panels;
  std::string chosen;
  if (drawFileDialog(p.fileDialog, p.recent.entries(), chosen)) finishFileDialog(state, chosen);
  if (p.resumeAfterSaveAs && !p.fileDialog.visible) {
    p.resumeAfterSaveAs = false;
    if (!state.doc.dirty()) runPendingFileAction(state);  // saved: New / Open / Quit goes on
    else p.pending = PendingFileAction::None;             // cancelled or failed
  }
  drawMotionImportDialog(ctx);
  discardModal(state);
  recoveryModal(state);
  errorPopup(state);
  helpWindow(ctx);
}

void drawEditorPanels(CommandContext& ctx, float fps) {
  EditorState& state = ctx.state;
  tickEditorSession(state, ImGui::GetTime());
  if (state.compare.active) state.hoveredProperty = HoveredProperty{};
  if (state.compare.active) {  // Teach > Compare Solvers covers the side panels and the 3D view
    drawMainMenuBar(ctx);
    drawComparePanel(ctx);
    drawStatusBar(ctx, fps);
    drawPreferencesWindow(ctx);
    drawLogWindow(state);
    drawSessionDialogs(ctx);
    closePopupsOnEscape(state);
    return;
  }
  drawMainMenuBar(ctx);
  relayoutPanels(state);
  state.hoveredProperty = HoveredProperty{};  // the Properties panel sets it again while a field is hovered
  drawOutlinerPanel(ctx);
  drawHistoryPanel(state);
  drawPropertiesPanel(ctx);
  drawIkTargetsPanel(ctx);
  drawStatusBar(ctx, fps);
  drawTimelinePanel(ctx);
  drawContactLanesPanel(ctx);
  drawCurveEditorPanel(ctx);
  drawDopeSheetPanel(state);
  drawPanelSplitters(state);
  drawAnimationDisplayWindows(state);
  drawPreferencesWindow(ctx);
  drawLogWindow(state);
  drawCleanUpWindow(ctx);
  drawSimulationWindow(ctx);
  drawCrowdWindow(ctx);
  drawParticlesWindow(ctx);
  drawStiffSpringsWindow(ctx);
  drawSessionDialogs(ctx);
  closePopupsOnEscape(state);
}

}  // namespace kinema
