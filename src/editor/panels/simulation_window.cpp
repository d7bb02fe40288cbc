// Simulate > Simulation Settings…: each dynamic chain's settings (stiffness, damping, drag,
// gravity, radius; its capsule colliders listed) and each ragdoll's, edited in place (one
// undo step per change), with the Simulate menu's commands as buttons and the last bake's
// parts. Teach > Stiff Springs: the four integrators on the damped spring chain at a step
// chosen as a fraction of explicit Euler's limit, energy over time (kinema demo stiff-springs
// draws the same runs into figures).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "editor/commands/animation_editor_commands.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"
#include "sim/integrators.h"

namespace kinema {

namespace {

constexpr const char* kSimulationWindow = "Simulation";
constexpr const char* kTeachWindow = "Stiff Springs";

void placeWindow(EditorState& state, float w, float h) {
  const PanelRect& v = state.layout.viewport;
  const ImVec2 size(std::min(scaled(state, w), v.w - scaled(state, 16.0f)), std::min(scaled(state, h), v.h - scaled(state, 16.0f)));
  ImGui::SetNextWindowPos(ImVec2(v.x + scaled(state, 8.0f), v.y + scaled(state, 8.0f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(std::max(size.x, 240.0f), std::max(size.y, 200.0f)), ImGuiCond_Appearing);
}

// A float field that commits on Enter or when it loses focus (one undo step then).
bool floatField(EditorState& state, const std::string& id, const char* label, float& value, float lo) {
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  ImGui::InputFloat(label, &value, 0.0f, 0.0f, "%.4g");
  recordItem(std::string(kSimulationWindow) + "/" + id);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  if (!std::isfinite(value) || value < lo) value = lo;
  return true;
}

void chainSection(EditorState& state, int index) {
  SpringBoneChain chain = state.doc.scene().simulation.springChains[index];
  const Skeleton& s = state.doc.skeleton();
  const std::string id = "Chain " + std::to_string(index);
  ImGui::PushID(index);
  ImGui::Text("Dynamic chain '%s': %s .. %s (%d joints)", chain.name.c_str(), s.names[chain.joints.front()].c_str(),
              s.names[chain.joints.back()].c_str(), static_cast<int>(chain.joints.size()));
  bool changed = false;
  changed |= floatField(state, id + "/Stiffness", "stiffness (1/s^2)", chain.stiffness, 0.0f);
  changed |= floatField(state, id + "/Damping", "damping (1/s)", chain.damping, 0.0f);
  changed |= floatField(state, id + "/Drag", "drag (1/unit)", chain.drag, 0.0f);
  changed |= floatField(state, id + "/Radius", "radius (units)", chain.radius, 0.0f);
  ImGui::SetNextItemWidth(scaled(state, 200.0f));
  ImGui::InputFloat3("gravity (units/s^2)", &chain.gravity.x, "%.4g");
  recordItem(std::string(kSimulationWindow) + "/" + id + "/Gravity");
  changed |= ImGui::IsItemDeactivatedAfterEdit() && isFinite(chain.gravity);
  ImGui::TextDisabled("%d collision capsule%s (Simulate > Add Collision Capsule on the active joint)",
                      static_cast<int>(chain.colliders.size()), chain.colliders.size() == 1 ? "" : "s");
  int removeCollider = -1;
  for (int k = 0; k < static_cast<int>(chain.colliders.size()); ++k) {
    SpringCollider& c = chain.colliders[k];
    const std::string cid = id + "/Capsule " + std::to_string(k);
    ImGui::PushID(k);
    ImGui::Text("Capsule %d on %s (ends in its space)", k, c.joint >= 0 ? s.names[c.joint].c_str() : "the world");
    ImGui::SetNextItemWidth(scaled(state, 200.0f));
    ImGui::InputFloat3("end a", &c.a.x, "%.4g");
    recordItem(std::string(kSimulationWindow) + "/" + cid + "/A");
    changed |= ImGui::IsItemDeactivatedAfterEdit() && isFinite(c.a);
    ImGui::SetNextItemWidth(scaled(state, 200.0f));
    ImGui::InputFloat3("end b", &c.b.x, "%.4g");
    recordItem(std::string(kSimulationWindow) + "/" + cid + "/B");
    changed |= ImGui::IsItemDeactivatedAfterEdit() && isFinite(c.b);
    changed |= floatField(state, cid + "/Radius", "capsule radius", c.radius, 1e-6f);
    ImGui::SameLine();
    if (ImGui::Button("Remove")) removeCollider = k;
    recordItem(std::string(kSimulationWindow) + "/" + cid + "/Remove");
    ImGui::PopID();
  }
  if (changed) reportDopeSheetEdit(state, setSpringChainEdit(state.doc, index, chain), "Set dynamic chain " + chain.name);
  else if (removeCollider >= 0)
    reportDopeSheetEdit(state, removeColliderEdit(state.doc, index, removeCollider), "Removed the collision capsule");
  if (ImGui::Button("Remove chain")) reportDopeSheetEdit(state, removeSpringChainEdit(state.doc, index), "Removed the dynamic chain");
  recordItem(std::string(kSimulationWindow) + "/" + id + "/Remove");
  ImGui::PopID();
  ImGui::Separator();
}

void ragdollSection(EditorState& state, int index) {
  RagdollSettings r = state.doc.scene().simulation.ragdolls[index];
  const std::string id = "Ragdoll " + std::to_string(index);
  ImGui::PushID(1000 + index);
  ImGui::Text("Ragdoll '%s' from joint %s", r.name.c_str(), state.doc.skeleton().names[r.root].c_str());
  bool changed = false;
  int start = static_cast<int>(r.startFrame);
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  ImGui::InputInt("start frame", &start, 0);
  recordItem(std::string(kSimulationWindow) + "/" + id + "/Start frame");
  if (ImGui::IsItemDeactivatedAfterEdit()) r.startFrame = std::max(start, 0), changed = true;
  changed |= floatField(state, id + "/Mass", "mass (kg)", r.mass, 1e-3f);
  changed |= floatField(state, id + "/Ground", "ground height", r.groundHeight, -1e9f);
  changed |= floatField(state, id + "/Friction", "friction", r.friction, 0.0f);
  changed |= floatField(state, id + "/Restitution", "restitution", r.restitution, 0.0f);
  changed |= floatField(state, id + "/Damping", "damping", r.damping, 0.0f);
  r.restitution = std::min(r.restitution, 1.0f);
  r.damping = std::min(r.damping, 1.0f);
  if (changed) reportDopeSheetEdit(state, setRagdollEdit(state.doc, index, r), "Set ragdoll " + r.name);
  if (ImGui::Button("Remove ragdoll")) reportDopeSheetEdit(state, removeRagdollEdit(state.doc, index), "Removed the ragdoll");
  recordItem(std::string(kSimulationWindow) + "/" + id + "/Remove");
  ImGui::PopID();
  ImGui::Separator();
}

}  // namespace

void drawSimulationWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.simulationWindowOpen) return;
  placeWindow(state, 420.0f, 520.0f);
  if (!ImGui::Begin(kSimulationWindow, &state.simulationWindowOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow(kSimulationWindow);
  commandButton(ctx, "sim.make_chain_dynamic", kSimulationWindow, "Make selected chain dynamic");
  ImGui::SameLine();
  commandButton(ctx, "sim.live_springs", kSimulationWindow, "Live");
  commandButton(ctx, "sim.ragdoll_from_frame", kSimulationWindow, "Ragdoll from current frame");
  ImGui::SameLine();
  commandButton(ctx, "sim.bake", kSimulationWindow, "Bake");
  commandButton(ctx, "sim.add_collider", kSimulationWindow, "Add collision capsule on the active joint");
  ImGui::Separator();
  const SimulationSettings& sim = state.doc.scene().simulation;
  if (sim.empty()) ImGui::TextWrapped("Nothing is dynamic yet: select a chain's first joint (a tail) and make it dynamic.");
  for (int i = 0; i < static_cast<int>(sim.springChains.size()); ++i) chainSection(state, i);
  // A section may have removed one: read the count again.
  for (int i = 0; i < static_cast<int>(state.doc.scene().simulation.ragdolls.size()); ++i) ragdollSection(state, i);
  if (state.lastBake) {
    ImGui::TextDisabled("Last bake");
    for (const SimulatedPart& p : state.lastBake->parts)
      ImGui::Text("%s '%s': frames %lld-%lld, %lld steps, limit excess %.2f deg", p.kind.c_str(), p.name.c_str(), p.firstFrame,
                  p.lastFrame, p.steps, p.largestLimitExcess / 0.01745329252);
    ImGui::Text("keys %d -> %d", state.lastBake->keysBefore, state.lastBake->keysAfter);
    recordItem(std::string(kSimulationWindow) + "/Last bake");
  }
  ImGui::End();
}

void drawStiffSpringsWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.stiffSpringsWindowOpen) return;
  placeWindow(state, 560.0f, 520.0f);
  if (!ImGui::Begin(kTeachWindow, &state.stiffSpringsWindowOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow(kTeachWindow);
  ImGui::TextWrapped("Ten 1 kg masses on 2,500 N/m springs, each with a dashpot giving the highest mode the damping "
                     "ratio zeta; the last mass starts pulled down 1 cm. Explicit Euler is stable below dt = 2 zeta / "
                     "w_max, symplectic Euler and Verlet below about 2 / w_max, backward Euler at every step.");
  ImGui::SetNextItemWidth(scaled(state, 200.0f));
  ImGui::SliderFloat("dt / explicit Euler's limit", &state.stiffSpringsStep, 0.1f, 12.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  recordItem(std::string(kTeachWindow) + "/Step");
  ImGui::SetNextItemWidth(scaled(state, 200.0f));
  ImGui::SliderFloat("zeta", &state.stiffSpringsZeta, 0.01f, 1.0f, "%.2f");
  recordItem(std::string(kTeachWindow) + "/Zeta");
  SpringChain chain{10, 1.0, 2500.0, 0.0};
  chain.beta = betaForHighestModeRatio(chain, state.stiffSpringsZeta);
  const double explicitLimit = chainStabilityLimit(chain, Integrator::ExplicitEuler);
  const double h = state.stiffSpringsStep * explicitLimit;
  ImGui::Text("dt = %.3g ms (explicit Euler's limit %.3g ms)", h * 1e3, explicitLimit * 1e3);
  // One chart, the four schemes on the same axes (as docs/teaching.md's figure): energy over
  // the starting energy, log scale from 10^-6 to 10^3 (a run stops once it passes 10^3).
  struct Run {
    Integrator scheme;
    ImU32 color;
    std::vector<ImVec2> points;  // (seconds, log10 ratio)
    bool blew = false;
  };
  std::vector<Run> runs = {{Integrator::ExplicitEuler, IM_COL32(235, 80, 70, 255), {}, false},
                           {Integrator::SymplecticEuler, IM_COL32(90, 170, 250, 255), {}, false},
                           {Integrator::Verlet, IM_COL32(120, 215, 110, 255), {}, false},
                           {Integrator::ImplicitEuler, IM_COL32(245, 200, 80, 255), {}, false}};
  constexpr double kSeconds = 5.0;
  constexpr float kLogMin = -6.0f, kLogMax = 3.0f;
  for (Run& run : runs) {
    ChainState st;
    st.x.assign(chain.masses, 0.0);
    st.v.assign(chain.masses, 0.0);
    st.x.back() = 0.01;
    const double e0 = chainEnergy(chain, st);
    const int steps = std::min(20000, static_cast<int>(std::ceil(kSeconds / h)));
    const int every = std::max(1, steps / 400);
    run.points.push_back(ImVec2(0.0f, 0.0f));
    for (int i = 0; i < steps && !run.blew; ++i) {
      stepChain(chain, run.scheme, h, st);
      const double r = chainEnergy(chain, st) / e0;
      run.blew = !(r < 1e3);
      if (i % every == 0 || run.blew)
        run.points.push_back(ImVec2(static_cast<float>((i + 1) * h),
                                    static_cast<float>(std::log10(std::max(std::min(r, 1e3), 1e-6)))));
    }
  }
  ImGui::Text("Energy / starting energy over %.0f s (log scale)", kSeconds);
  const float labelWidth = ImGui::CalcTextSize("1e-6").x + scaled(state, 6.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, scaled(state, 200.0f)), scaled(state, 220.0f));
  ImGui::InvisibleButton("##energy", size);
  recordItem(std::string(kTeachWindow) + "/Energy");
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 lo(origin.x + labelWidth, origin.y + 4.0f), hi(origin.x + size.x - 4.0f, origin.y + size.y - ImGui::GetTextLineHeight() - 6.0f);
  auto toScreen = [&](const ImVec2& p) {
    const float fx = p.x / static_cast<float>(kSeconds), fy = (p.y - kLogMin) / (kLogMax - kLogMin);
    return ImVec2(lo.x + fx * (hi.x - lo.x), hi.y - fy * (hi.y - lo.y));
  };
  draw->AddRectFilled(lo, hi, IM_COL32(30, 36, 48, 255));
  const ImU32 grid = IM_COL32(80, 88, 104, 255), text = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  for (int e = static_cast<int>(kLogMin); e <= static_cast<int>(kLogMax); e += 3) {
    const ImVec2 a = toScreen(ImVec2(0.0f, static_cast<float>(e))), b = toScreen(ImVec2(static_cast<float>(kSeconds), static_cast<float>(e)));
    draw->AddLine(a, b, e == 0 ? IM_COL32(150, 150, 150, 255) : grid);
    char tick[16];
    std::snprintf(tick, sizeof tick, e == 0 ? "1" : "1e%d", e);
    draw->AddText(ImVec2(origin.x, a.y - ImGui::GetTextLineHeight() * 0.5f), text, tick);
  }
  for (int t = 0; t <= static_cast<int>(kSeconds); ++t) {
    const ImVec2 a = toScreen(ImVec2(static_cast<float>(t), kLogMin));
    draw->AddLine(a, toScreen(ImVec2(static_cast<float>(t), kLogMax)), grid);
    char tick[16];
    std::snprintf(tick, sizeof tick, "%d s", t);
    draw->AddText(ImVec2(a.x - ImGui::CalcTextSize(tick).x * 0.5f, hi.y + 3.0f), text, tick);
  }
  for (const Run& run : runs) {
    std::vector<ImVec2> pts;
    pts.reserve(run.points.size());
    for (const ImVec2& p : run.points) pts.push_back(toScreen(p));
    draw->AddPolyline(pts.data(), static_cast<int>(pts.size()), run.color, ImDrawFlags_None, 2.0f);
    if (run.blew) draw->AddCircleFilled(pts.back(), 4.0f, run.color);
  }
  // The legend: each scheme's colour, its stability limit and whether it blew up.
  for (const Run& run : runs) {
    const double limit = chainStabilityLimit(chain, run.scheme);
    char label[160];
    if (std::isinf(limit)) std::snprintf(label, sizeof label, "%s: stable at every step%s", toString(run.scheme), run.blew ? ", BLEW UP" : "");
    else std::snprintf(label, sizeof label, "%s: limit %.3g ms%s", toString(run.scheme), limit * 1e3, run.blew ? ", BLEW UP" : "");
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float line = ImGui::GetTextLineHeight();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + line * 0.35f), ImVec2(p.x + line * 1.2f, p.y + line * 0.65f), run.color);
    ImGui::Dummy(ImVec2(line * 1.4f, line));
    ImGui::SameLine();
    ImGui::TextUnformatted(label);
    recordItem(std::string(kTeachWindow) + "/" + toString(run.scheme));
  }
  ImGui::End();
}

}  // namespace kinema
