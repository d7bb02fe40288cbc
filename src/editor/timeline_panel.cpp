// The timeline: play/pause and a frame slider for files with motion (Blender's timeline,
// reduced to playback; keyframe editing is the animating issue's).
#include <imgui.h>

#include <cmath>

#include "editor/editor_panels.h"
#include "editor/panel_layout.h"

namespace kinema {

void drawTimelinePanel(EditorState& state) {
  if (!state.hasMotion()) return;
  const PanelRect r = timelineRect(ImGui::GetIO().DisplaySize);
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::Begin("Timeline", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  if (ImGui::Button(state.playing ? "Pause" : "Play")) state.playing = !state.playing;
  ImGui::SameLine();
  ImGui::Checkbox("Loop", &state.loop);
  ImGui::SameLine();
  const long long last = state.frameCount() - 1;
  int frame = static_cast<int>(std::llround(state.time / state.frameTime()));
  ImGui::SetNextItemWidth(-160);
  if (ImGui::SliderInt("##frame", &frame, 0, static_cast<int>(last), "frame %d")) {
    state.time = frame * state.frameTime();
    state.playing = false;
    state.sampleClip = true;
  }
  ImGui::SameLine();
  ImGui::Text("%.2f / %.2f s", state.time, state.duration());
  ImGui::End();
}

void drawViewportHelp(const EditorState& state, float fps) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 8, 8), ImGuiCond_Always, ImVec2(1, 0));
  ImGui::SetNextWindowBgAlpha(0.35f);
  ImGui::Begin("##help", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::Text("%s", state.doc.scene().source.c_str());
  ImGui::TextDisabled("orbit: middle drag / Alt+left   pan: Shift+middle");
  ImGui::TextDisabled("zoom: wheel   frame all: Home / F   select: left click");
  ImGui::TextDisabled("%.0f fps", fps);
  ImGui::End();
}

}  // namespace kinema
