#pragma once
#include <memory>
#include <string>
#include <vector>

#include "editor/model/editor_state.h"
#include "editor/model/input_events.h"

namespace kinema {

struct EditorWindowOptions {
  // Window size in pixels (--size); 0: the size remembered in the preferences, else most of
  // the screen (never more than the monitor's work area).
  int width = 0, height = 0;
  float uiScale = 0.0f;       // > 0: --ui-scale, instead of the preferences' (not saved)
  long long frameCount = 0;   // > 0: stop after this many frames (tests under Xvfb)
  std::string screenshotPath; // with frameCount: the last frame's pixels go here as PNG
  // Replayed input (kinema edit --script): each event is handled in its frame, and every
  // frame advances a fixed 1/60 s, so runs are deterministic. Without frameCount the window
  // closes two frames after the last event.
  bool replay = false;
  std::vector<InputEvent> script;
  std::string dumpStatePath;  // written on exit (editorStateJson)
  bool reportFrameTimes = false;  // mean / median frame time on stderr at exit
  // --report-frame-passes: glFinish after each pass of every frame and the median time of
  // each pass on stderr at exit (slower frames, but where the time goes).
  bool reportFramePasses = false;
  bool emptyFrame = false;        // draw only an empty ImGui frame (the baseline for frame times)
  int maxFps = 0;                 // > 0: each frame lasts at least 1/maxFps s (kinema edit --max-fps)
  WindowRedraw redraw = WindowRedraw::Auto;  // kinema edit --redraw
};

struct EditorWindowResult {
  bool opened = false;  // false: no display or no usable OpenGL 3.3 window (see error)
  std::string error;    // one line, empty on success
  double meanFrameMs = 0, medianFrameMs = 0;
  long long frames = 0;
  std::string framePasses;  // reportFramePasses: the per-pass report, one line per pass
};

// The editor's window on `state` (which stays the caller's): setup opens the GLFW window
// and the GL and ImGui state, frame runs one frame (input, playback, panels, the 3D view,
// the picture shown), shutdown saves the window's place and closes everything.
class EditorWindow {
 public:
  EditorWindow(EditorState& state, const EditorWindowOptions& options);
  ~EditorWindow();  // closes what setup opened, if shutdown has not
  EditorWindow(const EditorWindow&) = delete;
  EditorWindow& operator=(const EditorWindow&) = delete;

  bool setup();  // false: no window (shutdown's result says why)
  bool frame();  // false: no frame follows (closed, the frame count reached, an error)
  EditorWindowResult shutdown();

 private:
  struct Session;
  std::unique_ptr<Session> s_;
};

// setup, frame until the last, shutdown: runs the editor until the user closes it (or the
// frame count is reached). Blocks.
EditorWindowResult runEditorWindow(EditorState& state, const EditorWindowOptions& options);

// True when a window system looks reachable (DISPLAY or WAYLAND_DISPLAY is set).
bool displayAvailable();

// "Kinema - name" with a * when the document has unsaved changes.
std::string editorWindowTitle(const EditorState& state);

}  // namespace kinema
