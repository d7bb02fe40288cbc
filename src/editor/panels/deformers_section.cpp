#include "editor/panels/deformers_section.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "editor/commands/command_registry.h"
#include "editor/model/deformer_edits.h"
#include "editor/model/shape_keys.h"
#include "editor/model/timeline.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"

namespace kinema {

namespace {

// One keyable parameter: a drag field (an undoable edit, keyed instead when the parameter is
// animated in the clip or auto-key is on) and a key button.
void parameterRow(EditorState& state, int instance, int index, const Deformer& d, const std::string& parameter,
                  const char* shown, float speed) {
  Document& doc = state.doc;
  const int clip = state.hasMotion() ? state.clip : -1;
  float value = deformerValueAt(doc, clip, state.time, instance, index, parameter);
  const std::string id = "##" + std::to_string(instance) + "_" + std::to_string(index) + "_" + parameter;
  const std::string item = "Properties/Deformers/" + d.name + "/" + parameter;
  bool animated = false;
  if (clip >= 0)
    for (const Channel& ch : doc.scene().clips[clip].channels)
      animated = animated || (ch.target == ChannelTarget::Scalar && ch.property == "deformers/" + d.name + "/" + parameter);
  if (ImGui::DragFloat((std::string(shown) + id).c_str(), &value, speed)) {
    if (animated || doc.autoKey.enabled) {
      showEditorError(state, keyDeformerValue(doc, state.clip, instance, index, parameter, static_cast<float>(state.time),
                                              value, doc.autoKey.preferences));
      syncDocumentPlayhead(state);
    } else {
      showEditorError(state, setDeformerValue(doc, instance, index, parameter, value));
    }
  }
  recordItem(item);
  if (ImGui::IsItemHovered()) {  // I keys it (anim.key_hovered_property)
    state.hoveredProperty.kind = HoveredProperty::Kind::DeformerParameter;
    state.hoveredProperty.instance = instance;
    state.hoveredProperty.deformer = index;
    state.hoveredProperty.parameter = parameter;
  }
  ImGui::SameLine();
  if (ImGui::SmallButton(("Key" + id).c_str())) {
    showEditorError(state, keyDeformerValue(doc, state.clip, instance, index, parameter, static_cast<float>(state.time),
                                            value, doc.autoKey.preferences));
    syncDocumentPlayhead(state);
  }
  recordItem(item + "/Key");
}

// SameLine when a small button labelled `label` still fits the panel's width, else a new line
// (a narrow panel would clip it off its edge).
void sameLineIfFits(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
  if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
    ImGui::SameLine();
}

// A soft pull's centre, radius and falloff (not keyable: its offset is): Pick centre waits for
// a click on the body in the 3D view (viewport_tools.cpp), radius and falloff edit in place.
void softPullShapeRows(EditorState& state, int instance, int index, const Deformer& d) {
  PanelState& panels = state.panels;
  const bool picking = panels.softPullPickInstance == instance && panels.softPullPickDeformer == index;
  if (ImGui::SmallButton(picking ? "Cancel pick" : "Pick centre")) {
    panels.softPullPickInstance = picking ? -1 : instance;
    panels.softPullPickDeformer = picking ? -1 : index;
    state.statusMessage = picking ? std::string() : "Soft pull: click the body in the 3D view where the pull is centred";
  }
  recordItem("Properties/Deformers/" + d.name + "/Pick centre");
  ImGui::SameLine();
  ImGui::TextDisabled("centre %.3f %.3f %.3f", d.pull.center.x, d.pull.center.y, d.pull.center.z);
  float radius = d.pull.radius;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  ImGui::InputFloat(("radius##" + d.name).c_str(), &radius, 0.0f, 0.0f, "%.4g");
  recordItem("Properties/Deformers/" + d.name + "/radius");
  if (ImGui::IsItemDeactivatedAfterEdit())
    showEditorError(state, setSoftPullShape(state.doc, instance, index, d.pull.center, radius, d.pull.falloff));
  ImGui::SameLine();
  static const Falloff kFalloffs[] = {Falloff::Smooth, Falloff::Sphere, Falloff::Root,
                                      Falloff::Sharp,  Falloff::Linear, Falloff::Constant};
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  if (ImGui::BeginCombo(("falloff##" + d.name).c_str(), toString(d.pull.falloff))) {
    for (Falloff f : kFalloffs)
      if (ImGui::Selectable(toString(f), f == d.pull.falloff) && f != d.pull.falloff)
        showEditorError(state, setSoftPullShape(state.doc, instance, index, d.pull.center, d.pull.radius, f));
    ImGui::EndCombo();
  }
  recordItem("Properties/Deformers/" + d.name + "/falloff");
}

// Where a deformer hangs and what it moves: parent (the world or a joint it follows), scope (every
// vertex or the active joint's skin weights); a lattice's resolution and fit; a bend / twist /
// taper's axis and range. Each change is one undo step (deformer_edits.h).
void placementRows(EditorState& state, int instance, int index, const Deformer& d) {
  Document& doc = state.doc;
  const int active = doc.selection.active();
  const std::string item = "Properties/Deformers/" + d.name + "/";
  ImGui::TextDisabled("follows %s", d.parentJoint >= 0 ? doc.skeleton().names[d.parentJoint].c_str() : "the world");
  sameLineIfFits("Parent to active");
  if (ImGui::SmallButton("Parent to active") && active >= 0) showEditorError(state, setDeformerParent(doc, instance, index, active));
  recordItem(item + "Parent to active");
  sameLineIfFits("World");
  if (ImGui::SmallButton("World")) showEditorError(state, setDeformerParent(doc, instance, index, -1));
  recordItem(item + "Parent to world");
  ImGui::TextDisabled("%s", d.weights.empty() ? "moves every vertex" : "moves a vertex group");
  sameLineIfFits("Limit to active's weights");
  if (ImGui::SmallButton("Limit to active's weights") && active >= 0)
    showEditorError(state, limitDeformerToJoint(doc, instance, index, active));
  recordItem(item + "Limit to active");
  sameLineIfFits("All");
  if (ImGui::SmallButton("All")) showEditorError(state, limitDeformerToJoint(doc, instance, index, -1));
  recordItem(item + "Limit to all");
  if (d.type == DeformerType::Lattice) {
    int counts[3] = {d.lattice.counts[0], d.lattice.counts[1], d.lattice.counts[2]};
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    ImGui::InputInt3(("points##res" + d.name).c_str(), counts);
    recordItem(item + "resolution");
    if (ImGui::IsItemDeactivatedAfterEdit()) showEditorError(state, setLatticeResolution(doc, instance, index, counts));
    sameLineIfFits("Fit to selected");
    if (ImGui::SmallButton("Fit to selected")) showEditorError(state, fitLatticeToJoints(doc, instance, index, doc.selection.joints()));
    recordItem(item + "Fit to selected");
  } else if (d.type != DeformerType::SoftPull) {
    static const char* kAxes[] = {"X", "Y", "Z"};
    int axis = static_cast<int>(d.axis.axis);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 3.0f);
    if (ImGui::Combo(("axis##" + d.name).c_str(), &axis, kAxes, 3))
      showEditorError(state, setAxisRange(doc, instance, index, static_cast<DeformAxis>(axis), d.axis.low, d.axis.high));
    recordItem(item + "axis");
    ImGui::SameLine();
    float range[2] = {d.axis.low, d.axis.high};
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputFloat2(("range (m)##" + d.name).c_str(), range, "%.3g");
    recordItem(item + "range");
    if (ImGui::IsItemDeactivatedAfterEdit())
      showEditorError(state, setAxisRange(doc, instance, index, d.axis.axis, range[0], range[1]));
  }
}

}  // namespace

void drawDeformersSection(CommandContext& ctx) {
  EditorState& state = ctx.state;
  Document& doc = state.doc;
  const int instances = static_cast<int>(doc.scene().meshInstances.size());
  if (instances == 0) return;
  if (!ImGui::CollapsingHeader("Deformers", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (int i = 0; i < instances; ++i) {
    ImGui::PushID(i);
    static const DeformerType kinds[] = {DeformerType::Lattice, DeformerType::Bend, DeformerType::Twist,
                                         DeformerType::Taper, DeformerType::SoftPull};
    static const char* labels[] = {"Lattice", "Bend", "Twist", "Taper", "Soft pull"};
    ImGui::TextDisabled("Add to mesh %d:", i);
    for (int k = 0; k < 5; ++k) {
      sameLineIfFits(labels[k]);
      if (ImGui::SmallButton(labels[k])) {
        showEditorError(state, addDeformer(doc, i, kinds[k]));
        if (kinds[k] == DeformerType::Lattice && !state.lattice.active) {  // the new lattice is the active one (Tab edits it)
          state.lattice.instance = i;
          state.lattice.deformer = static_cast<int>(doc.scene().deformers[i].deformers.size()) - 1;
        }
      }
      recordItem(std::string("Properties/Deformers/Add ") + labels[k]);
    }
    const DeformerStack* stack = doc.scene().deformerStack(static_cast<size_t>(i));
    const int count = stack ? static_cast<int>(stack->deformers.size()) : 0;
    for (int k = 0; k < count; ++k) {
      const Deformer d = doc.scene().deformers[i].deformers[k];  // a copy: the edits below replace the stack
      ImGui::PushID(k);
      bool enabled = d.enabled;
      if (ImGui::Checkbox(d.name.c_str(), &enabled)) showEditorError(state, setDeformerEnabled(doc, i, k, enabled));
      recordItem("Properties/Deformers/" + d.name);
      ImGui::SameLine();
      if (ImGui::SmallButton("Up")) showEditorError(state, moveDeformer(doc, i, k, -1));
      ImGui::SameLine();
      if (ImGui::SmallButton("Down")) showEditorError(state, moveDeformer(doc, i, k, 1));
      ImGui::SameLine();
      if (ImGui::SmallButton("Apply as shape")) showEditorError(state, applyDeformerAsShape(doc, i, k));
      recordItem("Properties/Deformers/" + d.name + "/Apply as shape");
      sameLineIfFits("Remove");
      if (ImGui::SmallButton("Remove")) showEditorError(state, removeDeformer(doc, i, k));
      placementRows(state, i, k, d);
      switch (d.type) {
        case DeformerType::Bend:
        case DeformerType::Twist: parameterRow(state, i, k, d, "angle", "angle (rad)", 0.01f); break;
        case DeformerType::Taper: parameterRow(state, i, k, d, "factor", "factor", 0.01f); break;
        case DeformerType::SoftPull:
          softPullShapeRows(state, i, k, d);
          parameterRow(state, i, k, d, "offset.x", "offset x", 0.002f);
          parameterRow(state, i, k, d, "offset.y", "offset y", 0.002f);
          parameterRow(state, i, k, d, "offset.z", "offset z", 0.002f);
          break;
        case DeformerType::Lattice: {
          ImGui::TextDisabled("%d x %d x %d points", d.lattice.counts[0], d.lattice.counts[1], d.lattice.counts[2]);
          // Edit / Done: lattice edit mode on this lattice (the command Tab runs).
          const bool editing = state.lattice.active && state.lattice.instance == i && state.lattice.deformer == k;
          ImGui::SameLine();
          if (ImGui::SmallButton(editing ? "Done" : "Edit")) {
            if (state.lattice.active) exitLatticeEdit(state);
            if (!editing) {
              state.lattice.instance = i;
              state.lattice.deformer = k;
            }
            if (!editing) showEditorError(state, runCommand(editorCommands(), "lattice.edit", ctx));
          }
          recordItem("Properties/Deformers/" + d.name + "/Edit");
          int& point = state.panels.latticePoint;
          point = std::clamp(point, 0, d.lattice.pointCount() - 1);
          ImGui::SliderInt("point", &point, 0, d.lattice.pointCount() - 1);
          recordItem("Properties/Deformers/" + d.name + "/point");
          for (const char* axis : {"x", "y", "z"}) {
            const std::string parameter = "point." + std::to_string(point) + "." + axis;
            parameterRow(state, i, k, d, parameter, axis, 0.002f);
          }
          break;
        }
      }
      ImGui::PopID();
      if (!doc.scene().deformerStack(static_cast<size_t>(i)) ||
          static_cast<int>(doc.scene().deformers[i].deformers.size()) != count)
        break;  // removed or applied: the rest is drawn next frame
    }
    ImGui::PopID();
  }
}

}  // namespace kinema
