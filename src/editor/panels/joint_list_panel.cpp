// The joint list: the skeleton as an indented tree (parents come before children, so one
// pass with depths is enough); clicking selects, as in Blender's outliner.
#include <imgui.h>

#include "editor/panels/editor_panels.h"

namespace kinema {

void drawJointListPanel(EditorState& state) {
  const Skeleton& s = state.doc.skeleton();
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(230, 420), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Joints")) {
    ImGui::End();
    return;
  }
  ImGui::TextDisabled("%d joints", s.size());
  std::vector<int> depth(static_cast<size_t>(s.size()), 0);
  for (int i = 0; i < s.size(); ++i) {
    if (s.parents[i] >= 0) depth[i] = depth[s.parents[i]] + 1;
    ImGui::PushID(i);
    ImGui::Indent(static_cast<float>(depth[i]) * 10.0f + 0.001f);
    if (ImGui::Selectable(s.names[i].c_str(), state.doc.selection.isSelected(i))) {
      if (ImGui::GetIO().KeyShift) state.doc.selection.shiftClick(i);
      else state.doc.selection.click(i);
    }
    ImGui::Unindent(static_cast<float>(depth[i]) * 10.0f + 0.001f);
    ImGui::PopID();
  }
  if (state.doc.selection.active() >= 0 && state.doc.selection.active() < static_cast<int>(state.world().size())) {
    ImGui::Separator();
    const glm::vec3 p(state.world()[state.doc.selection.active()][3]);
    ImGui::Text("%s", s.names[state.doc.selection.active()].c_str());
    ImGui::Text("world %.3f %.3f %.3f", p.x, p.y, p.z);
  }
  ImGui::End();
}

}  // namespace kinema
