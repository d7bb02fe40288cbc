// Properties of the active joint: name, rotation (Euler degrees in a chosen order, or a
// quaternion normalised on entry), location for roots, joint limits. Each change is one
// undo step; a drag on a field is one step (begun when the field activates, committed when
// it is released after an edit, dropped when nothing changed).
#include <imgui.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/deformers_section.h"
#include "editor/panels/mesh_section.h"
#include "editor/panels/panel_drag.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/pose_edits.h"

namespace kinema {

namespace {

constexpr EulerOrder kOrders[] = {EulerOrder::XYZ, EulerOrder::XZY, EulerOrder::YXZ,
                                  EulerOrder::YZX, EulerOrder::ZXY, EulerOrder::ZYX};

void rotationSection(EditorState& state, int joint) {
  Document& doc = state.doc;
  PanelState& p = state.panels;
  const glm::quat q = doc.pose().local[joint].rotation;
  const char* preview = p.quaternionEntry ? "Quaternion" : toString(p.eulerOrder);
  ImGui::SetNextItemWidth(scaled(state, 120));
  const bool modeOpen = ImGui::BeginCombo("Rotation mode", preview);
  recordItem("Properties/Rotation mode");
  if (modeOpen) {
    for (EulerOrder order : kOrders) {
      if (ImGui::Selectable(toString(order), !p.quaternionEntry && p.eulerOrder == order)) {
        p.eulerOrder = order;
        p.quaternionEntry = false;
      }
      recordItem(std::string("Properties/Rotation mode/") + toString(order));
    }
    if (ImGui::Selectable("Quaternion", p.quaternionEntry)) p.quaternionEntry = true;
    recordItem("Properties/Rotation mode/Quaternion");
    ImGui::EndCombo();
  }
  if (!p.quaternionEntry) {
    // While a field is held, its own numbers are kept (re-deriving them from the quaternion
    // every frame would jump between equivalent Euler triples).
    float degrees[3];
    if (p.dragging && p.heldJoint == joint) {
      for (int k = 0; k < 3; ++k) degrees[k] = p.heldEuler[k];
    } else {
      const glm::vec3 e = glm::degrees(quatToEuler(q, p.eulerOrder));
      degrees[0] = e.x, degrees[1] = e.y, degrees[2] = e.z;
      for (float& d : degrees) d += 0.0f;  // -0 shows as 0
    }
    const bool changed = ImGui::DragFloat3("Rotation", degrees, 0.5f, 0.0f, 0.0f, "%.2f");
    recordFields("Properties/Rotation", 3);
    for (int k = 0; k < 3; ++k) p.heldEuler[k] = degrees[k];
    p.heldJoint = joint;
    const glm::vec3 radians = glm::radians(glm::vec3(degrees[0], degrees[1], degrees[2]));
    dragAsOneStep(
        state, changed, [&] { return beginRotateDrag(doc, joint); },
        [&] { return updateRotateDrag(doc, joint, eulerToQuat(radians, p.eulerOrder)); });
    const std::string order = toString(p.eulerOrder);
    ImGui::TextDisabled("degrees about X, Y, Z; R = R%c R%c R%c", std::tolower(order[0]), std::tolower(order[1]),
                        std::tolower(order[2]));
  } else {
    // x, y, z, w as files write them. Typed components wait (a half-typed quaternion is no
    // rotation) until Enter or Apply sets the normalised rotation as one undo step.
    float* typed = p.typedQuaternion;
    if (!p.quaternionEditing || p.quaternionJoint != joint) {
      typed[0] = q.x, typed[1] = q.y, typed[2] = q.z, typed[3] = q.w;
      p.quaternionEditing = false;
      p.quaternionJoint = joint;
    }
    if (ImGui::InputFloat4("x y z w", typed, "%.3f")) p.quaternionEditing = true;
    recordFields("Properties/Quaternion", 4);
    bool apply = p.quaternionEditing && ImGui::IsItemDeactivated() &&
                 (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                  ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter), false));
    if (p.quaternionEditing) {
      apply = ImGui::Button("Apply") || apply;
      recordItem("Properties/Apply");
      ImGui::SameLine();
      if (ImGui::Button("Revert")) p.quaternionEditing = false;
      recordItem("Properties/Revert");
      ImGui::SameLine();
      ImGui::TextDisabled("normalised on entry");
    }
    if (apply) {
      p.quaternionEditing = false;
      const glm::quat entered(typed[3], typed[0], typed[1], typed[2]);
      if (!(glm::dot(entered, entered) > 1e-12f) || !std::isfinite(glm::dot(entered, entered)))
        showEditorError(state, "a rotation quaternion must be finite and not zero");
      else
        showEditorError(state, setJointRotation(doc, joint, safeNormalize(entered)));
    }
  }
}

void locationSection(EditorState& state, int joint) {
  Document& doc = state.doc;
  const glm::vec3 t = doc.pose().local[joint].translation;
  float v[3] = {t.x, t.y, t.z};
  const bool changed = ImGui::DragFloat3("Location", v, 0.01f, 0.0f, 0.0f, "%.3f");
  recordFields("Properties/Location", 3);
  dragAsOneStep(
      state, changed, [&] { return beginTranslateDrag(doc, joint); },
      [&] { return updateTranslateDrag(doc, joint, glm::vec3(v[0], v[1], v[2])); });
}

void limitSection(EditorState& state, int joint) {
  Document& doc = state.doc;
  const JointLimit* current = doc.rig().limitOf(joint);
  JointLimit limit = current ? *current : JointLimit{};
  bool enabled = current != nullptr;
  if (!ImGui::CollapsingHeader("Joint limit", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const bool toggled = ImGui::Checkbox("Enabled", &enabled);
  recordItem("Properties/Limit enabled");
  if (toggled) {
    // Enabling starts from a loose cone about the bone's direction; the user narrows it.
    JointLimit next = enabled ? JointLimit::cone(glm::vec3(0, 1, 0), glm::radians(45.0f), glm::radians(-45.0f),
                                                 glm::radians(45.0f))
                              : JointLimit{};
    showEditorError(state, setJointLimit(doc, joint, next));
    return;
  }
  if (!enabled) return;
  const char* types[] = {"Hinge", "Cone", "Euler"};
  int type = static_cast<int>(limit.type) - 1;
  ImGui::SetNextItemWidth(scaled(state, 120));
  const bool retyped = ImGui::Combo("Type", &type, types, 3);
  recordItem("Properties/Limit type");
  if (retyped) {
    JointLimit next = limit;
    next.type = static_cast<JointLimitType>(type + 1);
    showEditorError(state, setJointLimit(doc, joint, next));
    return;
  }
  // Ranges in degrees; each drag is one step through the document's generic drag.
  JointLimit edited = limit;
  bool changed = false;
  const auto dragRange = [&](const char* label, float& lo, float& hi, float min, float max) {
    float v[2] = {glm::degrees(lo), glm::degrees(hi)};
    changed = ImGui::DragFloat2(label, v, 0.5f, min, max, "%.1f deg");
    recordFields(std::string("Properties/") + label, 2);
    lo = glm::radians(v[0]);
    hi = glm::radians(v[1]);
  };
  const auto step = [&] {
    dragAsOneStep(
        state, changed, [&] { return doc.beginDrag("Set joint limit of " + doc.skeleton().names[joint]); },
        [&]() -> std::string {
          if (std::string why = edited.validate(); !why.empty()) return why;
          return doc.updateDrag([&](DocumentEdit& e) {
            if (static_cast<int>(e.limits.size()) < e.skeleton.size()) e.limits.resize(e.skeleton.size());
            e.limits[joint] = edited;
            return std::string();
          });
        });
  };
  if (limit.type == JointLimitType::Hinge) {
    dragRange("Angle", edited.minAngle, edited.maxAngle, -180.0f, 180.0f);
    step();
  } else if (limit.type == JointLimitType::Cone) {
    float cone = glm::degrees(limit.coneAngle);
    changed = ImGui::DragFloat("Cone", &cone, 0.5f, 0.0f, 180.0f, "%.1f deg");
    recordItem("Properties/Cone");
    edited.coneAngle = glm::radians(cone);
    step();
    edited = limit;
    dragRange("Twist", edited.twistMin, edited.twistMax, -180.0f, 180.0f);
    step();
  } else if (limit.type == JointLimitType::Euler) {
    const char* axes[] = {"X range", "Y range", "Z range"};
    for (int k = 0; k < 3; ++k) {
      edited = limit;
      dragRange(axes[k], edited.eulerMin[k], edited.eulerMax[k], -180.0f, 180.0f);
      step();
    }
  }
  ImGui::TextDisabled("axis %.2f %.2f %.2f", limit.axis.x, limit.axis.y, limit.axis.z);
}

}  // namespace

void drawPropertiesPanel(CommandContext& ctx) {
  EditorState& state = ctx.state;
  Document& doc = state.doc;
  const PanelRect r = state.layout.properties;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  state.panels.propertiesJoint = -1;
  if (!ImGui::Begin("Properties", nullptr, kPanelFlags)) {
    ImGui::End();
    return;
  }
  recordWindow("Properties");
  const int joint = doc.selection.active();
  if (joint < 0 || joint >= doc.skeleton().size() || joint >= doc.pose().size()) {
    ImGui::TextDisabled("Select a joint (click it or pick it in the outliner).");
    // The meshes' sections (skinning, shapes, deformers) do not depend on the joint.
    drawMeshSection(ctx);
    drawDeformersSection(ctx);
    ImGui::End();
    return;
  }
  state.panels.propertiesJoint = joint;  // what the state dump reports the panel showing
  ImGui::PushItemWidth(-110);
  ImGui::PushID(joint);
  // Name: renamed when Enter is pressed; the model refuses empty or duplicate names.
  PanelState& p = state.panels;
  if (!p.nameEditing || p.nameJoint != joint) {
    std::snprintf(p.nameBuffer, sizeof(p.nameBuffer), "%s", doc.skeleton().names[joint].c_str());
    p.nameJoint = joint;
  }
  if (ImGui::InputText("Name", p.nameBuffer, sizeof(p.nameBuffer), ImGuiInputTextFlags_EnterReturnsTrue))
    showEditorError(state, renameJoint(doc, joint, p.nameBuffer));
  p.nameEditing = ImGui::IsItemActive();
  recordItem("Properties/Name");
  const int parent = doc.skeleton().parents[joint];
  ImGui::TextDisabled("parent: %s", parent >= 0 ? doc.skeleton().names[parent].c_str() : "(root)");
  ImGui::Separator();
  rotationSection(state, joint);
  if (parent < 0) locationSection(state, joint);
  const glm::vec3 world(doc.worldTransforms()[joint][3]);
  ImGui::TextDisabled("world position %.3f %.3f %.3f", world.x, world.y, world.z);
  limitSection(state, joint);
  drawMeshSection(ctx);
  drawDeformersSection(ctx);
  ImGui::PopID();
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace kinema
