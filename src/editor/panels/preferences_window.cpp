// Edit > Preferences (Blender's): the interface (UI scale, theme, the presentation preset,
// 3D line scale), playback's loop switch and what new keys carry. A change is saved to the
// user's preferences file at once (user_preferences.h); the splitters and the window's size
// and place are saved on exit.
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "editor/commands/file_commands.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

// A slider whose value applies when it is let go (a new UI scale re-lays out the window,
// which would move the slider under the mouse). True when `value` changed.
bool sliderAppliedOnRelease(const char* label, const std::string& name, float* value, float lo, float hi,
                            const char* format, float width) {
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const ImGuiID held = ImGui::GetID((std::string(label) + "##held").c_str());
  float shown = storage->GetFloat(held, *value);
  ImGui::SetNextItemWidth(width);
  ImGui::SliderFloat(label, &shown, lo, hi, format, ImGuiSliderFlags_AlwaysClamp);
  recordFrame(name, width);
  const bool done = ImGui::IsItemDeactivatedAfterEdit();
  if (ImGui::IsItemActive()) {
    storage->SetFloat(held, shown);
    return false;
  }
  storage->SetFloat(held, done ? shown : *value);
  if (!done) return false;
  const float rounded = std::round(shown * 20.0f) / 20.0f;  // steps of 0.05
  if (rounded == *value) return false;
  *value = rounded;
  return true;
}

void heading(const char* text) {
  ImGui::Spacing();
  ImGui::TextUnformatted(text);
  ImGui::Separator();
}

}  // namespace

void drawPreferencesWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.preferencesWindowOpen) return;
  const PanelRect& v = state.layout.viewport;
  ImGui::SetNextWindowPos(ImVec2(v.x + scaled(state, 24.0f), v.y + scaled(state, 24.0f)), ImGuiCond_Appearing);
  if (!ImGui::Begin("Preferences", &state.preferencesWindowOpen,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow("Preferences");
  UserPreferences& p = state.preferences;
  bool changed = false;
  const float sliderWidth = scaled(state, 180.0f);

  heading("Interface");
  changed |= sliderAppliedOnRelease("UI scale", "Preferences/UI scale", &p.uiScale, kMinUiScale, kMaxUiScale, "%.2fx",
                                    sliderWidth);
  for (float s : {1.0f, 1.5f, 2.0f}) {
    ImGui::SameLine();
    char label[16];
    std::snprintf(label, sizeof label, "%gx", s);
    if (ImGui::SmallButton(label) && p.uiScale != s) {
      p.uiScale = s;
      changed = true;
    }
    recordItem(std::string("Preferences/UI scale/") + label);
  }
  std::error_code ec;
  if (std::filesystem::is_regular_file(kUiFontPath, ec))
    ImGui::TextDisabled("Font: DejaVu Sans, %.0f px", state.layout.metrics.fontSize);
  else
    ImGui::TextDisabled("Font: built-in (install fonts-dejavu-core for DejaVu Sans)");
  ImGui::TextUnformatted("Theme");
  for (UiTheme t : {UiTheme::Dark, UiTheme::Light, UiTheme::Classic}) {
    ImGui::SameLine();
    const std::string label = t == UiTheme::Dark ? "Dark" : t == UiTheme::Light ? "Light" : "Classic";
    if (ImGui::RadioButton(label.c_str(), p.theme == t) && p.theme != t) {
      p.theme = t;
      changed = true;
    }
    recordItem("Preferences/Theme/" + label);
  }
  changed |= sliderAppliedOnRelease("3D line scale", "Preferences/3D line scale", &p.lineScale, kMinLineScale,
                                    kMaxLineScale, "%.2fx", sliderWidth);
  // The preset for teaching on a projector (View > Presentation Mode): saves on its own.
  commandSelectable(ctx, "view.presentation", "Preferences", "Presentation preset (2x text, thicker 3D lines)");
  if (ImGui::Button("Reset panel sizes")) {
    p.panels = PanelSizes{};
    changed = true;
  }
  recordItem("Preferences/Reset panel sizes");

  heading("Playback");
  if (ImGui::Checkbox("Loop playback", &state.loop)) changed = true;  // the timeline's Loop switch
  recordItem("Preferences/Loop playback");

  heading("Animation");
  drawKeyPreferenceChoices(state, "Preferences/Keys/");  // saves its own changes

  ImGui::Spacing();
  ImGui::TextDisabled("Saved in %s", userPreferencesPath().c_str());
  if (changed) saveEditorPreferences(state);
  ImGui::End();
}

}  // namespace kinema
