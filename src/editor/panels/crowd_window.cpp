// Simulate > Show Crowd Panel: the active crowd's settings (members, seed, neighbourhood,
// weights, speeds, goal, obstacles), each change one undo step (Enter or leaving a field
// commits it), the Simulate menu's crowd commands as buttons, and a legend of the debug
// member's impulse vectors (the colours the viewport draws them in).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "editor/commands/animation_editor_commands.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

constexpr const char* kCrowdWindow = "Crowd";

bool floatField(EditorState& state, const char* label, float& value, float lo, float hi = 1e30f) {
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  ImGui::InputFloat(label, &value, 0.0f, 0.0f, "%.4g");
  recordItem(std::string(kCrowdWindow) + "/" + label);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  if (!std::isfinite(value) || value < lo) value = lo;
  value = std::min(value, hi);
  return true;
}

bool intField(EditorState& state, const char* label, int& value, int lo, int hi) {
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  ImGui::InputInt(label, &value, 0, 0);
  recordItem(std::string(kCrowdWindow) + "/" + label);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  value = std::clamp(value, lo, hi);
  return true;
}

bool vec3Field(EditorState& state, const std::string& label, glm::vec3& value) {
  ImGui::SetNextItemWidth(scaled(state, 160.0f));
  ImGui::InputFloat3(label.c_str(), &value.x, "%.3g");
  recordItem(std::string(kCrowdWindow) + "/" + label);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(value[i])) value[i] = 0.0f;
  return true;
}

}  // namespace

void drawCrowdWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.crowds.windowOpen) return;
  const PanelRect& v = state.layout.viewport;
  // At the viewport's right edge, narrow: the flock and the debug member stay in view.
  ImGui::SetNextWindowPos(ImVec2(v.x + v.w - scaled(state, 318.0f), v.y + scaled(state, 8.0f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(scaled(state, 310.0f), std::min(scaled(state, 640.0f), v.h - scaled(state, 16.0f))),
                           ImGuiCond_Appearing);
  if (!ImGui::Begin(kCrowdWindow, &state.crowds.windowOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow(kCrowdWindow);
  commandButton(ctx, "sim.add_crowd", kCrowdWindow, "Add crowd");
  ImGui::SameLine();
  commandButton(ctx, "sim.bake_crowd", kCrowdWindow, "Bake");
  ImGui::SameLine();
  commandButton(ctx, "sim.remove_crowd", kCrowdWindow, "Remove");
  commandSelectable(ctx, "sim.crowd_naive_average", kCrowdWindow, "Naive average allocation (instead of priority)");
  ImGui::Checkbox("Draw the flock", &state.crowds.live);
  recordItem(std::string(kCrowdWindow) + "/Draw the flock");
  ImGui::Separator();
  const auto& crowds = state.doc.scene().simulation.crowds;
  if (crowds.empty()) {
    ImGui::TextWrapped("No crowd yet: Add crowd makes a flock of this character playing its clip.");
    ImGui::End();
    return;
  }
  state.crowds.active = std::clamp(state.crowds.active, 0, static_cast<int>(crowds.size()) - 1);
  if (crowds.size() > 1) {
    ImGui::SetNextItemWidth(scaled(state, 90.0f));
    ImGui::InputInt("crowd", &state.crowds.active);
    recordItem(std::string(kCrowdWindow) + "/crowd");
    state.crowds.active = std::clamp(state.crowds.active, 0, static_cast<int>(crowds.size()) - 1);
  }
  CrowdSettings c = crowds[state.crowds.active];
  BoidsSettings& b = c.boids;
  ImGui::Text("'%s': %s, clip %d", c.name.c_str(), c.character.empty() ? "this character" : c.character.c_str(), c.clip);
  bool changed = false;
  changed |= intField(state, "members", c.members, 1, kCrowdMaxMembers);
  c.debugMember = std::min(c.debugMember, c.members - 1);
  int seed = static_cast<int>(c.seed & 0x7fffffff);
  if (intField(state, "seed", seed, 0, 0x7fffffff)) c.seed = static_cast<uint64_t>(seed), changed = true;
  changed |= intField(state, "debug member", c.debugMember, 0, c.members - 1);
  changed |= vec3Field(state, "spawn centre", c.spawnCentre);
  ImGui::TextDisabled("Neighbourhood");
  changed |= floatField(state, "separation distance", b.separationDistance, 1e-3f);
  changed |= floatField(state, "neighbour radius", b.neighbourRadius, 1e-3f);
  changed |= floatField(state, "field of view (deg)", b.fieldOfViewDegrees, 1.0f, 360.0f);
  ImGui::TextDisabled("Weights (priority order)");
  changed |= floatField(state, "avoidance", b.avoidanceWeight, 0.0f);
  changed |= floatField(state, "separation", b.separationWeight, 0.0f);
  changed |= floatField(state, "alignment", b.alignmentWeight, 0.0f);
  changed |= floatField(state, "cohesion", b.cohesionWeight, 0.0f);
  changed |= floatField(state, "goal", b.goalWeight, 0.0f);
  ImGui::TextDisabled("Speeds");
  changed |= floatField(state, "max speed", b.maxSpeed, 1e-3f);
  changed |= floatField(state, "cruise speed", b.cruiseSpeed, 0.0f, b.maxSpeed);
  changed |= floatField(state, "max acceleration", b.maxAcceleration, 1e-3f);
  changed |= floatField(state, "avoidance distance", b.avoidanceDistance, 0.0f);
  changed |= floatField(state, "stride speed (0 = clip's)", c.strideSpeed, 0.0f);
  ImGui::TextDisabled("Goal and obstacles");
  if (ImGui::Checkbox("seek the goal", &b.hasGoal)) changed = true;
  recordItem(std::string(kCrowdWindow) + "/seek the goal");
  if (b.hasGoal) changed |= vec3Field(state, "goal", b.goal);
  for (size_t i = 0; i < b.spheres.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    changed |= vec3Field(state, "sphere " + std::to_string(i), b.spheres[i].centre);
    changed |= floatField(state, "radius", b.spheres[i].radius, 1e-3f);
    ImGui::PopID();
  }
  for (size_t i = 0; i < b.boxes.size(); ++i) {
    changed |= vec3Field(state, "box " + std::to_string(i) + " min", b.boxes[i].min);
    changed |= vec3Field(state, "box " + std::to_string(i) + " max", b.boxes[i].max);
    b.boxes[i].max = glm::max(b.boxes[i].max, b.boxes[i].min);
  }
  if (ImGui::Button("Add sphere")) b.spheres.push_back({b.goal * 0.5f, 2.0f}), changed = true;
  recordItem(std::string(kCrowdWindow) + "/Add sphere");
  ImGui::SameLine();
  if (ImGui::Button("Add box")) b.boxes.push_back({glm::vec3(-1.0f), glm::vec3(1.0f)}), changed = true;
  recordItem(std::string(kCrowdWindow) + "/Add box");
  if (changed) reportDopeSheetEdit(state, setCrowdEdit(state.doc, state.crowds.active, c), "Crowd settings changed");
  ImGui::Separator();
  ImGui::TextDisabled("Member %d's impulses (desired accelerations x 0.15 s)", c.debugMember);
  const char* names[] = {"avoidance", "separation", "alignment", "cohesion", "goal", "acceleration"};
  for (int k = 0; k <= kBoidImpulseCount; ++k) {
    const glm::vec4& col = crowdImpulseColor(k);
    ImGui::TextColored(ImVec4(col.r, col.g, col.b, 1.0f), "%s %s", k < kBoidImpulseCount ? "->" : "=>", names[k]);
    if (k % 3 != 2 && k < kBoidImpulseCount) ImGui::SameLine();
  }
  if (!state.crowds.preview.error.empty()) ImGui::TextWrapped("%s", state.crowds.preview.error.c_str());
  ImGui::End();
}

}  // namespace kinema
