// Simulate > Particle Settings…: the shown particle system's emitter, forces and look,
// edited in place (one undo step per change: a field commits on Enter or when it loses
// focus, a combo or checkbox at once), with the Simulate menu's particle commands as
// buttons and the live counts at the playhead.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "editor/commands/animation_editor_commands.h"
#include "editor/commands/file_commands.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

constexpr const char* kParticlesWindow = "Particles";

// Field edits of one frame, committed together as one undo step.
struct Fields {
  EditorState& state;
  bool changed = false;

  void record(const char* id) { recordItem(std::string(kParticlesWindow) + "/" + id); }
  void number(const char* id, const char* label, float& value, float lo, float hi) {
    ImGui::SetNextItemWidth(scaled(state, 90.0f));
    float v = value;
    ImGui::InputFloat(label, &v, 0.0f, 0.0f, "%.4g");
    record(id);
    if (!ImGui::IsItemDeactivatedAfterEdit() || !std::isfinite(v)) return;
    value = std::clamp(v, lo, hi);
    changed = true;
  }
  void vector(const char* id, const char* label, glm::vec3& value) {
    ImGui::SetNextItemWidth(scaled(state, 200.0f));
    glm::vec3 v = value;
    ImGui::InputFloat3(label, &v.x, "%.4g");
    record(id);
    if (!ImGui::IsItemDeactivatedAfterEdit() || !isFinite(v)) return;
    value = v;
    changed = true;
  }
  void range(const char* id, const char* label, RandomRange& r) {
    ImGui::PushID(id);
    ImGui::TextUnformatted(label);
    number((std::string(id) + " mean").c_str(), "mean", r.mean, 0.0f, 1e9f);
    ImGui::SameLine();
    number((std::string(id) + " spread").c_str(), "spread", r.spread, 0.0f, 1e9f);
    ImGui::SameLine();
    bool normal = r.distribution == RandomDistribution::Normal;
    if (ImGui::Checkbox("normal", &normal)) {
      r.distribution = normal ? RandomDistribution::Normal : RandomDistribution::Uniform;
      changed = true;
    }
    record((std::string(id) + " normal").c_str());
    ImGui::PopID();
  }
};

void systemSection(EditorState& state, int index) {
  ParticleSystemSettings s = state.doc.scene().simulation.particles[index];
  const Skeleton& skeleton = state.doc.skeleton();
  Fields f{state};
  ParticleEmitter& e = s.emitters.front();
  static const char* kinds[] = {"point", "sphere", "mesh surface", "joint"};
  int kind = static_cast<int>(e.shape);
  ImGui::SetNextItemWidth(scaled(state, 140.0f));
  if (ImGui::Combo("emitter", &kind, kinds, 4)) {
    const EmitterShape shape = static_cast<EmitterShape>(kind);
    const bool usable = shape != EmitterShape::MeshSurface ? (shape != EmitterShape::Joint || e.joint >= 0 || state.doc.selection.active() >= 0)
                                                           : !e.surfaceIndices.empty();
    if (usable) {
      if (shape == EmitterShape::Joint && e.joint < 0) e.joint = state.doc.selection.active();
      e.shape = shape;
      f.changed = true;
    } else {
      showEditorError(state, shape == EmitterShape::Joint ? "Select a joint to emit from first"
                                                          : "A mesh surface emitter is made in the .kinema file (surface triangles)");
    }
  }
  f.record("Emitter");
  if (e.shape == EmitterShape::Joint && e.joint >= 0 && e.joint < skeleton.size()) {
    ImGui::SameLine();
    ImGui::Text("on %s", skeleton.names[e.joint].c_str());
    if (state.doc.selection.active() >= 0 && state.doc.selection.active() != e.joint) {
      ImGui::SameLine();
      if (ImGui::SmallButton("use active joint")) e.joint = state.doc.selection.active(), f.changed = true;
      f.record("Use active joint");
    }
  }
  f.vector("Position", e.shape == EmitterShape::Joint ? "offset (joint frame)" : "position", e.position);
  if (e.shape == EmitterShape::Sphere) f.number("Radius", "radius", e.radius, 1e-6f, 1e9f);
  f.vector("Direction", "direction", e.direction);
  if (glm::length(e.direction) < 1e-6f) e.direction = glm::vec3(0, 1, 0);
  f.number("Cone", "cone half-angle (deg)", e.coneDegrees, 0.0f, 180.0f);
  f.range("Rate", "rate (particles/s)", e.rate);
  f.range("Lifetime", "lifetime (s)", e.lifetime);
  f.range("Speed", "speed (units/s)", e.speed);
  ImGui::Separator();
  f.vector("Gravity", "gravity (units/s^2)", s.forces.gravity);
  f.vector("Wind", "wind (units/s)", s.forces.wind);
  f.number("Drag", "drag (1/s)", s.forces.drag, 0.0f, 1e9f);
  if (ImGui::Checkbox("ground", &s.forces.ground)) f.changed = true;
  f.record("Ground");
  ImGui::SameLine();
  f.number("Ground height", "height", s.forces.groundHeight, -1e9f, 1e9f);
  f.number("Restitution", "restitution", s.forces.restitution, 0.0f, 1.0f);
  f.number("Friction", "friction", s.forces.friction, 0.0f, 1.0f);
  ImGui::Separator();
  int style = s.style == ParticleDrawStyle::Points ? 0 : 1;
  static const char* styles[] = {"points (size in pixels)", "quads (size in units)"};
  ImGui::SetNextItemWidth(scaled(state, 180.0f));
  if (ImGui::Combo("draw as", &style, styles, 2)) {
    s.style = style == 0 ? ParticleDrawStyle::Points : ParticleDrawStyle::Quads;
    f.changed = true;
  }
  f.record("Draw as");
  f.number("Size", "size", s.size, 1e-6f, 1e6f);
  ImGui::SetNextItemWidth(scaled(state, 200.0f));
  glm::vec4 colour = s.colour;
  ImGui::ColorEdit4("colour", &colour.x);
  f.record("Colour");
  if (ImGui::IsItemDeactivatedAfterEdit()) s.colour = glm::clamp(colour, glm::vec4(0.0f), glm::vec4(1.0f)), f.changed = true;
  int seed = static_cast<int>(s.seed & 0x7fffffff);
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  ImGui::InputInt("seed", &seed, 0);
  f.record("Seed");
  if (ImGui::IsItemDeactivatedAfterEdit()) s.seed = static_cast<uint64_t>(std::max(seed, 0)), f.changed = true;
  ImGui::SameLine();
  int most = s.maxParticles;
  ImGui::SetNextItemWidth(scaled(state, 90.0f));
  ImGui::InputInt("max particles", &most, 0);
  f.record("Max particles");
  if (ImGui::IsItemDeactivatedAfterEdit()) s.maxParticles = std::clamp(most, 1, 1 << 22), f.changed = true;
  if (f.changed) reportDopeSheetEdit(state, setParticleSystemEdit(state.doc, index, s), "Set particle system " + s.name);
}

}  // namespace

void drawParticlesWindow(CommandContext& ctx) {
  EditorState& state = ctx.state;
  if (!state.particlesWindowOpen) return;
  const PanelRect& v = state.layout.viewport;
  ImGui::SetNextWindowPos(ImVec2(v.x + v.w - scaled(state, 440.0f), v.y + scaled(state, 8.0f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(std::max(std::min(scaled(state, 430.0f), v.w - 16.0f), 240.0f),
                                  std::max(std::min(scaled(state, 560.0f), v.h - 16.0f), 200.0f)),
                           ImGuiCond_Appearing);
  if (!ImGui::Begin(kParticlesWindow, &state.particlesWindowOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow(kParticlesWindow);
  commandButton(ctx, "sim.add_particle_emitter", kParticlesWindow, "Add emitter");
  ImGui::SameLine();
  commandButton(ctx, "sim.live_particles", kParticlesWindow, "Live");
  ImGui::SameLine();
  commandButton(ctx, "sim.remove_particle_system", kParticlesWindow, "Remove");
  const std::vector<ParticleSystemSettings>& systems = state.doc.scene().simulation.particles;
  if (systems.empty()) {
    ImGui::TextDisabled("No particle systems: Simulate > Add Particle Emitter makes one.");
    ImGui::End();
    return;
  }
  state.particleSystem = std::clamp(state.particleSystem, 0, static_cast<int>(systems.size()) - 1);
  ImGui::SetNextItemWidth(scaled(state, 200.0f));
  if (ImGui::BeginCombo("system", systems[state.particleSystem].name.c_str())) {
    for (int i = 0; i < static_cast<int>(systems.size()); ++i)
      if (ImGui::Selectable((systems[i].name + "##" + std::to_string(i)).c_str(), i == state.particleSystem)) state.particleSystem = i;
    ImGui::EndCombo();
  }
  recordItem(std::string(kParticlesWindow) + "/System");
  const LiveParticles& live = state.liveParticles;
  if (live.frame >= 0 && state.particleSystem < static_cast<int>(live.alive.size()))
    ImGui::TextDisabled("frame %lld: %d alive, %llu emitted", live.frame, live.alive[state.particleSystem],
                        static_cast<unsigned long long>(live.emitted[state.particleSystem]));
  if (!systems[state.particleSystem].emitters.empty()) {
    systemSection(state, state.particleSystem);
  } else {
    ImGui::TextDisabled("This system has no emitter (add them in the .kinema file).");
  }
  ImGui::End();
}

}  // namespace kinema
