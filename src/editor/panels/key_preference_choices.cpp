// What new keys carry (KeyPreferences): one set of widgets, drawn in the timeline's Keys
// popup and in Edit > Preferences, editing the one setting (Document::autoKey.preferences);
// a change is saved with the user's preferences.
#include <imgui.h>

#include "editor/commands/file_commands.h"
#include "editor/model/keying.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"

namespace kinema {

namespace {
const Interpolation kChoices[] = {Interpolation::Bezier, Interpolation::Linear, Interpolation::Step,
                                  Interpolation::CatmullRom, Interpolation::Ease};
}  // namespace

void drawKeyPreferenceChoices(EditorState& state, const std::string& itemPrefix) {
  KeyPreferences& p = state.doc.autoKey.preferences;
  const KeyPreferences before = p;
  ImGui::TextUnformatted("New keys");
  for (Interpolation i : kChoices) {
    if (ImGui::RadioButton(toString(i), p.interpolation == i)) p.interpolation = i;
    recordItem(itemPrefix + toString(i));
  }
  if (p.interpolation == Interpolation::Bezier) {
    const HandleType handles[] = {HandleType::AutoClamped, HandleType::Auto, HandleType::Vector};
    for (HandleType h : handles) {
      if (ImGui::RadioButton((std::string("handles: ") + toString(h)).c_str(), p.handles == h)) p.handles = h;
      recordItem(itemPrefix + "handles: " + toString(h));
    }
  }
  ImGui::Checkbox("Location + rotation only", &p.locRotOnly);
  recordItem(itemPrefix + "Location + rotation only");
  ImGui::TextDisabled("Rotations (quaternions) take %s", toString(rotationInterpolation(p.interpolation)));
  if (p.interpolation != before.interpolation || p.handles != before.handles || p.locRotOnly != before.locRotOnly)
    saveEditorPreferences(state);
}

}  // namespace kinema
