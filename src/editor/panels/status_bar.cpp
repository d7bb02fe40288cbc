// The status bar: the active joint and selection, what the current tool does, how each IK
// target's last solve went, the last message, and the frame rate. What does not fit is
// elided with "…" (the full text in a tooltip, and every message in View > Log), so nothing
// runs into the frame rate at the right end.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "editor/commands/controls_help.h"
#include "editor/model/text_elision.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

float textWidth(const std::string& s) { return ImGui::CalcTextSize(s.c_str()).x; }

// "…" when the font has it (DejaVu), else "..." (ImGui's built-in font).
const char* ellipsis() { return ImGui::GetFont()->FindGlyphNoFallback(0x2026) ? "\xE2\x80\xA6" : "..."; }

// `text` elided to `width`, with the whole text in a tooltip while hovered when it was cut.
void elidedText(const std::string& text, float width, bool disabled) {
  const std::string shown = elideText(text, width, textWidth, ellipsis());
  if (disabled) ImGui::TextDisabled("%s", shown.c_str());
  else ImGui::TextUnformatted(shown.c_str());
  if (shown != text && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

}  // namespace

void drawStatusBar(CommandContext& ctx, float fps) {
  EditorState& state = ctx.state;
  const Document& doc = state.doc;
  state.log.observeStatus(state.statusMessage);  // View > Log keeps every message in full
  const PanelRect r = state.layout.statusBar;
  placeNextWindow(r);
  const float pad = scaled(state, 8.0f), gap = scaled(state, 24.0f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(pad, std::max((r.h - ImGui::GetFontSize()) * 0.5f, 0.0f)));
  ImGui::Begin("##status", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const int active = doc.selection.active();
  if (active >= 0 && active < doc.skeleton().size())
    ImGui::Text("%s (%d selected)", doc.skeleton().names[active].c_str(), static_cast<int>(doc.selection.joints().size()));
  else
    ImGui::TextDisabled("nothing selected");
  // The frame rate keeps the right end; the rest shares what is left: the IK reports and the
  // message first, the tool hint with the remainder.
  const std::string rate = std::to_string(static_cast<int>(fps + 0.5f)) + " fps";
  const float rateX = r.w - textWidth(rate) - pad;
  std::string reports;
  for (const IkTargetReport& report : doc.lastIkReports()) {
    const std::string name = report.target < 0 ? "auto-IK" : "IK " + std::to_string(report.target);
    char line[160];
    std::snprintf(line, sizeof line, "%s: %d it, err %.1e, %.2f ms", name.c_str(), report.iterations, report.error,
                  report.milliseconds);
    reports += (reports.empty() ? "" : "   ") + std::string(line);
  }
  const std::string hint = ctx.keymap ? statusHint(state, *ctx.keymap) : std::string();
  const std::string& message = state.statusMessage;
  ImGui::SameLine(0, gap);
  float room = rateX - gap - ImGui::GetCursorPosX();
  const float messageWidth = message.empty() ? 0.0f : std::min(textWidth(message), room);
  room -= messageWidth + (message.empty() ? 0.0f : gap);
  const float reportsWidth = reports.empty() ? 0.0f : std::min(textWidth(reports), std::max(room, 0.0f));
  room -= reportsWidth + (reports.empty() ? 0.0f : gap);
  if (!hint.empty() && room > scaled(state, 40.0f)) {
    elidedText(hint, room, true);
    ImGui::SameLine(0, gap);
  }
  if (!reports.empty() && reportsWidth > scaled(state, 40.0f)) {
    elidedText(reports, reportsWidth, false);
    ImGui::SameLine(0, gap);
  }
  if (!message.empty()) elidedText(message, std::max(rateX - gap - ImGui::GetCursorPosX(), 0.0f), false);
  ImGui::SameLine(rateX);
  ImGui::TextDisabled("%s", rate.c_str());
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace kinema
