#pragma once
#include <CLI/CLI.hpp>

#include <limits>

namespace kinema::cli {

// `kinema edit [FILE] [--frame-count N] [--screenshot PATH] [--script FILE] [--dump-state FILE]
//  [--size WxH] [--ui-scale S] [--max-fps N] [--redraw MODE] [--report-frame-times] [--empty-frame] [--compare PRESET]
//  [--list-commands]`
struct EditOptions {
  std::string file;
  bool allowOutsidePaths = false;  // --allow-outside-paths: glTF uris may leave the file's folder
  long long frameCount = 0;
  std::string screenshot;
  std::string script;
  std::string dumpState;
  std::string size;
  int maxFps = -1;  // -1: not given (no cap beyond vsync)
  bool reportFrameTimes = false;
  bool reportFramePasses = false;
  bool emptyFrame = false;
  std::string redraw = "auto";  // --redraw: auto, whole or changed (window_redraw.h)
  std::string compare;  // open straight into Teach > Compare Solvers with this preset
  bool listCommands = false;  // print every command and its keys as markdown, open no window
  std::string up = "y";  // --up: BVH files' up axis
  float uiScale = std::numeric_limits<float>::quiet_NaN();  // --ui-scale; NaN: not given (the preferences')
  int width = 0, height = 0;  // 0: remembered, else most of the screen
};

CLI::App* addEditCommand(CLI::App& app, EditOptions& options);
int runEdit(const EditOptions& options);

// Plain `kinema`: the editor on the default character, or, when no window can open, the
// default character rendered headlessly to ./kinema-default.png (its path is printed).
int runDefault();

}  // namespace kinema::cli
