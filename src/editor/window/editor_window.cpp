#include "editor/window/editor_window.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <thread>

#include "editor/commands/editor_input.h"
#include "editor/commands/keymap.h"
#include "editor/model/key_codes.h"
#include "editor/panels/editor_panels.h"
#include "editor/window/back_buffer_probe.h"
#include "editor/window/imgui_backends.h"
#include "editor/window/imgui_damage.h"
#include "editor/window/imgui_input_feed.h"
#include "editor/panels/panel_layout.h"
#include "editor/window/state_dump.h"
#include "editor/window/ui_style.h"
#include "editor/window/window_present.h"
#include "editor/viewport/particle_display.h"
#include "editor/viewport/viewport_overlay.h"
#include "editor/viewport/crowd_display.h"
#include "editor/viewport/animation_display.h"
#include "editor/viewport/viewport_controller.h"
#include "editor/viewport/viewport_tools.h"
#include "io/atomic_write.h"
#include "io/image.h"
#include "render/loose_joints.h"
#include "render/mesh_renderer.h"
#include "render/rect_clear.h"
#include "render/skeleton_renderer.h"
#include "render/frame_pass_timer.h"
#include "render/frame_signature.h"
#include "render/gl_context.h"
#include "render/scene_damage.h"
#include "render/viewport_target.h"
#include "render/skeleton_view.h"
#include "evaluation/scene_deformation.h"

namespace kinema {

// model/key_codes.h copies GLFW's key numbering so the window-free layers need no GLFW header;
// live events pass GLFW's codes straight through, so the two must agree.
static_assert(keys::A == GLFW_KEY_A && keys::Z == GLFW_KEY_Z && keys::Num0 == GLFW_KEY_0 && keys::SPACE == GLFW_KEY_SPACE,
              "key_codes.h: letters, digits and space");
static_assert(keys::ESCAPE == GLFW_KEY_ESCAPE && keys::HOME == GLFW_KEY_HOME && keys::F1 == GLFW_KEY_F1 &&
                  keys::F25 == GLFW_KEY_F25 && keys::KP_0 == GLFW_KEY_KP_0 && keys::KP_ENTER == GLFW_KEY_KP_ENTER &&
                  keys::LEFT_SHIFT == GLFW_KEY_LEFT_SHIFT && keys::MENU == GLFW_KEY_MENU,
              "key_codes.h: named keys, function keys, keypad, modifiers");

namespace {

// The window's background, behind the panels and in the 3D view (drawn there without a clear of its own).
constexpr glm::vec4 kWindowGrey(0.235f, 0.235f, 0.235f, 1.0f);

// What the 3D view's area of the window shows: the canvas of changed-only redraws keeps it
// from one frame to the next, and a different content redraws the whole area.
struct ViewContent {
  enum class Shows { Nothing, KeptPicture, Scene };  // Nothing: the compare mode's grey
  Shows shows = Shows::Nothing;
  PixelRect rect;          // framebuffer pixels, rows from the bottom
  uint64_t signature = 0;  // KeptPicture: frameSignature of the kept picture
  int samples = 0;         // KeptPicture: its samples per pixel
  bool operator==(const ViewContent& o) const {
    if (shows != o.shows) return false;
    if (shows == Shows::Nothing) return true;
    return rect == o.rect && (shows != Shows::KeptPicture || (signature == o.signature && samples == o.samples));
  }
  bool operator!=(const ViewContent& o) const { return !(*this == o); }
};

// GLFW reports errors through a callback; keep the last one for the one-line message.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}
void onGlfwError(int code, const char* description) {
  lastGlfwError() = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

GLFWwindow* createWindow(const WindowPlacement& place, const std::string& title, int samples) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once placed
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, samples);
  // Depth for the 3D view drawn straight into the window, no stencil: nothing uses one, and
  // with one a depth clear must keep the stencil bits, which makes llvmpipe write the
  // buffer pixel by pixel (2.3 ms a frame at 1280x800) instead of filling it.
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  return glfwCreateWindow(place.width, place.height, title.c_str(), nullptr, nullptr);
}

// The primary monitor's work area (without panels and docks); width 0 when unknown.
ScreenArea primaryWorkArea() {
  ScreenArea a;
  if (GLFWmonitor* m = glfwGetPrimaryMonitor()) glfwGetMonitorWorkarea(m, &a.x, &a.y, &a.width, &a.height);
  return a;
}

// Text and widget scale: the preference times the monitor's factor (HiDPI, ui_style.h).
float effectiveUiScale(GLFWwindow* window, const EditorState& state, float framebufferRatio) {
  float cx = 1.0f, cy = 1.0f;
  glfwGetWindowContentScale(window, &cx, &cy);
  return state.preferences.uiScale * monitorUiFactor(cx, framebufferRatio);
}

// Live GLFW callbacks only queue events; the frame loop hands them to the same handler as
// replayed ones. The queue lives in the window's user pointer.
struct LiveInput {
  std::deque<InputEvent> queue;
  bool ignore = false;   // --script replay: the real pointer and keyboard must not interfere
  bool exposed = false;  // the X server lost the window's pixels: show the whole frame again
};
LiveInput* liveInput(GLFWwindow* w) { return static_cast<LiveInput*>(glfwGetWindowUserPointer(w)); }
void onRefresh(GLFWwindow* w) { liveInput(w)->exposed = true; }
void onCursor(GLFWwindow* w, double x, double y) {
  InputEvent e;
  e.type = InputEventType::MouseMove;
  e.x = static_cast<float>(x);
  e.y = static_cast<float>(y);
  if (!liveInput(w)->ignore) liveInput(w)->queue.push_back(e);
}
void onButton(GLFWwindow* w, int button, int action, int mods) {
  InputEvent e;
  e.type = action == GLFW_PRESS ? InputEventType::ButtonDown : InputEventType::ButtonUp;
  e.button = button;
  e.mods = mods;
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  e.x = static_cast<float>(x);
  e.y = static_cast<float>(y);
  if (!liveInput(w)->ignore) liveInput(w)->queue.push_back(e);
}
void onScroll(GLFWwindow* w, double dx, double dy) {
  InputEvent e;
  e.type = InputEventType::Scroll;
  e.x = static_cast<float>(dx);
  e.y = static_cast<float>(dy);
  if (!liveInput(w)->ignore) liveInput(w)->queue.push_back(e);
}
void onKey(GLFWwindow* w, int key, int, int action, int mods) {
  if (action == GLFW_REPEAT || key < 0) return;
  InputEvent e;
  e.type = action == GLFW_PRESS ? InputEventType::KeyDown : InputEventType::KeyUp;
  e.key = key;
  e.mods = mods;
  if (!liveInput(w)->ignore) liveInput(w)->queue.push_back(e);
}
void onChar(GLFWwindow* w, unsigned int c) {
  InputEvent e;
  e.type = InputEventType::Text;
  if (c < 0x80) {
    e.text = std::string(1, static_cast<char>(c));
  } else if (c < 0x800) {
    e.text = {char(0xC0 | (c >> 6)), char(0x80 | (c & 0x3F))};
  } else if (c < 0x10000) {
    e.text = {char(0xE0 | (c >> 12)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
  } else {
    e.text = {char(0xF0 | (c >> 18)), char(0x80 | ((c >> 12) & 0x3F)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
  }
  if (!liveInput(w)->ignore) liveInput(w)->queue.push_back(e);
}

const char* getClipboard(void* user) { return glfwGetClipboardString(static_cast<GLFWwindow*>(user)); }
void setClipboard(void* user, const char* text) { glfwSetClipboardString(static_cast<GLFWwindow*>(user), text); }

}  // namespace

bool displayAvailable() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

std::string editorWindowTitle(const EditorState& state) {
  return "Kinema - " + documentTitle(state) + (state.doc.dirty() ? "*" : "");
}
namespace {

// Destroys ImGui, the window and GLFW, in that order, when the session ends: the session's
// first member, so the GL objects declared after it go first, while the context lives.
struct WindowOwner {
  GLFWwindow* window = nullptr;
  bool glfw = false, imgui = false;
  ~WindowOwner() {
    if (imgui) {
      imguiBackendsShutdown();
      ImGui::DestroyContext();
    }
    if (window) glfwDestroyWindow(window);
    if (glfw) glfwTerminate();
  }
};

}  // namespace

// Everything the window keeps from one frame to the next.
struct EditorWindow::Session {
  Session(EditorState& state, const EditorWindowOptions& options) : state(state), o(options) {}
  bool setup();
  bool runFrame();
  EditorWindowResult shutdown();

  // Fonts, style and the panels' rectangles for a window of w x h (framebuffer width fw).
  void updateLayout(int w, int h, int fw);
  // The document's meshes to the GPU (again when a file is opened or a bind replaced them).
  std::string uploadMeshes();
  // The joints' bounds, grown by how far the body reaches past them.
  Bounds viewBounds() const;
  void mark(const char* pass) {
    if (timer) timer->mark(pass);
  }

  WindowOwner owner;  // first: destroyed last
  EditorState& state;
  const EditorWindowOptions& o;
  EditorWindowResult result;
  GLFWwindow* window = nullptr;
  LiveInput live;
  std::string title;
  std::vector<std::string> preferenceProblems;
  UiStyle uiStyle;  // fonts and style at the UI scale, rebuilt when it or the theme changes
  std::vector<double> frameMs;
  FramePassTimer passTimer;
  FramePassTimer* timer = nullptr;
  long long frame = 1;
  bool shutDown = false;

  // The objects that hold GL names, made once the context is current (their destructors
  // call GL): the renderers, the 3D view's kept picture and the canvas.
  struct GlObjects {
    SkeletonRenderer renderer;
    // The document's meshes, skinned on the GPU each frame; uploaded again when a file is
    // opened (edits never change meshes).
    MeshRenderer meshes;
    RectClear rectClear;            // the changed-only frames' clears
    ViewportTarget viewportTarget;  // the still 3D view, multisampled, kept while nothing changes
    ViewportTarget canvas;  // the whole window, one sample, where the back buffer does not survive swaps
  };
  std::unique_ptr<GlObjects> gl;
  std::string error;
  std::vector<char> skinJoints;  // bones only between skin joints (skinJointMask)
  glm::vec3 meshReach{0.0f};     // how far the body reaches past the joints (a head above the neck)
  ViewportTools tools;
  Keymap keymap;
  EditorInput input;
  SkeletonDrawList list;            // last frame's drawing: picking casts rays against it
  SkeletonDrawList selectionAlone;  // with the bones hidden: the selected bones (hiddenBonesSelection)
  OverlayDrawList overlay;
  std::optional<uint64_t> drawnSignature;  // frameSignature of the 3D view drawn last frame
  bool viewportTargetFailed = false;
  AnimationDisplay animationDisplay;  // onion-skin ghosts, motion path (kept: the path is cached)
  CrowdDisplay crowdDisplay;          // the crowd's members at the playhead (issue 24)
  // Changed-only redraws (window_redraw.h): the kept window, what its 3D view area and
  // panels show, and the framebuffer this frame draws into (0: the window's own).
  bool changedRedraws = false;
  bool backBufferKept = false;
  // Frames drawn only where they changed, into the kept back buffer, show those parts alone.
  std::optional<WindowPresenter> presenter;
  std::vector<PixelRect> shownRects;  // what this frame drew again, for the presenter
  glm::ivec2 keptSize{-1};  // the back buffer's size when it was last drawn (backBufferKept)
  ImGuiDrawSnapshot imguiSnapshot;
  SceneSnapshot sceneSnapshot;
  ViewContent canvasView;
  GLuint drawFramebuffer = 0;
  int fbw = 0, fbh = 0, ww = 0, wh = 0;
  long long uploadedMeshRevision = 0;  // a bind replaces the meshes
  size_t nextScripted = 0;
  long long lastScriptFrame = 0;
  double previous = 0.0;
};

void EditorWindow::Session::updateLayout(int w, int h, int fw) {
  const float ratio = w > 0 ? float(fw) / float(w) : 1.0f;
  const float scale = effectiveUiScale(window, state, ratio);
  uiStyle.update(scale, ratio, state.preferences.theme);
  LayoutMetrics metrics;
  metrics.fontSize = uiStyle.fontSize();
  metrics.scale = scale;
  metrics.framePaddingY = uiStyle.framePaddingY();
  state.layout = computeEditorLayout(float(w), float(h), state.preferences.panels, state.bottomPanels(), metrics);
}

std::string EditorWindow::Session::uploadMeshes() {
  MeshRenderer& meshes = gl->meshes;
  const Scene& scene = state.doc.scene();
  skinJoints = skinJointMask(scene);
  meshReach = glm::vec3(0.0f);
  const std::string failed = meshes.upload(scene);
  if (!failed.empty() || meshes.empty()) return failed;
  // Measured once per upload at the current pose, so framing and the grid take in the
  // body without reading vertices back every frame.
  MeshFrame now;
  now.world = &state.world();
  const Bounds body = meshes.deformedBounds(now), joints = jointBounds(state.world());
  if (!body.empty && !joints.empty)
    meshReach = glm::max(glm::max(joints.min - body.min, body.max - joints.max), glm::vec3(0.0f));
  return {};
}

Bounds EditorWindow::Session::viewBounds() const {
  Bounds b = jointBounds(state.world());
  if (!b.empty) {
    b.add(b.min - meshReach);
    b.add(b.max + meshReach);
  }
  return b;
}

bool EditorWindow::Session::setup() {
  if (!displayAvailable()) {
    result.error = "no display (DISPLAY and WAYLAND_DISPLAY are unset)";
    return false;
  }
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    result.error = "cannot start GLFW: " + lastGlfwError();
    return false;
  }
  owner.glfw = true;
  // Edit > Preferences as saved last; a bad file is reported (below) and the defaults used.
  applyPreferences(state, loadUserPreferences(preferenceProblems));
  if (o.uiScale > 0.0f) state.preferences.uiScale = o.uiScale;
  WindowPlacement place;
  if (o.width > 0 && o.height > 0) {  // --size wins over anything remembered
    place.width = o.width;
    place.height = o.height;
  } else {
    place = initialWindowPlacement(state.preferences.window, primaryWorkArea());
  }
  title = editorWindowTitle(state);
  // One sample per pixel: ImGui antialiases its own shapes, and the 3D view draws its still
  // picture multisampled into a framebuffer of its own (render/viewport_target.h).
  window = owner.window = createWindow(place, title, 0);
  if (!window) {
    result.error = "cannot open an OpenGL 3.3 core window: " + lastGlfwError();
    return false;
  }
  if (place.positioned) glfwSetWindowPos(window, place.x, place.y);
  glfwShowWindow(window);
  glfwMakeContextCurrent(window);
  const int version = gladLoadGL(glfwGetProcAddress);
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
    result.error = "the window's OpenGL is older than 3.3";
    return false;
  }
  result.opened = true;
  glfwSwapInterval(o.replay || o.reportFrameTimes ? 0 : 1);

  live.ignore = o.replay;
  glfwSetWindowUserPointer(window, &live);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetMouseButtonCallback(window, onButton);
  glfwSetScrollCallback(window, onScroll);
  glfwSetKeyCallback(window, onKey);
  glfwSetCharCallback(window, onChar);
  glfwSetWindowRefreshCallback(window, onRefresh);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini dropped in the user's folder
  io.UserData = &state.items;  // where panels record their named widgets (panels/item_names.h)
  io.BackendPlatformName = "kinema_input_events";
  io.SetClipboardTextFn = setClipboard;
  io.GetClipboardTextFn = getClipboard;
  io.ClipboardUserData = window;
  mapImGuiKeys(io);
  imguiBackendsInit(window);
  owner.imgui = true;

  timer = o.reportFramePasses ? &passTimer : nullptr;
  gl = std::make_unique<GlObjects>();
  error = gl->renderer.init();
  if (error.empty()) error = gl->meshes.init();
  if (error.empty()) error = gl->rectClear.init();
  if (!error.empty()) result.error = error;
  // Every key-down ImGui does not want runs the command its keymap binds (editor_input.h);
  // the user's keymap file is read once, its bad lines reported and skipped.
  std::vector<std::string> keymapProblems;
  keymap = loadUserKeymap(editorCommands(), keymapProblems);
  for (const std::string& problem : keymapProblems) {
    std::cerr << "kinema edit: keymap: " << problem << "\n";
    showEditorError(state, "keymap: " + problem);
  }
  for (const std::string& problem : preferenceProblems) {
    std::cerr << "kinema edit: preferences: " << problem << "\n";
    showEditorError(state, "preferences: " + problem);
  }
  changedRedraws = o.redraw == WindowRedraw::Changed || (o.redraw == WindowRedraw::Auto && softwareRasterizer());
  backBufferKept = changedRedraws && backBufferSurvivesSwaps(window);
  presenter.emplace(window, backBufferKept);
  evaluateEditorPose(state);
  glfwGetFramebufferSize(window, &fbw, &fbh);
  if (error.empty()) error = uploadMeshes();
  uploadedMeshRevision = state.doc.meshRevision();
  glfwGetWindowSize(window, &ww, &wh);
  updateLayout(ww, wh, fbw);
  const PanelRect startRect = state.layout.viewport;
  state.camera = defaultCamera(viewBounds(), startRect.w / startRect.h);
  lastScriptFrame = o.script.empty() ? 0 : o.script.back().frame;
  previous = glfwGetTime();
  return true;
}

// One frame: input, playback and the pose, the panels, the 3D view, the picture shown. False
// when no frame follows (this was the last, or the window cannot go on).
bool EditorWindow::Session::runFrame() {
  if (!error.empty() || !result.error.empty() || state.panels.quitApproved) return false;
  ImGuiIO& io = ImGui::GetIO();
  SkeletonRenderer& renderer = gl->renderer;
  MeshRenderer& meshes = gl->meshes;
  RectClear& rectClear = gl->rectClear;
  ViewportTarget& viewportTarget = gl->viewportTarget;
  ViewportTarget& canvas = gl->canvas;
  const auto frameStart = std::chrono::steady_clock::now();
  if (timer) timer->beginFrame();
  glfwPollEvents();
  if (glfwWindowShouldClose(window)) {
    glfwSetWindowShouldClose(window, GLFW_FALSE);
    requestQuit(state);  // asks first when there are unsaved changes
  }
  while (nextScripted < o.script.size() && o.script[nextScripted].frame <= frame)
    live.queue.push_back(o.script[nextScripted++]);
  const double now = glfwGetTime();
  const double dt = o.replay ? 1.0 / 60.0 : now - previous;
  previous = now;
  glfwGetWindowSize(window, &ww, &wh);
  glfwGetFramebufferSize(window, &fbw, &fbh);
  updateLayout(ww, wh, fbw);  // between frames: the font atlas may be rebuilt
  // The 3D view is the free area between the panels (the empty-frame measurement has none).
  const PanelRect vp = o.emptyFrame ? PanelRect{0.0f, 0.0f, float(std::max(ww, 1)), float(std::max(wh, 1))}
                                    : state.layout.viewport;
  state.viewportRect = glm::vec4(vp.x, vp.y, vp.w, vp.h);
  const ViewportView view = ViewportView::of(state.camera, glm::vec2(vp.w, vp.h), glm::vec2(vp.x, vp.y));

  // What commands run on this frame: from the keys below, the menus and the panels.
  CommandContext commands(state);
  commands.tools = &tools;
  commands.view = view;
  commands.keymap = &keymap;
  commands.mouse = input.held().mouse;
  // Input: ImGui gets every event; the tools, the compare mode and the keymap's commands
  // get those ImGui does not want (as of the previous frame, which is what the user saw).
  const bool mouseCaptured = io.WantCaptureMouse, keyboardCaptured = io.WantCaptureKeyboard;
  // ImGui needs each tap of a key it reads in a frame of its own while it has the keyboard
  // or a popup open, and while a panel's own gesture polls Esc / Enter through it (the dope
  // sheet's and curve editor's drags, G and B: imgui_input_feed.h); else every event goes at once.
  const bool panelGesture = state.doc.dragging() || state.curveEditor.boxArmed ||
                            state.curveEditor.drag != CurveEditorState::Drag::None ||
                            state.dopeSheet.gesture != DopeSheetState::Gesture::None;
  const bool imguiReadsKeys = keyboardCaptured || panelGesture ||
                              ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
  auto widgetByName = [&](std::deque<InputEvent>& queue) {
    if (queue.front().item.empty()) return true;
    // A scripted event naming a widget: at the widget as it was last drawn.
    InputEvent& e = queue.front();
    const ItemRect* r = state.items.find(e.item);
    if (!r) {
      result.error = "script: frame " + std::to_string(e.frame) + ": no widget named '" + e.item +
                     "' has been drawn (the state dump's \"items\" lists the names)";
      queue.clear();
      return false;
    }
    const glm::vec2 p = r->min + (r->max - r->min) * e.at;
    e.x = p.x;
    e.y = p.y;
    e.item.clear();
    if (e.type != InputEventType::MouseMove) {  // presses happen where the pointer is
      InputEvent move = e;
      move.type = InputEventType::MouseMove;
      queue.push_front(move);
    }
    return true;
  };
  feedFrameInput(
      live.queue, io, imguiReadsKeys,
      [&](const InputEvent& e) { input.handle(commands, e, list, mouseCaptured, keyboardCaptured); }, widgetByName);
  advancePlayback(state, dt);
  evaluateEditorPose(state);
  const Bounds bounds = viewBounds();
  mark("input, tools (IK), pose");

  state.items.frame = frame;
  imguiBackendsNewFrame();
  io.DisplaySize = ImVec2(float(ww), float(wh));
  io.DisplayFramebufferScale = ImVec2(ww > 0 ? float(fbw) / ww : 1.0f, wh > 0 ? float(fbh) / wh : 1.0f);
  io.DeltaTime = static_cast<float>(std::max(dt, 1e-4));
  ImGui::NewFrame();
  if (!o.emptyFrame) drawEditorPanels(commands, io.Framerate);
  ImGui::Render();
  evaluateEditorPose(state);  // the panels may have edited the document
  keepLatticeEditValid(state);  // an undo or a panel may have removed the edited lattice
  mark("ImGui: build the panels");

  const bool scriptDone = o.replay && o.frameCount <= 0 && nextScripted >= o.script.size() && live.queue.empty() &&
                          frame >= lastScriptFrame + 2;
  const bool last = (o.frameCount > 0 && frame >= o.frameCount) || scriptDone || state.panels.quitApproved;
  // What the frame's 3D view area shows, drawn below into the window or the canvas.
  ViewContent view3d;
  bool changedOnly = false;  // drawn into the canvas, only where it changed (window_redraw.h)
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (o.emptyFrame) {
    glViewport(0, 0, fbw, fbh);
    glClearColor(kWindowGrey.r, kWindowGrey.g, kWindowGrey.b, kWindowGrey.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    imguiBackendsRenderDrawData(ImGui::GetDrawData());
    state.windowRedraw = {false, false, 1, static_cast<long long>(fbw) * fbh};
  } else {
    if (meshes.needsUpload(state.doc.scene()) || state.doc.meshRevision() != uploadedMeshRevision) {
      uploadedMeshRevision = state.doc.meshRevision();
      const std::string failed = uploadMeshes();
      if (!failed.empty()) state.statusMessage = failed;
    }
    SkeletonDrawJob job;
    job.parents = &state.doc.skeleton().parents;
    job.world = &state.world();
    job.shownJoints = &skinJoints;
    // Dashed relationship lines to joints that move on their own (Blender's unconnected bones).
    const std::vector<char> loose = looseJoints(state.doc.skeleton(),
                                                state.hasMotion() ? &state.doc.scene().clips[state.clip] : nullptr,
                                                state.doc.pose());
    job.looseJoints = &loose;
    job.run(list);
    MeshDraw meshDraw;
    meshDraw.renderer = &meshes;
    meshDraw.frame.world = &state.world();
    std::vector<std::vector<float>> morphWeights;  // animated blend shapes at the playhead
    if (!meshes.empty()) morphWeights = sampleMorphWeights(state.doc.scene(), state.hasMotion() ? state.clip : -1, state.time);
    meshDraw.frame.morphWeights = &morphWeights;
    // Meshes with an active deformer stack: morphs, skin and deformers on the CPU (the
    // reference path), drawn as they come out.
    std::vector<DeformedPrimitive> cpuDeformed;
    std::vector<DeformerStack> gpuStacks;  // per instance: what the vertex shader deforms
    // On a software rasteriser every mesh is morphed, skinned and deformed here, once
    // (`posed`): drawn from these vertices, and compared with the last frame's to find
    // what changed on screen. Elsewhere the deformer stacks alone (`cpuDeformed`).
    const bool cpuPosed = !meshes.empty() && meshes.drawsPosed() && !state.view.showWeights;
    std::vector<DeformerStack> stacks;
    if (!meshes.empty() && !state.doc.scene().deformers.empty()) {
      stacks = sampleDeformerStacks(state.doc.scene(), state.hasMotion() ? state.clip : -1, state.time);
      previewLatticeMove(state, state.world(), stacks);  // a running G on lattice points
      // With the shader deforming (a hardware GPU), bend / twist / taper stacks run in
      // the vertex shader; the rest, and everything on llvmpipe, on the CPU.
      if (!meshes.cpuDeformation() && !state.view.showWeights) {
        gpuStacks.assign(stacks.size(), DeformerStack());
        for (size_t i = 0; i < stacks.size(); ++i)
          if (axisStackOnGpu(stacks[i])) std::swap(gpuStacks[i], stacks[i]);
      }
      if (anyDeformerActive(stacks) && !cpuPosed) {
        SceneDeformationJob deformJob;
        deformJob.scene = &state.doc.scene();
        deformJob.world = &state.world();
        deformJob.morphWeights = &morphWeights;
        deformJob.deformers = &stacks;
        deformJob.withDeformersOnly = true;
        deformJob.out = &cpuDeformed;
        if (!deformJob.run()) cpuDeformed.clear();
      }
    }
    meshDraw.frame.deformed = &cpuDeformed;
    std::vector<DeformedPrimitive> posed;
    if (cpuPosed) {
      SceneDeformationJob poseJob;
      poseJob.scene = &state.doc.scene();
      poseJob.world = &state.world();
      poseJob.morphWeights = &morphWeights;
      if (anyDeformerActive(stacks)) poseJob.deformers = &stacks;  // sampled, with a running G's preview
      poseJob.out = &posed;
      if (poseJob.run()) meshDraw.frame.posed = &posed;
    }
    meshDraw.frame.gpuDeformers = gpuStacks.empty() ? nullptr : &gpuStacks;
    meshDraw.frame.weightJoint = state.view.showWeights ? state.doc.selection.active() : -1;
    colorSelection(state, list);
    buildCrowdDisplay(state, skinJoints, !meshes.empty(), crowdDisplay);
    // The crowd too; in steps, so a small move keeps the grid and clip planes (camera.h).
    const float sceneRadius = steadySceneRadius(std::max(bounds.radius(), crowdDisplay.radius));
    state.camera.fitClipPlanes(sceneRadius);
    // The viewport in framebuffer pixels (GL counts rows from the bottom); the panels
    // cover the rest, which is cleared to the background behind them.
    const float sx = ww > 0 ? float(fbw) / ww : 1.0f, sy = wh > 0 ? float(fbh) / wh : 1.0f;
    const int vx = int(std::lround(vp.x * sx)), vw = std::max(int(std::lround(vp.w * sx)), 1);
    const int vh = std::max(int(std::lround(vp.h * sy)), 1), vy = std::max(fbh - int(std::lround(vp.y * sy)) - vh, 0);
    mark("scene draw lists");
    buildViewportOverlay(state, ViewportView::of(state.camera, glm::vec2(vw, vh), glm::vec2(vp.x * sx, vp.y * sy)),
                         tools, overlay);
    buildAnimationDisplay(state, skinJoints, animationDisplay, overlay);  // onion skin, motion path
    buildParticleDisplay(state, static_cast<float>(vh), overlay);         // live particles (issue 24)
    // Body ghosts go to the mesh renderer; bones stand in where the meshes failed to upload.
    std::vector<MeshGhost> meshGhosts;
    if (animationDisplay.ghostBodies && meshes.empty())
      animationDisplay.ghostLists = buildGhostDrawLists(state.doc.skeleton().parents, skinJoints, animationDisplay.ghosts,
                                                        animationDisplay.ghostPoses);
    else if (animationDisplay.ghostBodies)
      for (size_t g = 0; g < animationDisplay.ghosts.size(); ++g)
        meshGhosts.push_back({&animationDisplay.ghostPoses[g], &animationDisplay.ghostMorphWeights[g],
                              animationDisplay.ghosts[g].color});
    addCrowdOverlay(state, overlay);
    for (const std::vector<glm::mat4>* member : crowdDisplay.bodies)
      meshGhosts.push_back({member, &crowdDisplay.noMorphs, crowdDisplay.tint});
    std::vector<SkeletonDrawList> ghostLists = animationDisplay.ghostLists;
    ghostLists.insert(ghostLists.end(), crowdDisplay.bones.begin(), crowdDisplay.bones.end());
    FrameDescription description;
    description.skeleton = &list;
    description.overlay = &overlay;
    description.camera = state.camera;
    description.x = vx;
    description.y = vy;
    description.width = vw;
    description.height = vh;
    description.sceneRadius = sceneRadius;
    description.showGrid = state.view.showGrid;
    description.lineScale = state.preferences.lineScale;  // thicker for a projector (Edit > Preferences)
    description.meshes = meshes.empty() ? nullptr : &meshDraw;
    description.ghosts = &ghostLists;
    description.meshGhosts = &meshGhosts;
    description.timer = timer;
    description.bones = !state.view.showBones ? BoneDisplay::None
                        : state.view.xrayBones ? BoneDisplay::XRay
                                               : BoneDisplay::On;
    // Bones hidden: the selected ones alone, x-ray over the body, so the selection shows.
    if (hiddenBonesSelection(state, list, selectionAlone)) {
      description.skeleton = &selectionAlone;
      description.bones = BoneDisplay::XRay;
    }
    // The compare mode draws with ImGui; else the 3D view, antialiased when it holds still
    // (viewport_quality.h) and then kept, to be shown again while nothing in it changes.
    view3d.rect = PixelRect{vx, vy, vx + vw, vy + vh};
    if (state.compare.active) {
      state.viewportRender = {};
    } else {
      const uint64_t signature = frameSignature(description) ^ (uint64_t(uploadedMeshRevision) * 0x9E3779B97F4A7C15ull);
      const bool changed = !drawnSignature || *drawnSignature != signature;
      drawnSignature = signature;
      const ViewportQuality quality = viewportQuality(state, changed, last && !o.screenshotPath.empty());
      std::string failed;
      if (quality == ViewportQuality::Still && !changed && viewportTarget.holds(vw, vh)) {
        view3d.shows = ViewContent::Shows::KeptPicture;
        state.viewportRender = {viewportTarget.samples(), true};
      } else if (quality == ViewportQuality::Still && !viewportTargetFailed &&
                 (failed = viewportTarget.begin(vw, vh, viewportSamples(quality))).empty()) {
        description.x = description.y = 0;  // the target is the view's own size
        renderer.draw(description);
        description.x = vx, description.y = vy;
        viewportTarget.resolve();
        view3d.shows = ViewContent::Shows::KeptPicture;
        state.viewportRender = {viewportTarget.samples(), false};
      } else {  // moving (or no framebuffer of its own): one sample, straight into the window
        if (!failed.empty() && !viewportTargetFailed) {
          viewportTargetFailed = true;
          std::cerr << "kinema edit: " << failed << "; the 3D view is drawn without antialiasing\n";
        }
        viewportTarget.forget();
        view3d.shows = ViewContent::Shows::Scene;
        state.viewportRender = {kMovingViewportSamples, false};
        description.frontFacesOnly = true;  // closed shapes: front faces alone while moving
      }
      view3d.signature = signature;
      view3d.samples = state.viewportRender.samples;
    }
    mark("overlay, onion skin lists");
    // The 3D view (as decided above) and the panels: drawn whole into the window, or only
    // where they changed into the canvas, which is then copied into the window.
    auto drawView = [&](const PixelRect& limit) {  // into the bound framebuffer, within `limit` (empty: all)
      if (view3d.shows == ViewContent::Shows::KeptPicture) {
        viewportTarget.present(view3d.rect.x0, view3d.rect.y0, drawFramebuffer);
      } else if (view3d.shows == ViewContent::Shows::Scene) {
        glBindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer);
        description.clear = false;  // cleared to the same grey just before
        description.limit = limit;
        renderer.draw(description);
      }
      glViewport(0, 0, fbw, fbh);
    };
    // Changed-only: into the window's back buffer where it survives swaps, else into
    // the canvas; `kept`: it holds the previous frame's pixels.
    changedOnly = changedRedraws;
    bool kept = false;
    if (changedOnly && backBufferKept) {
      kept = keptSize == glm::ivec2(fbw, fbh);
      keptSize = glm::ivec2(fbw, fbh);
    } else if (changedOnly) {
      kept = canvas.holds(fbw, fbh);
      if (const std::string failed = canvas.begin(fbw, fbh, 1); !failed.empty()) {
        std::cerr << "kinema edit: " << failed << "; every frame is drawn whole\n";
        changedRedraws = changedOnly = false;
      }
    }
    drawFramebuffer = changedOnly && !backBufferKept ? canvas.boundFramebuffer() : 0;
    if (!changedOnly) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, fbw, fbh);
      glClearColor(kWindowGrey.r, kWindowGrey.g, kWindowGrey.b, kWindowGrey.a);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      mark("clear the window");
      drawView(PixelRect{});
      mark("3D view: resolve, copy to the window");
      imguiBackendsRenderDrawData(ImGui::GetDrawData());
      state.windowRedraw = {false, false, 1, static_cast<long long>(fbw) * fbh};
    } else {
      // Where this frame differs from the canvas: the panels' changed triangles, and in
      // the 3D view what SceneDamageJob finds (all of it when it shows something else now).
      const PixelRect window{0, 0, fbw, fbh};
      const float sx = ww > 0 ? float(fbw) / ww : 1.0f, sy = wh > 0 ? float(fbh) / wh : 1.0f;
      std::vector<PixelRect> damage;
      for (const PixelRect& r : imguiDamage(*ImGui::GetDrawData(), io.Fonts->TexID, imguiSnapshot))
        damage.push_back(PixelRect{int(std::floor(r.x0 * sx)), fbh - int(std::ceil(r.y1 * sy)), int(std::ceil(r.x1 * sx)),
                                   fbh - int(std::floor(r.y0 * sy))});
      if (!kept) damage.assign(1, window);
      if (view3d != canvasView) {
        damage.push_back(canvasView.rect);
        damage.push_back(view3d.rect);
        if (view3d.shows == ViewContent::Shows::Scene) sceneSnapshot.valid = false;
      }
      if (view3d.shows == ViewContent::Shows::Scene) {
        SceneDamageJob damageJob;
        damageJob.frame = &description;
        damageJob.scene = &state.doc.scene();
        damageJob.last = &sceneSnapshot;
        damageJob.run();
        damage.push_back(damageJob.out);
      }
      canvasView = view3d;
      for (PixelRect& r : damage) r = r.intersected(window);
      const std::vector<PixelRect> rects = mergeDamage(std::move(damage), 4);
      shownRects = rects;
      long long pixels = 0;
      std::vector<ImVec4> clips;  // the same rectangles in ImGui's display coordinates
      glBindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer);
      glViewport(0, 0, fbw, fbh);
      rectClear.clear(rects, fbw, fbh, kWindowGrey);
      for (const PixelRect& r : rects) {
        pixels += r.area();
        clips.push_back(ImVec4(r.x0 / sx, (fbh - r.y1) / sy, r.x1 / sx, (fbh - r.y0) / sy));
      }
      mark("clear the window");
      for (const PixelRect& r : rects) {
        const PixelRect inView = r.intersected(view3d.rect);
        if (inView.empty()) continue;
        glEnable(GL_SCISSOR_TEST);
        glScissor(inView.x0, inView.y0, inView.width(), inView.height());
        drawView(inView);
      }
      glDisable(GL_SCISSOR_TEST);
      mark("3D view: resolve, copy to the window");
      if (!rects.empty()) imguiBackendsRenderDrawData(ImGui::GetDrawData(), &clips);
      mark("ImGui: draw the panels");
      state.windowRedraw = {true, backBufferKept, static_cast<int>(rects.size()), pixels};
      if (!backBufferKept) {
        canvas.resolve();  // one sample: nothing to resolve, kept for the next frame
        canvas.present(0, 0, 0);
        mark("copy the canvas to the window");
      }
    }
  }
  if (!changedOnly) mark("ImGui: draw the panels");

  if (last && !o.screenshotPath.empty()) {
    // Read the back buffer before swapping: its contents are undefined afterwards.
    Image shot(fbw, fbh);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, fbw, fbh, GL_RGBA, GL_UNSIGNED_BYTE, shot.rgba.data());
    shot.flipVertically();
    for (size_t i = 3; i < shot.rgba.size(); i += 4) shot.rgba[i] = 255;  // the window is opaque
    result.error = savePng(o.screenshotPath, shot);
  }
  if (live.exposed) {
    presenter->markExposed();
    live.exposed = false;
  }
  // Drawn into the kept back buffer only where it changed: those rectangles shown alone.
  state.windowRedraw.presentedRectangles =
      presenter->present(changedOnly && backBufferKept ? &shownRects : nullptr, fbw, fbh);
  // --max-fps: the rest of the frame's time is slept (events keep queueing meanwhile).
  if (o.maxFps > 0) std::this_thread::sleep_until(frameStart + std::chrono::microseconds(1000000 / o.maxFps));
  if (timer) {
    timer->mark("swap");
    timer->endFrame();
  }
  if (o.reportFrameTimes) {
    glFinish();
    frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
  }
  const std::string newTitle = editorWindowTitle(state);
  if (newTitle != title) {
    title = newTitle;
    glfwSetWindowTitle(window, title.c_str());
  }
  if (last) return false;
  ++frame;
  return true;
}

EditorWindowResult EditorWindow::Session::shutdown() {
  if (result.opened && !shutDown) {
    shutDown = true;
    result.frames = frame;
    // The window's size and place and the splitters, for the next start (the rest of the
    // preferences is saved when changed); a file that could not be read is left alone.
    std::vector<std::string> unreadable;
    UserPreferences saved = loadUserPreferences(unreadable);
    if (unreadable.empty()) {
      saved.panels = state.preferences.panels;
      glfwGetWindowPos(window, &saved.window.x, &saved.window.y);
      glfwGetWindowSize(window, &saved.window.width, &saved.window.height);
      saved.window.positioned = true;
      if (const std::string failed = saveUserPreferences(saved); !failed.empty())
        std::cerr << "kinema edit: preferences: " << failed << "\n";
    }
    if (!o.dumpStatePath.empty()) {
      const std::string dumpError = writeFileAtomically(o.dumpStatePath, editorStateJson(state, ww, wh, frame));
      if (result.error.empty()) result.error = dumpError;
    }
    if (timer) result.framePasses = timer->report(static_cast<size_t>(frame / 10));
    if (!frameMs.empty()) {
      // The first frames compile shaders and upload meshes: leave out the first tenth.
      std::vector<double> t(frameMs.begin() + frameMs.size() / 10, frameMs.end());
      result.meanFrameMs = std::accumulate(t.begin(), t.end(), 0.0) / t.size();
      std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
      result.medianFrameMs = t[t.size() / 2];
    }
  }
  return result;
}

EditorWindow::EditorWindow(EditorState& state, const EditorWindowOptions& options)
    : s_(std::make_unique<Session>(state, options)) {}
EditorWindow::~EditorWindow() = default;
bool EditorWindow::setup() { return s_->setup(); }
bool EditorWindow::frame() { return s_->runFrame(); }
EditorWindowResult EditorWindow::shutdown() {
  EditorWindowResult result = s_->shutdown();
  s_.reset();  // the GL objects, ImGui, the window and GLFW, in that order
  return result;
}

EditorWindowResult runEditorWindow(EditorState& state, const EditorWindowOptions& options) {
  EditorWindow window(state, options);
  if (window.setup())
    while (window.frame()) {
    }
  return window.shutdown();
}

}  // namespace kinema
