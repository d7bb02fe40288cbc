#include "editor/panels/mesh_section.h"

#include <imgui.h>

#include <string>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/model/pose_edits.h"

namespace kinema {

void drawMeshSection(EditorState& state) {
  Document& doc = state.doc;
  const std::vector<MeshInstance>& instances = doc.scene().meshInstances;
  if (instances.empty()) return;
  if (!ImGui::CollapsingHeader("Mesh", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Checkbox("Show weights (Alt+W)", &state.view.showWeights);
  recordItem("Properties/Show weights");
  const char* methods[] = {"Linear blend", "Dual quaternion"};
  for (size_t i = 0; i < instances.size(); ++i) {
    const MeshInstance& m = instances[i];
    if (m.skin < 0) continue;  // rigid instances follow their joint; no skinning to choose
    const std::vector<Mesh>& meshes = doc.scene().meshes;
    const std::string shown = m.mesh >= 0 && m.mesh < static_cast<int>(meshes.size()) && !meshes[m.mesh].name.empty()
                                  ? meshes[m.mesh].name
                                  : "mesh " + std::to_string(i);
    const std::string label = shown + "##skinning" + std::to_string(i);
    int current = m.skinning == SkinningMethod::DualQuaternion ? 1 : 0;
    // Named "Properties/Mesh/<mesh>", its entries ".../Linear blend" and ".../Dual quaternion".
    if (namedCombo(label.c_str(), "Properties/Mesh/" + shown, &current, methods, 2))
      showEditorError(state, setMeshSkinning(doc, static_cast<int>(i),
                                             current == 1 ? SkinningMethod::DualQuaternion : SkinningMethod::LinearBlend));
  }
}

}  // namespace kinema
