// Animation > Clean Up Motion…: the edited clip's foot contacts (listed per foot; Detect, Add
// over a frame range, Delete, the selected one's frames typed), the clean-up settings (foot
// locking, key reduction with a position tolerance in file units and a rotation tolerance
// in degrees), Apply (one undo step), and the last run's before/after figure. The buttons run
// the Animation menu's commands (motion_commands.cpp); the work is motion_cleanup_edit.h's.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "editor/commands/animation_editor_commands.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

constexpr const char* kCleanUpWindow = "Clean Up Motion";
const ImVec4 kBefore(0.80f, 0.45f, 0.30f, 1.0f), kAfter(0.35f, 0.70f, 0.40f, 1.0f);

std::string format(const char* fmt, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, v);
  return buffer;
}

// One row of the figure: a label, the two numbers, and a bar each on a shared scale.
void figureRow(EditorState& state, const char* label, double before, double after, const char* fmt) {
  const double top = std::max({before, after, 1e-30});
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(label);
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(format(fmt, before).c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(format(fmt, after).c_str());
  ImGui::TableNextColumn();
  const float w = ImGui::GetContentRegionAvail().x, h = ImGui::GetTextLineHeight() * 0.42f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p, ImVec2(p.x + std::max(1.0f, static_cast<float>(w * before / top)), p.y + h),
                      ImGui::GetColorU32(kBefore));
  draw->AddRectFilled(ImVec2(p.x, p.y + h + 1), ImVec2(p.x + std::max(1.0f, static_cast<float>(w * after / top)), p.y + 2 * h + 1),
                      ImGui::GetColorU32(kAfter));
  ImGui::Dummy(ImVec2(w, 2 * h + 1));
  recordItem(std::string(kCleanUpWindow) + "/Figure/" + label);
  (void)state;
}

void contactList(CommandContext& ctx, const Clip& clip) {
  EditorState& state = ctx.state;
  for (int foot = 0; foot < 2; ++foot) {
    const Foot ft = static_cast<Foot>(foot);
    const std::vector<ContactInterval>& list = clip.contacts.of(ft);
    ImGui::Text("%s foot: %d contact%s", foot == 0 ? "Left" : "Right", static_cast<int>(list.size()),
                list.size() == 1 ? "" : "s");
    ImGui::Indent();
    const float width = ImGui::GetContentRegionAvail().x;
    float used = 0.0f;
    for (int i = 0; i < static_cast<int>(list.size()); ++i) {
      const std::string text = std::to_string(list[i].first) + "-" + std::to_string(list[i].last);
      const float w = ImGui::CalcTextSize(text.c_str()).x + ImGui::GetStyle().FramePadding.x * 2;
      if (i > 0 && used + w < width) ImGui::SameLine();
      else used = 0.0f;
      used += w + ImGui::GetStyle().ItemSpacing.x;
      ImGui::PushID(foot * 100000 + i);
      const bool selected = state.contactSelection.foot == ft && state.contactSelection.index == i;
      if (ImGui::Selectable(text.c_str(), selected, 0, ImVec2(w - ImGui::GetStyle().FramePadding.x, 0)))
        state.contactSelection = FootContactSelection{ft, i};
      recordItem(std::string(kCleanUpWindow) + "/" + toString(ft) + "/" + std::to_string(i));
      ImGui::PopID();
    }
    ImGui::Unindent();
  }
}

}  // namespace

void drawCleanUpWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.cleanUpWindowOpen) return;
  const PanelRect& v = state.layout.viewport;
  const ImVec2 size(std::min(scaled(state, 430.0f), v.w - scaled(state, 16.0f)),
                    std::min(scaled(state, 560.0f), v.h - scaled(state, 16.0f)));
  ImGui::SetNextWindowPos(ImVec2(v.right() - size.x - scaled(state, 8.0f), v.y + scaled(state, 8.0f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(std::max(size.x, 240.0f), std::max(size.y, 200.0f)), ImGuiCond_Appearing);
  if (!ImGui::Begin(kCleanUpWindow, &state.cleanUpWindowOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow(kCleanUpWindow);
  if (!state.hasMotion()) {
    ImGui::TextWrapped("No clip: import a motion (File > Import Motion onto Character...) or key a pose first.");
    ImGui::End();
    return;
  }
  const Clip& clip = state.doc.scene().clips[state.clip];
  int keys = 0;
  for (const Channel& c : clip.channels) keys += c.keyCount();
  ImGui::Text("Clip '%s': %d channels, %d keys", clip.name.c_str(), static_cast<int>(clip.channels.size()), keys);

  ImGui::Separator();
  ImGui::TextDisabled("Foot contacts");
  contactList(ctx, clip);
  commandButton(ctx, "contacts.detect", kCleanUpWindow, "Detect");
  ImGui::SameLine();
  commandButton(ctx, "contacts.delete", kCleanUpWindow, "Delete selected");
  if (state.contactSelection.valid(clip)) {
    // The selected contact's frames, typed (one undo step on Enter).
    const ContactInterval c = clip.contacts.of(state.contactSelection.foot)[state.contactSelection.index];
    int frames[2] = {c.first, c.last};
    ImGui::SetNextItemWidth(scaled(state, 120.0f));
    if (ImGui::InputInt2("Selected (first, last)", frames, ImGuiInputTextFlags_EnterReturnsTrue))
      reportDopeSheetEdit(state,
                          setFootContactEdit(state.doc, state.clip, state.contactSelection.foot,
                                             state.contactSelection.index, frames[0], frames[1]),
                          "Set the contact's frames");
    recordItem(std::string(kCleanUpWindow) + "/Selected frames");
  }
  int foot = static_cast<int>(state.newContactFoot);
  ImGui::SetNextItemWidth(scaled(state, 70.0f));
  if (ImGui::Combo("##new foot", &foot, "Left\0Right\0")) state.newContactFoot = static_cast<Foot>(foot);
  recordItem(std::string(kCleanUpWindow) + "/New foot");
  ImGui::SameLine();
  int range[2] = {state.newContactFirst, state.newContactLast};
  ImGui::SetNextItemWidth(scaled(state, 110.0f));
  if (ImGui::InputInt2("##new range", range)) {
    state.newContactFirst = std::max(range[0], 0);
    state.newContactLast = std::max(range[1], 0);
  }
  recordItem(std::string(kCleanUpWindow) + "/New range");
  ImGui::SameLine();
  commandButton(ctx, "contacts.add", kCleanUpWindow, "Add");
  ImGui::TextDisabled("On the timeline: drag a bar's end, drag on an empty lane to add.");

  ImGui::Separator();
  ImGui::TextDisabled("Clean up");
  CleanUpOptions& o = state.cleanUp;
  ImGui::Checkbox("Lock feet during contacts", &o.lockFeet);
  recordItem(std::string(kCleanUpWindow) + "/Lock feet");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(scaled(state, 60.0f));
  if (ImGui::InputInt("blend frames", &o.blendFrames, 0)) o.blendFrames = std::clamp(o.blendFrames, 0, 60);
  recordItem(std::string(kCleanUpWindow) + "/Blend frames");
  ImGui::Checkbox("Reduce keys", &o.reduce);
  recordItem(std::string(kCleanUpWindow) + "/Reduce keys");
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  if (ImGui::InputFloat("position tolerance (file units)", &o.positionTolerance, 0.0f, 0.0f, "%.4g"))
    o.positionTolerance = std::max(o.positionTolerance, 1e-6f);
  recordItem(std::string(kCleanUpWindow) + "/Position tolerance");
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  if (ImGui::InputFloat("rotation tolerance (degrees)", &o.rotationDegrees, 0.0f, 0.0f, "%.4g"))
    o.rotationDegrees = std::max(o.rotationDegrees, 1e-4f);
  recordItem(std::string(kCleanUpWindow) + "/Rotation tolerance");
  commandButton(ctx, "anim.apply_clean_up", kCleanUpWindow, "Apply", ImVec2(scaled(state, 120.0f), 0));

  ImGui::Separator();
  ImGui::TextDisabled("Before / after");
  if (!state.lastCleanUp) {
    ImGui::TextDisabled("Apply shows the figures here.");
  } else {
    const CleanUpResult& res = *state.lastCleanUp;
    const MotionCleanupReport& rep = res.report;
    ImGui::Text("Last run on '%s' (%d contact frames)", res.clipName.c_str(), rep.contactFrames);
    if (ImGui::BeginTable("##figure", 4, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerH)) {
      ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 1.6f);
      ImGui::TableSetupColumn("before", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("after", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 1.6f);
      ImGui::TableHeadersRow();
      figureRow(state, "keys", rep.keys.keysBefore, rep.keys.keysAfter, "%.0f");
      figureRow(state, "foot skate", rep.skateBefore, rep.skateAfter, "%.3g");
      ImGui::EndTable();
    }
    ImGui::TextColored(kBefore, "before");
    ImGui::SameLine();
    ImGui::TextColored(kAfter, "after");
    ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("(foot skate: the ankle's mean slide per contact frame, in leg lengths)");
    ImGui::PopStyleColor();
    if (res.options.reduce)
      ImGui::Text("Largest reduction error: %.3g file units, %.3g degrees", rep.keys.maxPositionError,
                  rep.keys.maxAngleError / 0.01745329251994329577);
    else
      ImGui::TextDisabled("Keys not reduced.");
    recordItem(std::string(kCleanUpWindow) + "/Reduction error");
  }
  ImGui::End();
}

}  // namespace kinema
