// The foot contact strip over the timeline (contact_lanes.h): a lane per foot with a bar per
// contact of the edited clip. Click a bar to select it (Animation > Foot Contacts > Delete
// deletes it); drag its start or end to change its frames, its middle to move it; drag on an
// empty lane to draw a new one. Each drag is one undo step at release; Esc or a right click
// cancels it. The editing is the model's (foot_contact_edits.h); this file draws and forwards.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/contact_lanes.h"

namespace kinema {

namespace {

const ImU32 kLaneBackground = IM_COL32(34, 34, 34, 255);
const ImU32 kLaneRange = IM_COL32(48, 48, 48, 255);
const ImU32 kLaneText = IM_COL32(150, 150, 150, 255);
const ImU32 kBarColor[2] = {IM_COL32(66, 135, 200, 255), IM_COL32(86, 170, 95, 255)};  // left blue, right green
const ImU32 kBarSelected = IM_COL32(255, 255, 255, 255);
const ImU32 kHandleColor = IM_COL32(20, 20, 20, 200);

void endGesture(EditorState& state, bool commit) {
  if (commit) state.contactDrag.commit(state.doc);
  else state.contactDrag.cancel(state.doc);
  state.contactNewArmed = false;
}

}  // namespace

void drawContactLanesPanel(CommandContext& ctx) {
  EditorState& state = ctx.state;
  const PanelRect r = state.layout.contactLanes;
  if (!state.bottomPanels().contactLanes || r.h < 2.0f || !state.hasMotion()) {
    if (state.contactDrag.active()) endGesture(state, false);
    return;
  }
  const Clip& clip = state.doc.scene().clips[state.clip];
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("Contacts", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  recordWindow("Contacts");
  const ContactLanes lanes = contactLanes(state, r);
  const TimelineRuler& f = lanes.frames;
  ImGui::SetCursorScreenPos(ImVec2(f.x, lanes.y));
  ImGui::InvisibleButton("##contacts", ImVec2(f.w, 2.0f * lanes.laneHeight),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  recordItem("Contacts/Strip");
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const float handle = scaled(state, 5.0f);
  const ContactHit hover = hitContactLanes(lanes, clip, glm::vec2(mouse.x, mouse.y), handle);
  if (ImGui::IsItemHovered() && hover.index >= 0 && hover.part != ContactDragPart::Whole)
    ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);

  // Press: select the bar under the mouse and start dragging its part; on an empty lane arm
  // a new contact that starts once the mouse moves a frame (a plain click deselects).
  if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && hover.lane && !state.playing) {
    if (hover.index >= 0) {
      state.contactSelection = FootContactSelection{hover.foot, hover.index};
      const std::string error =
          state.contactDrag.begin(state.doc, state.clip, hover.foot, hover.index, hover.part, hover.frame);
      if (!error.empty()) state.statusMessage = error;
    } else {
      state.contactSelection.index = -1;
      state.contactNewArmed = true;
      state.contactNewFoot = hover.foot;
      state.contactNewFrame = hover.frame;
    }
  }
  const bool held = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  const long long frameNow = f.frameAtX(mouse.x);
  if (state.contactNewArmed && held && frameNow != state.contactNewFrame) {
    state.contactNewArmed = false;
    const std::string error = state.contactDrag.begin(state.doc, state.clip, state.contactNewFoot, -1,
                                                      ContactDragPart::New, state.contactNewFrame);
    if (!error.empty()) state.statusMessage = error;
  }
  if (state.contactDrag.active()) {
    const bool cancel = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) ||
                        ImGui::IsMouseClicked(ImGuiMouseButton_Right);
    if (cancel) {
      endGesture(state, false);
      state.statusMessage = "Contact edit cancelled";
    } else if (!held) {
      const std::vector<ContactInterval>& list = state.doc.scene().clips[state.clip].contacts.of(state.contactDrag.foot());
      const int index = state.contactDrag.index();
      state.contactSelection = FootContactSelection{state.contactDrag.foot(), index};
      endGesture(state, true);
      if (index >= 0 && index < static_cast<int>(list.size()))
        state.statusMessage = std::string(toString(state.contactSelection.foot)) + " foot contact: frames " +
                              std::to_string(list[index].first) + " - " + std::to_string(list[index].last);
    } else {
      const std::string error = state.contactDrag.update(state.doc, frameNow);
      if (!error.empty()) state.statusMessage = error;
    }
  } else if (!held) {
    state.contactNewArmed = false;
  }

  // Drawing: lanes over the ruler's playback range, bars, the selection, the playhead.
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), kLaneBackground);
  const Clip& shown = state.doc.scene().clips[state.clip];  // after this frame's drag update
  for (int foot = 0; foot < 2; ++foot) {
    const Foot ft = static_cast<Foot>(foot);
    const float top = lanes.laneTop(ft) + 1.0f, bottom = lanes.laneTop(ft) + lanes.laneHeight - 1.0f;
    draw->AddRectFilled(ImVec2(f.xOfFrame(f.first), top), ImVec2(f.xOfFrame(f.last), bottom), kLaneRange);
    draw->AddText(ImVec2(r.x + scaled(state, 3.0f), top + (bottom - top - ImGui::GetFontSize()) * 0.5f), kLaneText,
                  foot == 0 ? "L" : "R");
    const std::vector<ContactInterval>& list = shown.contacts.of(ft);
    for (int i = 0; i < static_cast<int>(list.size()); ++i) {
      const ContactInterval& c = list[i];
      if (c.last < f.first || c.first > f.last) continue;
      const float x0 = std::max(lanes.barLeft(c), f.x), x1 = std::min(lanes.barRight(c), f.x + f.w);
      draw->AddRectFilled(ImVec2(x0, top + 1), ImVec2(x1, bottom - 1), kBarColor[foot], 2.0f);
      const float hw = std::min(scaled(state, 2.0f), (x1 - x0) * 0.25f);
      draw->AddRectFilled(ImVec2(x0, top + 1), ImVec2(x0 + hw, bottom - 1), kHandleColor);
      draw->AddRectFilled(ImVec2(x1 - hw, top + 1), ImVec2(x1, bottom - 1), kHandleColor);
      const bool selected = state.contactSelection.foot == ft && state.contactSelection.index == i;
      if (selected) draw->AddRect(ImVec2(x0, top), ImVec2(x1, bottom), kBarSelected, 2.0f, 0, 1.5f);
      state.items.record("Contacts/" + std::string(toString(ft)) + "/" + std::to_string(i), glm::vec2(x0, top),
                         glm::vec2(x1, bottom));
    }
  }
  const long long frame = currentFrame(state);
  if (frame >= f.first && frame <= f.last) {
    const float x = f.xOfFrame(frame);
    draw->AddLine(ImVec2(x, r.y), ImVec2(x, r.y + r.h), kPlayheadColor, 2.0f);
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace kinema
