// The IK targets of the document: a list, add / remove (the Pose menu's commands), and the
// active joint's target (active_ik_target.h): its effector, chain (length or IK root),
// solver, pole (two-bone), pinned and active switches, and how its last solve went. Every change is one undo step (setIkTarget); drags of the position and
// pole fields are one step each.
#include <imgui.h>

#include <string>

#include "editor/model/active_ik_target.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/model/ik_posing.h"
#include "editor/panels/panel_drag.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/pose_edits.h"

namespace kinema {

namespace {

constexpr IkSolver kSolvers[] = {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianDls,
                                 IkSolver::JacobianTranspose, IkSolver::JacobianPinv, IkSolver::JacobianSdls};

const char* jointName(const Skeleton& s, int joint) {
  return joint >= 0 && joint < s.size() ? s.names[joint].c_str() : "(none)";
}

void apply(EditorState& state, int t, const PoseIkTarget& settings) {
  showEditorError(state, setIkTarget(state.doc, t, settings));
}

void targetSettings(EditorState& state, int t) {
  Document& doc = state.doc;
  const Skeleton& s = doc.skeleton();
  const PoseIkTarget current = doc.ikTargets()[t];
  PoseIkTarget next = current;

  const bool effectorOpen = ImGui::BeginCombo("Effector", jointName(s, current.target.effector));
  recordItem("IK Targets/Effector");
  if (effectorOpen) {
    for (int j = 0; j < s.size(); ++j) {
      if (ImGui::Selectable(s.names[j].c_str(), j == current.target.effector)) {
        next.target.effector = j;
        next.target.root = -1;
        next.target.mid = -1;
        apply(state, t, next);
        // The target stays the active one: its new effector becomes the active joint.
        if (doc.ikTargets()[t].target.effector == j) doc.selection.click(j);
      }
      recordItem("IK Targets/Effector/" + s.names[j]);
    }
    ImGui::EndCombo();
  }
  // Chain: a length up from the effector, or 0 and an explicit IK root among its ancestors.
  int length = current.chainLength;
  const bool lengthChanged = ImGui::InputInt("Chain length", &length);
  recordStepper("IK Targets/Chain length");
  if (lengthChanged && length >= 0 && length <= s.size()) {
    next = current;
    next.chainLength = length;
    apply(state, t, next);
  }
  if (current.chainLength == 0) {
    const int root = current.target.root;
    const bool rootOpen = ImGui::BeginCombo("IK root", root < 0 ? "(automatic)" : jointName(s, root));
    recordItem("IK Targets/IK root");
    if (rootOpen) {
      if (ImGui::Selectable("(automatic)", root < 0)) {
        next = current;
        next.target.root = -1;
        apply(state, t, next);
      }
      recordItem("IK Targets/IK root/(automatic)");
      for (int j = s.parents[current.target.effector]; j >= 0; j = s.parents[j]) {
        if (ImGui::Selectable(s.names[j].c_str(), j == root)) {
          next = current;
          next.target.root = j;
          apply(state, t, next);
        }
        recordItem("IK Targets/IK root/" + s.names[j]);
      }
      ImGui::EndCombo();
    }
  }
  const bool solverOpen = ImGui::BeginCombo("Solver", toString(current.solver));
  recordItem("IK Targets/Solver");
  if (solverOpen) {
    for (IkSolver solver : kSolvers) {
      if (ImGui::Selectable(toString(solver), solver == current.solver)) {
        next = current;
        next.solver = solver;
        apply(state, t, next);
      }
      recordItem(std::string("IK Targets/Solver/") + toString(solver));
    }
    ImGui::EndCombo();
  }
  bool pinned = current.pinned, active = current.active;
  const bool pinToggled = ImGui::Checkbox("Pinned", &pinned);
  recordItem("IK Targets/Pinned");
  if (pinToggled) {
    next = current;
    next.pinned = pinned;
    apply(state, t, next);
  }
  ImGui::SameLine();
  const bool activeToggled = ImGui::Checkbox("Active", &active);
  recordItem("IK Targets/Active");
  if (activeToggled) {
    next = current;
    next.active = active;
    apply(state, t, next);
  }

  // Position: a drag moves the target and solves, one undo step.
  float position[3] = {current.target.position.x, current.target.position.y, current.target.position.z};
  const bool moved = ImGui::DragFloat3("Position", position, 0.01f, 0.0f, 0.0f, "%.3f");
  recordFields("IK Targets/Position", 3);
  dragAsOneStep(
      state, moved, [&] { return beginIkTargetDrag(doc, t); },
      [&] { return updateIkTargetDrag(doc, t, glm::vec3(position[0], position[1], position[2])); });

  if (current.solver == IkSolver::TwoBone) {
    bool hasPole = current.target.hasPole;
    const bool poleToggled = ImGui::Checkbox("Pole target", &hasPole);
    recordItem("IK Targets/Pole target");
    if (poleToggled) {
      next = current;
      next.target.hasPole = hasPole;
      if (hasPole && current.target.pole == glm::vec3(0.0f)) {
        // Start the pole in front of the middle joint, where knees and elbows usually point.
        const int mid = current.target.mid >= 0 ? current.target.mid : s.parents[current.target.effector];
        if (mid >= 0) next.target.pole = glm::vec3(doc.worldTransforms()[mid][3]) + glm::vec3(0, 0, 0.5f);
      }
      apply(state, t, next);
    }
    if (current.target.hasPole) {
      float pole[3] = {current.target.pole.x, current.target.pole.y, current.target.pole.z};
      const bool changed = ImGui::DragFloat3("Pole", pole, 0.01f, 0.0f, 0.0f, "%.3f");
      recordFields("IK Targets/Pole", 3);
      dragAsOneStep(
          state, changed, [&] { return doc.beginDrag("Set IK pole of " + std::string(jointName(s, current.target.effector))); },
          [&] {
            return doc.updateDrag([&](DocumentEdit& e) {
              e.targets[t].target.pole = glm::vec3(pole[0], pole[1], pole[2]);
              return std::string();
            });
          });
    }
  }

  // How the last solve went (Document::lastIkReports, also in the status bar).
  for (const IkTargetReport& report : doc.lastIkReports())
    if (report.target == t)
      ImGui::TextDisabled("%s: %d it, error %.1e, %.2f ms", report.converged ? "reached" : "missed",
                          report.iterations, report.error, report.milliseconds);
}

}  // namespace

void drawIkTargetsPanel(CommandContext& ctx) {
  EditorState& state = ctx.state;
  Document& doc = state.doc;
  PanelState& p = state.panels;
  const PanelRect r = state.layout.ikTargets;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  if (!ImGui::Begin("IK Targets", nullptr, kPanelFlags)) {
    ImGui::End();
    return;
  }
  recordWindow("IK Targets");
  const Skeleton& s = doc.skeleton();
  // Add and Remove are the Pose menu's commands: they act on the active joint and its target.
  commandButton(ctx, "pose.add_ik_target", "IK Targets", "Add to selected");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(scaled(state, 70));
  ImGui::InputInt("bones", &p.ikChainLength);
  recordStepper("IK Targets/Bones", 70);
  if (p.ikChainLength < 1) p.ikChainLength = 1;
  ImGui::SameLine();
  commandButton(ctx, "pose.remove_ik_target", "IK Targets", "Remove");
  // The row of the active IK target is highlighted; clicking a row makes its effector the
  // active joint, so the row, the menu and the keys always mean the same target.
  const int activeTarget = activeIkTarget(doc);
  if (ImGui::BeginListBox("##targets", ImVec2(-1, 4.5f * ImGui::GetTextLineHeightWithSpacing()))) {
    const auto& targets = doc.ikTargets();
    for (size_t i = 0; i < targets.size(); ++i) {
      const PoseIkTarget& t = targets[i];
      const std::string label = std::to_string(i) + ": " + jointName(s, t.target.effector) + "  (" +
                                toString(t.solver) + (t.pinned ? ", pinned" : "") + (t.active ? "" : ", off") + ")";
      if (ImGui::Selectable(label.c_str(), activeTarget == static_cast<int>(i)) && t.target.effector >= 0 &&
          t.target.effector < s.size())
        doc.selection.click(t.target.effector);
      recordItem(state.items, "IK Targets/" + std::to_string(i));
    }
    if (targets.empty()) ImGui::TextDisabled("no targets: select a joint, then Add");
    ImGui::EndListBox();
  }
  // The document solves every target with one tolerance and iteration cap (not undo steps).
  if (ImGui::TreeNode("Solver limits (all targets)")) {
    ImGui::PushItemWidth(-110);
    float tolerance = doc.ikSettings.tolerance;
    if (ImGui::DragFloat("Tolerance", &tolerance, 1e-5f, 1e-6f, 1.0f, "%.6f", ImGuiSliderFlags_Logarithmic) &&
        tolerance > 0.0f)
      doc.ikSettings.tolerance = tolerance;
    int iterations = doc.ikSettings.maxIterations;
    if (ImGui::InputInt("Iterations", &iterations) && iterations >= 1 && iterations <= 100000)
      doc.ikSettings.maxIterations = iterations;
    ImGui::PopItemWidth();
    ImGui::TreePop();
  }
  // The active joint's targets (one, unless an effector was changed onto a joint that had one).
  for (int t : ikTargetsOnJoint(doc, doc.selection.active())) {
    if (t >= static_cast<int>(doc.ikTargets().size())) break;  // a setting above removed one
    ImGui::Separator();
    ImGui::PushID(t);
    ImGui::PushItemWidth(-110);
    targetSettings(state, t);
    ImGui::PopItemWidth();
    ImGui::PopID();
  }
  ImGui::End();
}

}  // namespace kinema
