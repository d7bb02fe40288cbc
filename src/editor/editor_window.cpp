#include "editor/editor_window.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdlib>

#include "editor/editor_panels.h"
#include "editor/imgui_backends.h"
#include "editor/viewport_controller.h"
#include "io/image.h"
#include "render/skeleton_renderer.h"
#include "render/skeleton_view.h"

namespace kinema {

namespace {

// GLFW reports errors through a callback; keep the last one for the one-line message.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}
void onGlfwError(int code, const char* description) {
  lastGlfwError() = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

GLFWwindow* createWindow(const EditorWindowOptions& o, const std::string& title, int samples) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, samples);
  return glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
}

void handleViewportInput(EditorState& state, const ViewportController& controller, const Bounds& bounds,
                         glm::vec2 windowSize) {
  const ImGuiIO& io = ImGui::GetIO();
  const float aspect = windowSize.y > 0 ? windowSize.x / windowSize.y : 1.0f;
  if (!io.WantCaptureMouse) {
    const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
    const bool navigate = ImGui::IsMouseDown(ImGuiMouseButton_Middle) || (io.KeyAlt && ImGui::IsMouseDown(ImGuiMouseButton_Left));
    if (navigate && (delta.x != 0 || delta.y != 0)) {
      if (io.KeyShift) controller.pan(state.camera, delta, windowSize.y);
      else controller.orbit(state.camera, delta);
    }
    if (io.MouseWheel != 0) controller.zoom(state.camera, io.MouseWheel);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyAlt) {
      const glm::mat4 vp = state.camera.projection(aspect) * state.camera.view();
      const int picked = pickJoint(state.world, vp, windowSize, glm::vec2(io.MousePos.x, io.MousePos.y), 12.0f);
      if (io.KeyShift) state.doc.selection.shiftClick(picked);
      else state.doc.selection.click(picked);
    }
  }
  if (!io.WantCaptureKeyboard) {
    // ImGui 1.86 indexes keys by the platform's codes (GLFW's here).
    if (ImGui::IsKeyPressed(GLFW_KEY_HOME) || ImGui::IsKeyPressed(GLFW_KEY_F)) controller.frameAll(state.camera, bounds, aspect);
    if (ImGui::IsKeyPressed(GLFW_KEY_SPACE) && state.hasMotion()) state.playing = !state.playing;
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) state.doc.selection.clear();
  }
}

}  // namespace

bool displayAvailable() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

EditorWindowResult runEditorWindow(EditorState& state, const EditorWindowOptions& o) {
  EditorWindowResult result;
  if (!displayAvailable()) {
    result.error = "no display (DISPLAY and WAYLAND_DISPLAY are unset)";
    return result;
  }
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    result.error = "cannot start GLFW: " + lastGlfwError();
    return result;
  }
  const std::string title = "Kinema - " + state.scene.source;
  GLFWwindow* window = createWindow(o, title, 4);
  if (!window) window = createWindow(o, title, 0);  // no multisampled visual: draw without MSAA
  if (!window) {
    result.error = "cannot open an OpenGL 3.3 core window: " + lastGlfwError();
    glfwTerminate();
    return result;
  }
  glfwMakeContextCurrent(window);
  const int version = gladLoadGL(glfwGetProcAddress);
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
    result.error = "the window's OpenGL is older than 3.3";
    glfwDestroyWindow(window);
    glfwTerminate();
    return result;
  }
  result.opened = true;
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini dropped in the user's folder
  ImGui::StyleColorsDark();
  imguiBackendsInit(window);

  {
    SkeletonRenderer renderer;
    const std::string error = renderer.init();
    if (!error.empty()) result.error = error;
    ViewportController controller;
    // The panels edit the document; until the window's own integration lands it shows it.
    if (state.doc.skeleton().empty() && !state.scene.skeleton.empty()) state.doc = Document(state.scene, state.path);
    state.world = state.doc.worldTransforms();
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window, &fbw, &fbh);
    state.camera = defaultCamera(jointBounds(state.world), fbh > 0 ? float(fbw) / float(fbh) : 1.0f);
    std::string shownTitle = title;
    for (long long frame = 1; error.empty() && !state.panels.quitApproved; ++frame) {
      glfwPollEvents();
      if (glfwWindowShouldClose(window)) {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        requestQuit(state);  // asks first when there are unsaved changes
      }
      state.world = state.doc.worldTransforms();
      const Bounds bounds = jointBounds(state.world);
      if (state.requests.frameAll) {
        state.requests.frameAll = false;
        controller.frameAll(state.camera, bounds, fbh > 0 ? float(fbw) / float(fbh) : 1.0f);
      }
      const std::string wanted = "Kinema - " + documentTitle(state) + (state.doc.dirty() ? " *" : "");
      if (wanted != shownTitle) glfwSetWindowTitle(window, (shownTitle = wanted).c_str());

      imguiBackendsNewFrame();
      ImGui::NewFrame();
      int ww = 0, wh = 0;
      glfwGetWindowSize(window, &ww, &wh);
      handleViewportInput(state, controller, bounds, glm::vec2(ww, wh));
      drawEditorPanels(state, ImGui::GetIO().Framerate);
      ImGui::Render();

      glfwGetFramebufferSize(window, &fbw, &fbh);
      SkeletonDrawList list;
      SkeletonDrawJob job;
      job.parents = &state.scene.skeleton.parents;
      job.world = &state.world;
      job.selectedJoint = state.doc.selection.active();
      job.run(list);
      state.camera.fitClipPlanes(bounds.radius());
      FrameDescription description;
      description.skeleton = &list;
      description.camera = state.camera;
      description.width = fbw;
      description.height = fbh;
      description.sceneRadius = bounds.radius();
      description.showGrid = state.view.showGrid;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      renderer.draw(description);
      imguiBackendsRenderDrawData(ImGui::GetDrawData());

      const bool last = o.frameCount > 0 && frame >= o.frameCount;
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
      glfwSwapBuffers(window);
      if (last) break;
    }
  }
  imguiBackendsShutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return result;
}

}  // namespace kinema
