// The timeline (Blender's): transport buttons, frame range and rate, loop, auto-key and key
// preferences on one row; below them the frame ruler with the keyframe diamonds of the
// selected joints and the current frame line. Dragging in the ruler scrubs. The logic is
// in timeline.h (window-free); this file only draws and forwards clicks.
#include <imgui.h>

#include <cmath>
#include <string>

#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/model/keying.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

const ImU32 kRulerBackground = IM_COL32(40, 40, 40, 255);
const ImU32 kRulerRange = IM_COL32(58, 58, 58, 255);
const ImU32 kTickColor = IM_COL32(95, 95, 95, 255);
const ImU32 kDiamondFill = IM_COL32(240, 180, 50, 255);    // keys of the selected joints
const ImU32 kDiamondOutline = IM_COL32(0, 0, 0, 255);
constexpr float kTimelineDiamondRadius = 4.5f;

void keyPreferencesPopup(EditorState& state) {
  if (!ImGui::BeginPopup("Key preferences")) return;
  drawKeyPreferenceChoices(state, "Timeline/Keys/");  // also in Edit > Preferences
  ImGui::EndPopup();
}

void drawRuler(EditorState& state, const TimelineRuler& r) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
  ImGui::InvisibleButton("##ruler", ImVec2(r.w, r.h));
  recordItem("Timeline/Ruler");
  if (ImGui::IsItemActive()) {
    const long long f = r.frameAtX(ImGui::GetIO().MousePos.x);
    if (f != currentFrame(state)) {
      state.playing = false;
      goToFrame(state, f);
    }
  }
  draw->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), kRulerBackground);
  draw->AddRectFilled(ImVec2(r.xOfFrame(r.first), r.y), ImVec2(r.xOfFrame(r.last), r.y + r.h), kRulerRange);
  // Ticks every 1, 2, 5, 10, 20, 50... frames, at least 40 px apart.
  const double pxPerFrame = (r.w - 2 * kTimelineRulerMargin) / double(std::max(r.last - r.first, 1LL));
  long long step = 1;
  for (int i = 0; step * pxPerFrame < scaled(state, 40.0f) && i < 30; ++i) step = (i % 3 == 1) ? step / 2 * 5 : step * 2;
  for (long long f = (r.first / step) * step; f <= r.last; f += step) {
    if (f <= r.first) f = r.first;  // the first frame is always labelled
    const float x = r.xOfFrame(f);
    draw->AddLine(ImVec2(x, r.y), ImVec2(x, r.y + 5), kTickColor);
    draw->AddText(ImVec2(x + 2, r.y), kTickColor, std::to_string(f).c_str());
    if (f == r.first && f % step != 0) f = (f / step) * step;  // back on the tick grid
  }
  const long long frame = currentFrame(state);
  if (frame >= r.first && frame <= r.last) {
    const float x = r.xOfFrame(frame);
    draw->AddLine(ImVec2(x, r.y), ImVec2(x, r.y + r.h), kPlayheadColor, 2.0f);
  }
  const float cy = r.y + r.h * 0.5f + 2.0f;  // below the tick labels' middle
  for (long long f : selectedKeyFrames(state)) {
    if (f < r.first || f > r.last) continue;
    const float x = r.xOfFrame(f), d = scaled(state, kTimelineDiamondRadius);
    draw->AddQuadFilled(ImVec2(x, cy - d - 1), ImVec2(x + d + 1, cy), ImVec2(x, cy + d + 1), ImVec2(x - d - 1, cy),
                        kDiamondOutline);
    draw->AddQuadFilled(ImVec2(x, cy - d), ImVec2(x + d, cy), ImVec2(x, cy + d), ImVec2(x - d, cy), kDiamondFill);
  }
}

}  // namespace

void drawTimelinePanel(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.timelineShown()) return;
  const PanelRect r = state.layout.timeline;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, scaled(state, ImVec2(4, 2)));
  ImGui::Begin("Timeline", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  recordWindow("Timeline");
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, scaled(state, ImVec2(4, 1)));
  auto status = [&](const std::string& message) {
    if (!message.empty()) state.statusMessage = message;
  };
  // The transport buttons run the timeline's commands (Space, Left, Right, Shift+Left/Right).
  commandButton(ctx, "timeline.jump_start", "Timeline", "|<");
  ImGui::SameLine(0, 2);
  commandButton(ctx, "timeline.step_back", "Timeline", "<");
  ImGui::SameLine(0, 2);
  commandButton(ctx, "timeline.play", "Timeline", state.playing ? "Pause" : "Play ");
  ImGui::SameLine(0, 2);
  commandButton(ctx, "timeline.step_forward", "Timeline", ">");
  ImGui::SameLine(0, 2);
  commandButton(ctx, "timeline.jump_end", "Timeline", ">|");
  ImGui::SameLine();
  ImGui::Text("%5lld", currentFrame(state));
  ImGui::SameLine();
  const ImGuiInputTextFlags enter = ImGuiInputTextFlags_EnterReturnsTrue;
  int start = static_cast<int>(rangeStartFrame(state)), end = static_cast<int>(rangeEndFrame(state));
  ImGui::TextUnformatted("Start");
  ImGui::SameLine(0, 3);
  ImGui::SetNextItemWidth(scaled(state, 40));
  if (ImGui::InputInt("##start", &start, 0, 0, enter)) status(setFrameRange(state, start, end));
  recordItem("Timeline/Start frame");
  ImGui::SameLine();
  ImGui::TextUnformatted("End");
  ImGui::SameLine(0, 3);
  ImGui::SetNextItemWidth(scaled(state, 40));
  if (ImGui::InputInt("##end", &end, 0, 0, enter)) status(setFrameRange(state, start, end));
  recordItem("Timeline/End frame");
  ImGui::SameLine();
  ImGui::TextUnformatted("fps");
  ImGui::SameLine(0, 3);
  int fps = static_cast<int>(std::lround(timelineFps(state)));
  ImGui::SetNextItemWidth(scaled(state, 28));
  if (ImGui::InputInt("##fps", &fps, 0, 0, enter)) status(setFrameRate(state, fps));
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(timelineRateIsTheDocuments(state)
                          ? "The document's frame rate: every clip without a rate of its own counts at it"
                          : "This clip's own frame rate (from its file, or set here)");
  recordItem("Timeline/Fps");
  ImGui::SameLine();
  if (ImGui::Checkbox("Loop", &state.loop)) saveEditorPreferences(state);  // also in Edit > Preferences
  recordItem("Timeline/Loop");
  ImGui::SameLine();
  // Auto-key: Blender's record button, red while on.
  const bool recording = state.doc.autoKey.enabled;
  if (recording) ImGui::PushStyleColor(ImGuiCol_Button, IM_COL32(190, 40, 40, 255));
  commandButton(ctx, "anim.auto_key", "Timeline", recording ? "(*) Auto-key" : "( ) Auto-key");
  if (recording) ImGui::PopStyleColor();
  ImGui::SameLine(0, 2);
  if (ImGui::Button("Keys")) ImGui::OpenPopup("Key preferences");
  recordItem("Timeline/Keys");
  keyPreferencesPopup(state);
  ImGui::SameLine();
  commandSelectable(ctx, "view.dope_sheet", "Timeline", "Dope", scaled(state, ImVec2(34, 0)));
  ImGui::SameLine();
  commandSelectable(ctx, "view.curve_editor", "Timeline", "Curves", scaled(state, ImVec2(44, 0)));
  ImGui::PopStyleVar();
  drawRuler(state, timelineRuler(state, r.x, r.y, r.w, r.h));
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace kinema
