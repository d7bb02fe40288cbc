#include "editor/panels/mesh_section.h"

#include <imgui.h>

#include <string>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/model/pose_edits.h"
#include "editor/model/shape_keys.h"
#include "editor/panels/command_widgets.h"

namespace kinema {

void drawMeshSection(CommandContext& ctx) {
  EditorState& state = ctx.state;
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
  // Shape sliders: the weight at the playhead; a change keys it where it is animated.
  bool anyShapes = false;
  const int clip = state.hasMotion() ? state.clip : -1;
  for (int i = 0; i < static_cast<int>(instances.size()); ++i)
    for (int t = 0; t < shapeCount(doc, i); ++t) {
      if (!anyShapes) ImGui::TextDisabled("Shapes");
      anyShapes = true;
      float w = shapeWeightAt(doc, clip, state.time, i, t);
      const std::string name = shapeName(doc, i, t);
      const std::string label = name + "##shape" + std::to_string(i) + "_" + std::to_string(t);
      if (ImGui::SliderFloat(label.c_str(), &w, 0.0f, 1.0f, "%.3f"))
        showEditorError(state, moveShapeSlider(state, i, t, w));
      recordItem("Properties/Shapes/" + name);
      if (ImGui::IsItemHovered()) {  // I keys it (anim.key_hovered_property)
        state.hoveredProperty.kind = HoveredProperty::Kind::ShapeWeight;
        state.hoveredProperty.instance = i;
        state.hoveredProperty.target = t;
      }
    }
  if (anyShapes) commandButton(ctx, "anim.insert_shape_keys", "Properties");
}

}  // namespace kinema
