#include "cli/edit_command.h"

#include <iostream>

#include "cli/command_line.h"
#include "cli/render_command.h"
#include "editor/editor_window.h"

namespace kinema::cli {

CLI::App* addEditCommand(CLI::App& app, EditOptions& o) {
  CLI::App* cmd = app.add_subcommand("edit", "Open the editor window on a file (default: the default character)");
  cmd->add_option("file", o.file, "A .bvh or .kinema file");
  CLI::Option* count = cmd->add_option("--frame-count", o.frameCount, "Draw N frames, then quit (for tests)");
  cmd->add_option("--screenshot", o.screenshot, "With --frame-count: write the last frame to this PNG")->needs(count);
  return cmd;
}

int runEdit(const EditOptions& o) {
  if (o.frameCount < 0) return badInput("--frame-count must not be negative");
  Result<Scene> loaded = loadSceneOrDefault(o.file);
  if (!loaded) return badInput(loaded.error());
  EditorState state;
  state.scene = std::move(loaded.value());
  state.path = o.file;
  EditorWindowOptions options;
  options.frameCount = o.frameCount;
  options.screenshotPath = o.screenshot;
  options.width = o.width;
  options.height = o.height;
  const EditorWindowResult result = runEditorWindow(state, options);
  if (!result.opened) return badInput("cannot open the editor window: " + result.error + " (kinema render works without one)");
  if (!result.error.empty()) return badInput(result.error);
  return kExitOk;
}

int runDefault() {
  if (displayAvailable()) {
    EditorState state;
    state.scene = loadSceneOrDefault("").value();
    const EditorWindowResult result = runEditorWindow(state, EditorWindowOptions{});
    if (result.opened) return result.error.empty() ? kExitOk : badInput(result.error);
    std::cerr << "kinema: cannot open the editor window (" << result.error << "); rendering instead\n";
  }
  return renderDefaultCharacterHeadless("kinema-default.png");
}

}  // namespace kinema::cli
