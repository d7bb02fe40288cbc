#pragma once
#include <string>

#include "editor/editor_state.h"

namespace kinema {

struct EditorWindowOptions {
  int width = 1280, height = 720;
  long long frameCount = 0;   // > 0: stop after this many frames (tests under Xvfb)
  std::string screenshotPath; // with frameCount: the last frame's pixels go here as PNG
};

struct EditorWindowResult {
  bool opened = false;  // false: no display or no usable OpenGL 3.3 window (see error)
  std::string error;    // one line, empty on success
};

// Opens the GLFW window and runs the editor on `state` until the user closes it (or the
// frame count is reached). Blocks. The state stays the caller's.
EditorWindowResult runEditorWindow(EditorState& state, const EditorWindowOptions& options);

// True when a window system looks reachable (DISPLAY or WAYLAND_DISPLAY is set).
bool displayAvailable();

}  // namespace kinema
