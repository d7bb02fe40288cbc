// Esc closes any open menu, combo or popup (ImGui 1.86 leaves them open, so the next click
// picked an item by accident). Modal dialogs are left to their own Esc handling.
#include <imgui.h>
#include <imgui_internal.h>  // the open-popup stack: 1.86 has no public "close all popups"

#include "editor/panels/editor_panels.h"

namespace kinema {

void closePopupsOnEscape(EditorState& state) {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  // The non-modal popups sit above the topmost modal (or fill the stack when there is none).
  int level = g.OpenPopupStack.Size;
  while (level > 0) {
    const ImGuiWindow* w = g.OpenPopupStack[level - 1].Window;
    if (w && (w->Flags & ImGuiWindowFlags_Modal)) break;
    --level;
  }
  const bool open = level < g.OpenPopupStack.Size;
  if (open && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::ClosePopupToLevel(level, true);
    state.panels.popupOpen = false;
    return;
  }
  state.panels.popupOpen = open;
}

}  // namespace kinema
