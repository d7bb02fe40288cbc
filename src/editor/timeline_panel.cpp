// The timeline: play/pause and a frame slider for files with motion (Blender's timeline,
// reduced to what this issue needs).
#include <imgui.h>

#include <cmath>

#include "editor/editor_panels.h"

namespace kinema {

void drawTimelinePanel(EditorState& state) {
  if (!state.hasMotion()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(8, display.y - 72), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(display.x - 16, 64), ImGuiCond_Always);
  ImGui::Begin("Timeline", nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
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
