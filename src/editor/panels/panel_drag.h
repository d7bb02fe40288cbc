#pragma once
#include <imgui.h>

#include <string>

#include "editor/panels/editor_panels.h"

namespace kinema {

// Wraps the last ImGui item in a document drag so that dragging (or typing into) a field is
// one undo step: `begin` when the item activates, `update` while its value changes, commit
// when it is released after an edit, cancel when nothing changed.
template <class Begin, class Update>
void dragAsOneStep(EditorState& state, bool changed, Begin begin, Update update) {
  Document& doc = state.doc;
  if (ImGui::IsItemActivated() && !doc.dragging()) {
    if (const std::string error = begin(); !error.empty()) showEditorError(state, error);
    else state.panels.dragging = true;
  }
  if (changed && state.panels.dragging) {
    if (const std::string error = update(); !error.empty()) state.statusMessage = error;
  }
  if (ImGui::IsItemDeactivated() && state.panels.dragging) {
    state.panels.dragging = false;
    if (ImGui::IsItemDeactivatedAfterEdit()) doc.commitDrag();
    else doc.cancelDrag();
  }
}

}  // namespace kinema
