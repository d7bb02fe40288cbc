#include "cli/edit_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/command_line.h"
#include "cli/render_command.h"
#include "editor/commands/controls_help.h"
#include "editor/commands/keymap.h"
#include "editor/commands/file_commands.h"
#include "editor/window/editor_window.h"
#include "editor/model/input_events.h"

namespace kinema::cli {

CLI::App* addEditCommand(CLI::App& app, EditOptions& o) {
  CLI::App* cmd = app.add_subcommand("edit", "Open the editor window on a file (default: the default character)");
  cmd->add_option("file", o.file, "A .bvh, .kinema, .gltf or .glb file");
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  cmd->add_option("--frame-count", o.frameCount, "Draw N frames, then quit (for tests)");
  cmd->add_option("--screenshot", o.screenshot, "Write the last frame to this PNG (with --frame-count or --script)");
  cmd->add_option("--script", o.script,
                  "Replay input events from this file (JSON lines or array, see docs/cli.md) at 1/60 s per frame");
  cmd->add_option("--dump-state", o.dumpState, "On exit, write the editor's state as JSON to this file");
  cmd->add_option("--size", o.size, "Window size WxH in pixels (default: the last size, at most the screen)");
  cmd->add_option("--ui-scale", o.uiScale,
                  "Text and widget scale from 0.75 to 3 for this run (default: Edit > Preferences, saved)");
  cmd->add_option("--max-fps", o.maxFps, "Draw at most N frames per second (1 to 1000; for tests and slow machines)");
  cmd->add_flag("--report-frame-times", o.reportFrameTimes, "Print mean and median frame times (ms) on stderr at exit");
  cmd->add_flag("--report-frame-passes", o.reportFramePasses,
                "Time each pass of every frame (with glFinish between them) and print the medians on stderr at exit");
  cmd->add_flag("--empty-frame", o.emptyFrame, "Draw only an empty ImGui frame (baseline for --report-frame-times)");
  cmd->add_option("--redraw", o.redraw,
                  "How each frame is drawn: changed (only what differs from the previous frame), whole, or auto "
                  "(changed on software rasterisers such as llvmpipe; the default)")
      ->check(CLI::IsMember({"auto", "whole", "changed"}));
  addUpOption(cmd, o.up);
  cmd->add_option("--compare", o.compare, "Open in Teach > Compare Solvers with this preset (kinema demo list)");
  cmd->add_flag("--list-commands", o.listCommands,
                "Print every editor command with its keys (the keymap file applied) as markdown, and exit");
  return cmd;
}

int runEdit(const EditOptions& o) {
  if (o.listCommands) {
    std::vector<std::string> problems;
    const Keymap keymap = loadUserKeymap(editorCommands(), problems);
    for (const std::string& p : problems) std::cerr << "kinema edit: keymap: " << p << "\n";
    std::cout << controlsMarkdown(keymap);
    return kExitOk;
  }
  if (o.frameCount < 0) return badInput("--frame-count must not be negative");
  if (!std::isnan(o.uiScale) && !(o.uiScale >= kMinUiScale && o.uiScale <= kMaxUiScale)) {
    char given[32];
    std::snprintf(given, sizeof given, "%g", o.uiScale);
    return badInput(std::string("--ui-scale ") + given + ": expected a scale from 0.75 to 3");
  }
  if (o.maxFps != -1 && (o.maxFps < 1 || o.maxFps > 1000)) return badInput("--max-fps must be a whole number from 1 to 1000");
  EditorWindowOptions options;
  options.redraw = o.redraw == "whole" ? WindowRedraw::Whole : o.redraw == "changed" ? WindowRedraw::Changed : WindowRedraw::Auto;
  options.width = o.width;
  options.height = o.height;
  options.uiScale = std::isnan(o.uiScale) ? 0.0f : o.uiScale;
  if (!o.size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(o.size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x') {
      std::cerr << "kinema edit: --size takes WxH, e.g. 1280x720; see --help\n";
      return kExitUsage;
    }
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
      return badInput("--size " + o.size + ": width and height must be whole numbers from 1 to 16384");
    options.width = w;
    options.height = h;
  }
  if (!o.screenshot.empty() && o.frameCount == 0 && o.script.empty())
    return badInput("--screenshot needs --frame-count or --script (the frame to capture)");
  if (!o.script.empty()) {
    // A command event must name a command of the registry (an unknown id fails here).
    Result<std::vector<InputEvent>> script =
        loadInputScript(o.script, [](const std::string& id) { return editorCommands().find(id) != nullptr; });
    if (!script) return badInput(script.error());
    options.script = std::move(script.value());
    options.replay = true;
  }
  Result<Scene> loaded = loadSceneOrDefault(o.file, inputLimits(o.allowOutsidePaths), upAxisOf(o.up));
  if (!loaded) return badInput(loaded.error());
  EditorState state;
  state.inputLimits = inputLimits(o.allowOutsidePaths);  // File > Open reads with the same limits
  openDocumentInEditor(state, Document(std::move(loaded.value()), o.file));  // as File > Open does
  if (!o.compare.empty()) {
    if (!findTeachingPreset(o.compare)) {
      std::cerr << "kinema edit: --compare '" << o.compare << "' is not an IK preset (the entries of `kinema demo list --json` whose kind is ik-preset; figure demos such as stiff-springs are not solver comparisons); see --help\n";
      return kExitUsage;
    }
    state.compare.active = true;
    if (const std::string err = openComparePreset(state.compare, o.compare); !err.empty()) return badInput(err);
  }
  options.frameCount = o.frameCount;
  options.screenshotPath = o.screenshot;
  options.dumpStatePath = o.dumpState;
  options.reportFrameTimes = o.reportFrameTimes;
  options.maxFps = std::max(o.maxFps, 0);
  options.emptyFrame = o.emptyFrame;
  options.reportFramePasses = o.reportFramePasses;
  const EditorWindowResult result = runEditorWindow(state, options);
  if (!result.opened) return badInput("cannot open the editor window: " + result.error + " (kinema render works without one)");
  if (!result.error.empty()) return badInput(result.error);
  if (o.reportFrameTimes)
    std::fprintf(stderr, "frame times over %lld frames (first tenth left out): mean %.2f ms, median %.2f ms\n",
                 result.frames, result.meanFrameMs, result.medianFrameMs);
  if (o.reportFramePasses)
    std::fprintf(stderr, "frame passes over %lld frames (first tenth left out, glFinish after each):\n%s", result.frames,
                 result.framePasses.c_str());
  return kExitOk;
}

int runDefault() {
  if (displayAvailable()) {
    EditorState state;
    openDocumentInEditor(state, Document(loadSceneOrDefault("").value()));
    const EditorWindowResult result = runEditorWindow(state, EditorWindowOptions{});
    if (result.opened) return result.error.empty() ? kExitOk : badInput(result.error);
    std::cerr << "kinema: cannot open the editor window (" << result.error << "); rendering instead\n";
  }
  return renderDefaultCharacterHeadless("kinema-default.png");
}

}  // namespace kinema::cli
