#pragma once
#include <string>
#include <vector>

#include "editor/model/editor_layout.h"
#include "editor/model/key_preferences.h"

namespace kinema {

// Edit > Preferences: how the editor looks and what new keys carry, the user's own (not the
// document's), kept as JSON in kinemaConfigDir()/preferences.json and read at start.
enum class UiTheme { Dark, Light, Classic };
const char* toString(UiTheme theme);  // "dark", "light", "classic"
bool fromString(const std::string& s, UiTheme& out);

// The editor's text font: DejaVu Sans (Debian's fonts-dejavu-core) rasterised at the UI
// scale, or ImGui's built-in bitmap font, scaled, when the file is absent (window/ui_style.h).
constexpr const char* kUiFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kUiFontPixels = 14.0f;        // DejaVu Sans at UI scale 1 (window pixels)
constexpr float kFallbackFontPixels = 13.0f;  // ImGui's built-in font at UI scale 1

constexpr float kMinUiScale = 0.75f, kMaxUiScale = 3.0f;  // the UI scale's range (1 = 14 px text)
constexpr float kMinLineScale = 1.0f, kMaxLineScale = 4.0f;  // 3D lines and markers, times their pixels

// Where and how large the window was when last closed (screen pixels, top left origin);
// width 0: never saved (the editor picks a size for the screen).
struct WindowPlacement {
  int x = 0, y = 0, width = 0, height = 0;
  bool positioned = false;  // x, y are known (a window manager may refuse to say)
  bool operator==(const WindowPlacement& o) const {
    return x == o.x && y == o.y && width == o.width && height == o.height && positioned == o.positioned;
  }
};

// The work area of the monitor the window opens on (screen pixels, without panels and docks).
struct ScreenArea {
  int x = 0, y = 0, width = 0, height = 0;  // width 0: unknown
};
// Where the window opens when no --size is given: the remembered size, else 90% of the work
// area; never larger than the work area. The remembered position when the window fits there
// on the work area, else centred on it (positioned false when the work area is unknown).
WindowPlacement initialWindowPlacement(const WindowPlacement& remembered, const ScreenArea& work);

struct UserPreferences {
  float uiScale = 1.0f;    // text and widgets, [kMinUiScale, kMaxUiScale]; times the monitor's content scale
  float lineScale = 1.0f;  // 3D lines, IK target markers and the grid, [kMinLineScale, kMaxLineScale]
  UiTheme theme = UiTheme::Dark;
  // The session's settings these mirror are EditorState::loop and Document::autoKey.preferences;
  // the file keeps them between sessions (preferencesOf / applyPreferences in editor_preferences.h).
  bool loop = true;
  KeyPreferences keys;
  PanelSizes panels;       // the splitters' positions (editor_layout.h)
  WindowPlacement window;
  bool operator==(const UserPreferences& o) const;
  bool operator!=(const UserPreferences& o) const { return !(*this == o); }
};

// Teaching on a projector: text twice as large, 3D lines and markers thicker.
UserPreferences presentationPreset(UserPreferences base);
// The desk defaults for the look (scale 1, thin lines), keeping keys, loop, panels and window.
UserPreferences deskPreset(UserPreferences base);
// True when `p` looks like the presentation preset (scale and lines as it sets them).
bool isPresentation(const UserPreferences& p);

// JSON text of `p` (every field, so the file documents itself).
std::string preferencesJson(const UserPreferences& p);
// Reads preferences from JSON text. Unknown members are ignored, missing ones keep their
// defaults; a member of the wrong type or out of range is reported in `problems` (one line
// each, prefixed with `source`) and left at its default. Not valid JSON: defaults, one problem.
UserPreferences parsePreferences(const std::string& text, const std::string& source, std::vector<std::string>& problems);

// kinemaConfigDir()/preferences.json; "" when no config folder is known.
std::string userPreferencesPath();
// Loads `path` (default: userPreferencesPath()); a missing file gives the defaults silently.
UserPreferences loadUserPreferences(std::vector<std::string>& problems, const std::string& path = userPreferencesPath());
// Writes atomically, creating the folder; "" on success, else one line.
std::string saveUserPreferences(const UserPreferences& p, const std::string& path = userPreferencesPath());

}  // namespace kinema
