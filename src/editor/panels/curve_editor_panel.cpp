// The curve editor (Blender's Graph Editor) in the animation editor area under the 3D view:
// channel list with visibility toggles on the left, the curve plot (keys, handles, current
// frame, grid) on the right, a toolbar and a key properties strip above it. The logic is in
// curve_editor.h; this file turns mouse and widgets into its calls, each edit one undo step.
#include "editor/commands/keymap.h"
#include "editor/model/key_codes.h"
#include "editor/panels/command_widgets.h"
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "anim/bezier_handles.h"
#include "anim/sampling.h"
#include "editor/model/curve_editor.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/curve_key_edits.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

constexpr float kChannelListWidth = 190.0f;
constexpr float kKeyRadius = 4.0f, kPickRadius = 7.0f;

ImU32 curveColour(const Channel& ch, int component, bool selectedCurve) {
  static const ImU32 base[4] = {IM_COL32(230, 80, 80, 255), IM_COL32(110, 210, 90, 255), IM_COL32(90, 140, 240, 255),
                                IM_COL32(220, 200, 80, 255)};
  ImU32 c = ch.target == ChannelTarget::Scalar ? IM_COL32(200, 200, 200, 255) : base[std::clamp(component, 0, 3)];
  if (!selectedCurve) c = (c & 0x00FFFFFF) | 0xB0000000;
  return c;
}

// A "nice" grid step (1, 2, 5 x 10^n) giving about `target` lines over `extent`.
float gridStep(float extent, float target) {
  const float raw = extent / std::max(target, 1.0f);
  const float p = std::pow(10.0f, std::floor(std::log10(std::max(raw, 1e-9f))));
  for (float m : {1.0f, 2.0f, 5.0f, 10.0f})
    if (raw <= m * p) return m * p;
  return 10.0f * p;
}

const char* const kInterpolationNames[] = {"Step", "Linear", "Hermite", "Catmull-Rom", "TCB",
                                           "Bezier", "Ease", "Nlerp", "Squad"};
const char* const kHandleNames[] = {"Free", "Aligned", "Vector", "Auto", "Auto Clamped"};
const char* const kEasingNames[] = {"Sine", "Quad", "Cubic", "Quart", "Quint", "Expo", "Circ", "Back", "Bounce", "Elastic"};
const char* const kEasingModeNames[] = {"In", "Out", "In Out"};
const char* const kEulerOrderNames[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};

// After a key edit the working pose shows the edited clip at the current frame (not an undo step).
void reposeAtCurrentFrame(EditorState& state) { poseAtPlayhead(state); }

// Applies `change` to the selected keys' settings as one undo step.
void editSelectedKeys(EditorState& state, const char* label, const std::function<void(KeySettings&)>& change) {
  CurveEditorState& ce = state.curveEditor;
  int skipped = 0;
  const std::string error = editCurveKeySettings(state.doc, state.clip, ce.selected, label, change, &skipped);
  if (!error.empty()) showEditorError(state, error);
  else if (skipped > 0) state.statusMessage = std::to_string(skipped) + " key(s) left alone: the interpolation does not suit their channel";
  reposeAtCurrentFrame(state);
}

void drawGrid(ImDrawList* dl, const CurveView& v, const PlotRect& r, double frameTime) {
  const ImU32 line = IM_COL32(70, 70, 70, 255), text = IM_COL32(160, 160, 160, 255);
  // Time lines in frames (labels are frame numbers, as in Blender).
  const float framesPerSecond = static_cast<float>(1.0 / frameTime);
  const float f0 = v.t0 * framesPerSecond, f1 = v.t1 * framesPerSecond;
  const float fs = std::max(1.0f, gridStep(f1 - f0, r.w / 70.0f));
  char label[32];
  for (float f = std::ceil(f0 / fs) * fs; f <= f1; f += fs) {
    const float x = curveToScreen(v, r, f / framesPerSecond, 0).x;
    dl->AddLine(ImVec2(x, r.y), ImVec2(x, r.y + r.h), line);
    std::snprintf(label, sizeof label, "%.0f", f == 0.0f ? 0.0f : f);  // no "-0"
    dl->AddText(ImVec2(x + 2, r.y + r.h - 14), text, label);
  }
  const float vs = gridStep(v.v1 - v.v0, r.h / 40.0f);
  for (float val = std::ceil(v.v0 / vs) * vs; val <= v.v1; val += vs) {
    const float y = curveToScreen(v, r, 0, val).y;
    dl->AddLine(ImVec2(r.x, y), ImVec2(r.x + r.w, y), line);
    std::snprintf(label, sizeof label, "%.3g", std::abs(val) < vs * 1e-3f ? 0.0f : val);
    dl->AddText(ImVec2(r.x + 2, y - 14), text, label);
  }
}

void keyPropertiesStrip(EditorState& state, const Clip& clip) {
  CurveEditorState& ce = state.curveEditor;
  ImGui::AlignTextToFramePadding();  // the same row height with or without widgets: the plot stays put
  if (ce.selected.empty()) {
    ImGui::TextDisabled("Select keys: click (Shift: add), drag a box (B), A: all; drag keys to move");
    return;
  }
  const CurveKeyRef k = ce.selected.front();
  if (k.channel < 0 || k.channel >= static_cast<int>(clip.channels.size()) ||
      k.key >= clip.channels[k.channel].keyCount()) {
    ce.selected.clear();
    return;
  }
  const Channel& ch = clip.channels[k.channel];
  const KeySettings s = ch.settings(k.key);
  int interpolation = static_cast<int>(s.interpolation);
  ImGui::SetNextItemWidth(100);
  if (namedCombo("##interpolation", "Curve Editor/Interpolation", &interpolation, kInterpolationNames,
                 IM_ARRAYSIZE(kInterpolationNames)))
    editSelectedKeys(state, "Key interpolation", [&](KeySettings& ks) { ks.interpolation = Interpolation(interpolation); });
  if (s.interpolation == Interpolation::TCB) {
    float tcb[3] = {s.tension, s.continuity, s.bias};
    const char* names[3] = {"T##tension", "C##continuity", "B##bias"};
    for (int i = 0; i < 3; ++i) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(70);
      // Dragging a slider is one undo step (a Document drag from press to release).
      const bool slid = ImGui::SliderFloat(names[i], &tcb[i], -1.0f, 1.0f, "%.2f");
      recordFrame(std::string("Curve Editor/") + "TCB"[i], 70);
      if (slid) {
        if (!state.doc.dragging()) state.doc.beginDrag("Key TCB");
        dragCurveKeySettings(state.doc, state.clip, state.curveEditor.selected, [&](KeySettings& ks) {
          (i == 0 ? ks.tension : i == 1 ? ks.continuity : ks.bias) = tcb[i];
        });
        reposeAtCurrentFrame(state);
      }
      if (ImGui::IsItemDeactivated() && state.doc.dragging()) {
        state.doc.commitDrag();
        reposeAtCurrentFrame(state);
      }
    }
  } else if (s.interpolation == Interpolation::Bezier) {
    int left = static_cast<int>(s.leftHandleType), right = static_cast<int>(s.rightHandleType);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(95);
    if (namedCombo("L##lefthandle", "Curve Editor/Left handle", &left, kHandleNames, IM_ARRAYSIZE(kHandleNames)))
      editSelectedKeys(state, "Key handle type", [&](KeySettings& ks) { ks.leftHandleType = HandleType(left); });
    ImGui::SameLine();
    ImGui::SetNextItemWidth(95);
    if (namedCombo("R##righthandle", "Curve Editor/Right handle", &right, kHandleNames, IM_ARRAYSIZE(kHandleNames)))
      editSelectedKeys(state, "Key handle type", [&](KeySettings& ks) { ks.rightHandleType = HandleType(right); });
  } else if (s.interpolation == Interpolation::Ease) {
    int easing = static_cast<int>(s.easing), mode = static_cast<int>(s.easingMode);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80);
    if (namedCombo("##easing", "Curve Editor/Easing", &easing, kEasingNames, IM_ARRAYSIZE(kEasingNames)))
      editSelectedKeys(state, "Key easing", [&](KeySettings& ks) { ks.easing = EasingFunction(easing); });
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    if (namedCombo("##easingmode", "Curve Editor/Easing mode", &mode, kEasingModeNames, IM_ARRAYSIZE(kEasingModeNames)))
      editSelectedKeys(state, "Key easing", [&](KeySettings& ks) { ks.easingMode = EasingMode(mode); });
  }
  // The first selected key's time (frames) and value.
  int frame = static_cast<int>(timelineGrid(state).nearestFrame(ch.times[k.key]));
  ImGui::SameLine();
  ImGui::SetNextItemWidth(60);
  const bool retimed = ImGui::InputInt("##frame", &frame, 0, 0, ImGuiInputTextFlags_EnterReturnsTrue);
  recordItem("Curve Editor/Key frame");
  if (retimed) {
    CurveKeyRef moved;
    const std::string error = setCurveKeyFrame(state.doc, state.clip, k, timelineGrid(state), frame, moved);
    if (!error.empty()) showEditorError(state, error);
    else ce.selected = {moved};
    reposeAtCurrentFrame(state);
  }
  // Angles in degrees (displayUnitScale), as the properties panel shows them.
  float value = keyDisplayValue(ch, k.key, k.component, ce.rotationView, ce.eulerOrder);
  const bool degrees = *displayUnitName(ch, ce.rotationView) != '\0';
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  const bool revalued =
      ImGui::InputFloat("##value", &value, 0, 0, degrees ? "%.2f" : "%.4f", ImGuiInputTextFlags_EnterReturnsTrue);
  recordItem("Curve Editor/Key value");
  if (degrees) {
    ImGui::SameLine(0, 4);
    ImGui::TextDisabled("deg");
  }
  if (revalued) {
    const std::string error = setCurveKeyValue(state.doc, state.clip, k, ce.rotationView, ce.eulerOrder, value);
    if (!error.empty()) showEditorError(state, error);
    reposeAtCurrentFrame(state);
  }
}

}  // namespace

void drawCurveEditorPanel(CommandContext& ctx) {
  EditorState& state = ctx.state;
  const ImGuiIO& io = ImGui::GetIO();
  // Shift+F6 (view.curve_editor) opens it; Home over it (curves.frame_all) fits.
  if (state.animationEditor != AnimationEditorKind::CurveEditor) return;
  CurveEditorState& ce = state.curveEditor;
  const PanelRect r = state.layout.animationEditor;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::Begin("Curve Editor", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                                            ImGuiWindowFlags_NoScrollWithMouse);
  recordWindow("Curve Editor");
  if (!state.hasMotion()) {
    ImGui::TextDisabled("Curve editor: the scene has no animation (key a pose first)");
    ImGui::End();
    return;
  }
  const Clip& clip = state.doc.scene().clips[state.clip];
  const Skeleton& skeleton = state.doc.skeleton();

  // The curves of the selected joints' channels.
  const std::vector<ShownCurve> curves = shownCurves(clip, state.doc.selection, ce);
  const std::vector<int> channels = shownChannels(clip, state.doc.selection);
  // Drop selected keys that no longer exist (undo, other edits) or are not shown.
  ce.selected.erase(std::remove_if(ce.selected.begin(), ce.selected.end(),
                                   [&](const CurveKeyRef& k) {
                                     return std::find(channels.begin(), channels.end(), k.channel) == channels.end() ||
                                            k.key >= clip.channels[k.channel].keyCount() ||
                                            k.component >= curveCount(clip.channels[k.channel], ce.rotationView);
                                   }),
                    ce.selected.end());
  if (static_cast<int>(curves.size()) != ce.lastChannelCount) ce.fitPending = true, ce.lastChannelCount = int(curves.size());
  auto fit = [&] {
    std::vector<CurvePoints> visible;
    for (const ShownCurve& s : curves)
      if (!ce.isHidden(s.ref)) visible.push_back(s.points);
    ce.view = fitView(visible, ce.normalized);
    ce.fitPending = false;
  };
  auto display = [&](const ShownCurve& s, float v) { return ce.normalized ? normalizeValue(s.range, v) : v; };

  // Left: the channel list (a checkbox per curve).
  ImGui::BeginChild("##curve_channels", ImVec2(kChannelListWidth, 0), true);
  if (curves.empty()) ImGui::TextDisabled("Select joints to see their curves");
  for (const ShownCurve& s : curves) {
    const Channel& ch = clip.channels[s.ref.channel];
    bool visible = !ce.isHidden(s.ref);
    ImGui::PushStyleColor(ImGuiCol_Text, curveColour(ch, s.ref.component, true));
    const std::string label = curveLabel(skeleton, ch, s.ref.component, ce.rotationView, ce.eulerOrder);
    if (ImGui::Checkbox(label.c_str(), &visible)) ce.toggleHidden(s.ref);
    recordItem("Curve Editor/Channel/" + label);
    ImGui::PopStyleColor();
  }
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginGroup();
  // Toolbar.
  const std::string fitKey = ctx.keymap ? ctx.keymap->shortcut("curves.frame_all") : std::string();
  commandButton(ctx, "curves.frame_all", "Curve Editor", fitKey.empty() ? "Fit" : ("Fit (" + fitKey + ")").c_str());
  // Add Modifier (also Animation > Add Modifier): on the selected keys' channels, else the shown ones.
  for (const char* kind : {"noise", "cycles", "wave"}) {
    ImGui::SameLine();
    const std::string shown = std::string("+") + kind;
    commandButton(ctx, std::string("curves.add_") + kind + "_modifier", "Curve Editor", shown.c_str());
  }
  ImGui::SameLine();
  if (ImGui::Checkbox("Normalize", &ce.normalized)) ce.fitPending = true;
  recordItem("Curve Editor/Normalize");
  ImGui::SameLine();
  const bool switchView = ImGui::Button(ce.rotationView == RotationView::Euler ? "Rotation: Euler" : "Rotation: Quaternion");
  recordItem("Curve Editor/Rotation view");
  if (switchView) {
    ce.rotationView = ce.rotationView == RotationView::Euler ? RotationView::Quaternion : RotationView::Euler;
    ce.selected.clear();
    ce.fitPending = true;
  }
  if (ce.rotationView == RotationView::Euler) {
    int order = static_cast<int>(ce.eulerOrder);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(60);
    if (namedCombo("##eulerorder", "Curve Editor/Euler order", &order, kEulerOrderNames, IM_ARRAYSIZE(kEulerOrderNames))) {
      ce.eulerOrder = EulerOrder(order);
      ce.fitPending = true;
    }
  }
  keyPropertiesStrip(state, clip);

  // The plot.
  const ImVec2 cursor = ImGui::GetCursorScreenPos(), avail = ImGui::GetContentRegionAvail();
  const PlotRect plot{cursor.x, cursor.y, std::max(avail.x, 10.0f), std::max(avail.y, 10.0f)};
  ce.plot = plot;
  ImGui::InvisibleButton("##curve_plot", ImVec2(plot.w, plot.h),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle);
  recordItem("Curve Editor/Plot");
  const bool hovered = ImGui::IsItemHovered();
  if (ce.fitPending) fit();
  const CurveView view = ce.view;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(ImVec2(plot.x, plot.y), ImVec2(plot.x + plot.w, plot.y + plot.h), true);
  dl->AddRectFilled(ImVec2(plot.x, plot.y), ImVec2(plot.x + plot.w, plot.y + plot.h), IM_COL32(40, 40, 40, 255));
  drawGrid(dl, view, plot, timelineGrid(state).secondsPerFrame);

  const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
  auto screen = [&](float t, float v) {
    const glm::vec2 p = curveToScreen(view, plot, t, v);
    return ImVec2(p.x, p.y);
  };
  auto curveOf = [&](const CurveKeyRef& k) -> const ShownCurve* {
    for (const ShownCurve& c : curves)
      if (c.ref.channel == k.channel && c.ref.component == k.component) return &c;
    return nullptr;
  };
  // A handle's point in the plot: the key plus its offset, the value scaled in the normalized view.
  auto handlePoint = [&](const ShownCurve& s, const CurveHandle& h) {
    const glm::vec2 key = keyPlotPoint(s, h.key.key, ce.normalized);
    return screen(key.x + h.offset.x, key.y + h.offset.y / displayToValueScale(s.range, ce.normalized));
  };
  // Curves, extended flat before the first and after the last key (constant extrapolation).
  CurveKeyRef keyUnderMouse;
  float bestKey = kPickRadius;
  std::vector<CurveHandle> handles;
  for (const ShownCurve& s : curves) {
    if (ce.isHidden(s.ref) || s.points.times.empty()) continue;
    const Channel& ch = clip.channels[s.ref.channel];
    bool curveSelected = false;
    for (const CurveKeyRef& k : ce.selected) curveSelected = curveSelected || (k.channel == s.ref.channel && k.component == s.ref.component);
    const ImU32 colour = curveColour(ch, s.ref.component, curveSelected);
    std::vector<ImVec2> line;
    line.push_back(screen(view.t0, display(s, s.points.values.front())));
    for (size_t i = 0; i < s.points.times.size(); ++i) line.push_back(screen(s.points.times[i], display(s, s.points.values[i])));
    line.push_back(screen(view.t1, display(s, s.points.values.back())));
    if (line.front().x > line[1].x) line.front() = line[1];
    if (line.back().x < line[line.size() - 2].x) line.back() = line[line.size() - 2];
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), colour, 0, curveSelected ? 2.0f : 1.5f);
    // With modifiers (Blender's Graph Editor): the played curve too, across the view, a point
    // every two pixels; the keyed curve above stays what the keys edit.
    const CurvePoints played = modifiedCurvePoints(ch, s.ref.component, ce.rotationView, ce.eulerOrder, view.t0, view.t1,
                                                   std::max(2, static_cast<int>(plot.w / 2)));
    if (!played.times.empty()) {
      std::vector<ImVec2> modifiedLine;
      for (size_t i = 0; i < played.times.size(); ++i) modifiedLine.push_back(screen(played.times[i], display(s, played.values[i])));
      dl->AddPolyline(modifiedLine.data(), static_cast<int>(modifiedLine.size()), (colour & 0x00FFFFFFu) | 0xB0000000u, 0, 2.5f);
    }
    // Keys closer than a few pixels apart (imported motion, a key per frame) are not drawn
    // unless selected: thousands of circles would cost more than the rest of the frame.
    const size_t keyCount = s.points.keyTimes.size();
    const float span = keyCount > 1 ? screen(s.points.keyTimes.back(), 0).x - screen(s.points.keyTimes.front(), 0).x : 0;
    const bool denseKeys = keyCount > 1 && span / float(keyCount - 1) < 3 * kKeyRadius;
    for (size_t k = 0; k < keyCount; ++k) {
      const CurveKeyRef ref{s.ref.channel, s.ref.component, static_cast<int>(k)};
      const ImVec2 p = screen(s.points.keyTimes[k], display(s, s.points.keyValues[k]));
      const bool sel = ce.isSelected(ref);
      if (p.x < plot.x - kPickRadius || p.x > plot.x + plot.w + kPickRadius) continue;
      if (!denseKeys || sel) {
        dl->AddCircleFilled(p, kKeyRadius, sel ? IM_COL32(255, 190, 50, 255) : IM_COL32(20, 20, 20, 255), 8);
        dl->AddCircle(p, kKeyRadius, sel ? IM_COL32(255, 255, 255, 255) : colour, 8);
      }
      const float d = glm::length(glm::vec2(p.x, p.y) - mouse);
      if (d < bestKey) bestKey = d, keyUnderMouse = ref;
      if (sel)
        for (const CurveHandle& h : curveHandles(ch, ref, ce.rotationView, ce.eulerOrder)) {
          const ImVec2 hp = handlePoint(s, h);
          dl->AddLine(p, hp, IM_COL32(200, 200, 200, 200));
          if (h.hermite) dl->AddRectFilled(ImVec2(hp.x - 3, hp.y - 3), ImVec2(hp.x + 3, hp.y + 3), IM_COL32(230, 230, 230, 255));
          else dl->AddCircleFilled(hp, 3.5f, IM_COL32(230, 230, 230, 255));
          handles.push_back(h);
        }
    }
  }
  // The current frame.
  const float nowX = screen(static_cast<float>(state.time), 0).x;
  dl->AddLine(ImVec2(nowX, plot.y), ImVec2(nowX, plot.y + plot.h), IM_COL32(80, 140, 255, 255), 2.0f);
  // The box being dragged (B, or a drag from empty space).
  if (ce.drag == CurveEditorState::Drag::Box) {
    const glm::vec2 lo = glm::min(ce.dragStart, mouse), hi = glm::max(ce.dragStart, mouse);
    dl->AddRectFilled(ImVec2(lo.x, lo.y), ImVec2(hi.x, hi.y), IM_COL32(255, 255, 255, 30));
    dl->AddRect(ImVec2(lo.x, lo.y), ImVec2(hi.x, hi.y), IM_COL32(230, 230, 230, 200));
  } else if (ce.boxArmed && hovered) {  // B: a crosshair until the press
    dl->AddLine(ImVec2(mouse.x, plot.y), ImVec2(mouse.x, plot.y + plot.h), IM_COL32(230, 230, 230, 120));
    dl->AddLine(ImVec2(plot.x, mouse.y), ImVec2(plot.x + plot.w, mouse.y), IM_COL32(230, 230, 230, 120));
  }
  dl->PopClipRect();

  // Handle under the mouse (handles win over keys: they sit on top).
  const CurveHandle* handleUnderMouse = nullptr;
  float bestHandle = kPickRadius;
  for (const CurveHandle& h : handles) {
    const ShownCurve* s = curveOf(h.key);
    if (!s) continue;
    const ImVec2 hp = handlePoint(*s, h);
    const float d = glm::length(glm::vec2(hp.x, hp.y) - mouse);
    if (d < bestHandle) bestHandle = d, handleUnderMouse = &h;
  }

  const int clipIndex = state.clip;
  // Mouse: press on a handle / key starts a drag, on empty space a box (a click without
  // moving clears the selection); after B any press starts a box.
  if (hovered && ce.drag == CurveEditorState::Drag::None && !state.doc.dragging()) {
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      if (ce.boxArmed || (!handleUnderMouse && keyUnderMouse.key < 0)) {
        ce.drag = CurveEditorState::Drag::Box;
        ce.dragStart = mouse;
        ce.boxExtend = io.KeyShift;
      } else if (handleUnderMouse) {
        ce.drag = CurveEditorState::Drag::Handle;
        ce.dragHandleKey = handleUnderMouse->key;
        ce.dragHandleRight = handleUnderMouse->right;
        ce.dragHandleHermite = handleUnderMouse->hermite;
        ce.dragHandleStart = handleUnderMouse->offset;
        ce.dragStart = mouse;
      } else {
        if (io.KeyShift) {
          if (ce.isSelected(keyUnderMouse)) ce.selected.erase(std::find(ce.selected.begin(), ce.selected.end(), keyUnderMouse));
          else ce.selected.push_back(keyUnderMouse);
        } else if (!ce.isSelected(keyUnderMouse)) {
          ce.selected = {keyUnderMouse};
        }
        if (ce.isSelected(keyUnderMouse)) {
          ce.drag = CurveEditorState::Drag::Keys;
          ce.dragStart = mouse;
        }
      }
      ce.boxArmed = false;
    } else if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) {
      ce.drag = CurveEditorState::Drag::Pan;
      ce.dragStart = mouse;
    }
    if (io.MouseWheel != 0.0f) {
      const float factor = std::pow(1.15f, io.MouseWheel);
      // Ctrl+wheel zooms time only, Shift+wheel values only.
      zoomView(ce.view, plot, mouse, factor, !io.KeyShift, !io.KeyCtrl);
    }
  }
  // B waits for a press: Esc or a right click drops it, as in Blender.
  if (ce.boxArmed && (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsKeyPressed(keys::ESCAPE, false)))
    ce.boxArmed = false;
  if (ce.drag == CurveEditorState::Drag::Pan) {
    panView(ce.view, plot, glm::vec2(io.MouseDelta.x, io.MouseDelta.y));
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Middle)) ce.drag = CurveEditorState::Drag::None;
  }
  if (ce.drag == CurveEditorState::Drag::Box) {
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsKeyPressed(keys::ESCAPE, false)) {
      ce.drag = CurveEditorState::Drag::None;  // cancelled: the selection stays
    } else if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      ce.drag = CurveEditorState::Drag::None;
      // A click without a drag on empty space clears the selection (Shift keeps it).
      if (glm::length(mouse - ce.dragStart) < 3.0f) {
        if (!ce.boxExtend) ce.selected.clear();
      } else {
        applyBoxSelection(ce, keysInBox(curves, ce, ce.dragStart, mouse), ce.boxExtend);
      }
    }
  }
  if (ce.drag == CurveEditorState::Drag::Keys || ce.drag == CurveEditorState::Drag::Handle) {
    const glm::vec2 delta = mouse - ce.dragStart;
    const bool moved = glm::length(delta) >= 3.0f;
    if (moved && !state.doc.dragging()) {
      const std::string error = state.doc.beginDrag(ce.drag == CurveEditorState::Drag::Keys ? "Move keys" : "Move handle");
      if (!error.empty()) showEditorError(state, error), ce.drag = CurveEditorState::Drag::None;
      // The keys' display values and ranges at the start (the drag restarts from them).
      ce.dragRanges.clear();
      for (const CurveKeyRef& k : ce.selected) {
        const ShownCurve* s = curveOf(k);
        ce.dragRanges.push_back(s ? s->range : ValueRange{});
      }
      ce.dragStartValues.clear();
      for (const CurveKeyRef& k : ce.selected) {
        const ShownCurve* s = curveOf(k);
        ce.dragStartValues.push_back(s ? s->points.keyValues[k.key] : 0.0f);
      }
      ce.dragStartKeys = ce.selected;
    }
    if (state.doc.dragging()) {
      const glm::vec2 d = handleDeltaFromPixels(view, plot, delta);
      if (ce.drag == CurveEditorState::Drag::Keys) {
        std::vector<float> scales;
        for (const ValueRange& range : ce.dragRanges) scales.push_back(displayToValueScale(range, ce.normalized));
        std::vector<CurveKeyRef> moved;
        dragCurveKeys(state.doc, clipIndex, timelineGrid(state), ce.dragStartKeys, ce.dragStartValues, scales, d.x, d.y,
                      ce.rotationView, ce.eulerOrder, moved);
        if (!moved.empty()) ce.selected = moved;
      } else {
        CurveHandle h;
        h.key = ce.dragHandleKey;
        h.right = ce.dragHandleRight;
        h.hermite = ce.dragHandleHermite;
        const ShownCurve* s = curveOf(h.key);
        // The plot's offset (normalized in that view) back to display units.
        const float scale = s ? displayToValueScale(s->range, ce.normalized) : 1.0f;
        const glm::vec2 offset(ce.dragHandleStart.x + d.x, ce.dragHandleStart.y + d.y * scale);
        const float fps = static_cast<float>(timelineGrid(state).framesPerSecond());
        dragCurveKeyHandle(state.doc, clipIndex, h, offset, ce.rotationView, ce.eulerOrder, fps);
      }
    }
    // Esc or a right click cancels (back to the start, nothing recorded), as in the 3D view.
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsKeyPressed(keys::ESCAPE, false)) {
      if (state.doc.dragging()) {
        state.doc.cancelDrag();
        if (ce.drag == CurveEditorState::Drag::Keys) ce.selected = ce.dragStartKeys;
      }
      ce.drag = CurveEditorState::Drag::None;
    } else if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      if (state.doc.dragging()) state.doc.commitDrag();
      ce.drag = CurveEditorState::Drag::None;
      reposeAtCurrentFrame(state);
    }
  }
  ImGui::EndGroup();
  ImGui::End();
}

}  // namespace kinema
