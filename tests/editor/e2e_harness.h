#pragma once
// Shared pieces of the editor's end-to-end tests: running the real `kinema edit` under
// xvfb-run with Mesa's llvmpipe on a --script, reading its --dump-state, and the test's own
// camera (rebuilt from the dumped eye, target, field of view and viewport rectangle) that
// turns world points into the window pixels a script clicks, independently of the editor.
//
// Widgets are found by name, never by layout pixels: a script event names a widget
// ("View/Dope Sheet", "IK Targets/Position/0") and the editor puts the pointer where that
// widget was last drawn; the dump's "items" gives every named widget's rectangle
// (src/editor/panels/item_names.h), so a test derives points inside custom-drawn areas from
// those rectangles or from the areas the dump describes. Every suite runs at 1280x720, or at
// KINEMA_E2E_SIZE=WxH (e.g. 1600x1000) when that is set.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "test_support.h"

namespace kinema::test::e2e {

using json = nlohmann::json;

inline const std::string kSoftware =
    "LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";

// The editor window's size in every e2e run: KINEMA_E2E_SIZE ("WxH") when set, else 1280x720.
inline glm::ivec2 windowPixels() {
  const char* env = std::getenv("KINEMA_E2E_SIZE");
  if (env == nullptr || *env == '\0') return {1280, 720};
  int w = 0, h = 0;
  char rest = 0;
  if (std::sscanf(env, "%dx%d%c", &w, &h, &rest) != 2 || w < 640 || h < 480 || w > 7680 || h > 4320) {
    ADD_FAILURE() << "KINEMA_E2E_SIZE=" << env << ": expected WxH (at least 640x480), e.g. 1600x1000";
    return {1280, 720};
  }
  return {w, h};
}
inline std::string windowSize() {
  const glm::ivec2 s = windowPixels();
  return std::to_string(s.x) + "x" + std::to_string(s.y);
}

// An Xvfb of the command's own (tests/tools/xvfb_run.sh: the server picks a free display, so
// parallel tests never race for one) with a screen at least 1920x1200, never smaller than the window.
inline std::string xvfb() {
  const glm::ivec2 s = glm::max(windowPixels(), glm::ivec2(1920, 1200));
  return "sh '" KINEMA_SOURCE_DIR "/tests/tools/xvfb_run.sh' " + std::to_string(s.x) + "x" + std::to_string(s.y) + "x24 ";
}

// `env` with software GL and the user's config and state folders (recent files, recovery
// files, anything remembered) in the test's own temporary folders, for every editor launch.
inline std::string editorEnvironment(const std::string& configHome, const std::string& stateHome) {
  return "env XDG_CONFIG_HOME='" + configHome + "' XDG_STATE_HOME='" + stateHome + "' " + kSoftware;
}
inline std::string editorEnvironment(const std::string& dir) { return editorEnvironment(dir, dir); }

inline json readJson(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  json j = json::parse(s.str(), nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << path << " is not JSON: " << s.str().substr(0, 200);
  return j.is_discarded() ? json() : j;
}

inline glm::dvec3 vec3(const json& a) {
  return a.is_array() && a.size() == 3 ? glm::dvec3(a[0], a[1], a[2]) : glm::dvec3(NAN);
}

// A camera rebuilt from a dump: eye, target, vertical field of view, Y up (the azimuth's
// horizontal direction at the poles, as OrbitCamera does), perspective or orthographic
// (half height distance * tan(fov/2)), over the dumped viewport rectangle (window pixels).
struct DumpCamera {
  glm::dvec3 eye, target, f, r, u;
  double fovY = 0.6, x0 = 0, y0 = 0, w = 1, h = 1;
  bool ortho = false;
  explicit DumpCamera(const json& d) {
    const json& c = d["camera"];
    const json& v = d["viewport"];
    x0 = v["x"], y0 = v["y"], w = v["width"], h = v["height"];
    eye = vec3(c["eye"]);
    target = vec3(c["target"]);
    fovY = double(c["fov_y"]) * M_PI / 180.0;
    ortho = c["orthographic"].get<bool>();
    f = glm::normalize(target - eye);
    glm::dvec3 up(0, 1, 0);
    if (std::abs(f.y) > 0.9999) {
      const double az = double(c["azimuth"]) * M_PI / 180.0;
      up = glm::dvec3(-std::sin(az), 0, -std::cos(az)) * (f.y < 0 ? 1.0 : -1.0);
    }
    r = glm::normalize(glm::cross(f, up));
    u = glm::cross(r, f);
  }
  double depth(glm::dvec3 p) const { return glm::dot(p - eye, f); }
  // Half the view's height in world units on the plane facing the camera through p.
  double halfHeight(glm::dvec3 p) const {
    return (ortho ? glm::length(target - eye) : depth(p)) * std::tan(fovY / 2);
  }
  glm::dvec2 pixel(glm::dvec3 p) const {
    const glm::dvec3 d = p - eye;
    const double hh = halfHeight(p);
    const double nx = glm::dot(d, r) / (hh * w / h), ny = glm::dot(d, u) / hh;
    return {x0 + (nx + 1) / 2 * w, y0 + (1 - ny) / 2 * h};
  }
  // World units per pixel on the plane facing the camera at p's depth.
  double unitsPerPixel(glm::dvec3 p) const { return 2 * halfHeight(p) / h; }
  // The ray through a window pixel (perspective: from the eye).
  void ray(glm::dvec2 px, glm::dvec3& origin, glm::dvec3& direction) const {
    const double nx = (px.x - x0) / w * 2 - 1, ny = 1 - (px.y - y0) / h * 2;
    const double hh = (ortho ? glm::length(target - eye) : 1.0) * std::tan(fovY / 2);
    if (ortho) {
      origin = eye + r * (nx * hh * w / h) + u * (ny * hh);
      direction = f;
    } else {
      origin = eye;
      direction = glm::normalize(f + r * (nx * hh * w / h) + u * (ny * hh));
    }
  }
};

// A named widget's rectangle in a dump (window pixels); `at` is a point by fractions of it.
struct Rect {
  double x = NAN, y = NAN, width = NAN, height = NAN;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
  glm::dvec2 at(double fx, double fy) const { return {x + fx * width, y + fy * height}; }
  glm::dvec2 centre() const { return at(0.5, 0.5); }
  bool contains(glm::dvec2 p) const { return p.x >= x && p.x < right() && p.y >= y && p.y < bottom(); }
};
inline Rect rectOf(const json& r) {
  if (!r.is_object()) return Rect{};
  return Rect{double(r["x"]), double(r["y"]), double(r["width"]), double(r["height"])};
}
// The rectangle where the widget (or panel window) `name` was last drawn.
inline Rect itemRect(const json& d, const std::string& name) {
  if (!d.contains("items") || !d["items"].contains(name)) {
    ADD_FAILURE() << "no item named '" << name << "' in the dump";
    return Rect{};
  }
  return rectOf(d["items"][name]);
}
// The 3D view's rectangle in a dump.
inline Rect viewportRect(const json& d) { return rectOf(d["viewport"]); }
// The last frame any named widget was drawn in: the dump's final frame.
inline long long lastDrawnFrame(const json& d) {
  long long last = -1;
  for (const auto& [name, r] : d["items"].items()) last = std::max(last, r["frame"].get<long long>());
  return last;
}
// Whether `name` was drawn in the final frame (a name keeps its last rectangle once gone).
inline bool drawnLast(const json& d, const std::string& name) {
  return d["items"].contains(name) && d["items"][name]["frame"].get<long long>() == lastDrawnFrame(d);
}

// Events at increasing frames from frame 3 (frames 1-2: the front view, then frame all,
// unless the script starts as opened). Panel clicks need the press and the release in
// different frames, as the editor's do; a widget is named and the editor puts the pointer
// where it was last drawn (the move, then the press and release in the next frames).
class Script {
 public:
  enum class Start { FrontView, AsOpened };
  explicit Script(Start start = Start::FrontView) {
    if (start == Start::FrontView)
      lines_ = "{\"frame\":1,\"type\":\"key\",\"key\":\"KP_1\"}\n{\"frame\":2,\"type\":\"key\",\"key\":\"HOME\"}\n";
  }
  Script& move(glm::dvec2 p) { return add("\"type\":\"mouse_move\",\"x\":" + num(p.x) + ",\"y\":" + num(p.y)); }
  Script& down(const char* button = "left") { return add(std::string("\"type\":\"button_down\",\"button\":\"") + button + "\""); }
  Script& up(const char* button = "left") { return add(std::string("\"type\":\"button_up\",\"button\":\"") + button + "\""); }
  Script& click(glm::dvec2 p) { return move(p).down().up(); }
  Script& doubleClick(glm::dvec2 p) { return move(p).down().up().down().up(); }
  // The pointer onto the widget `name` at `at` (fractions of its rectangle, default the centre).
  Script& moveItem(const std::string& name, glm::dvec2 at = {0.5, 0.5}) {
    json e = {{"type", "mouse_move"}, {"item", name}};
    if (at != glm::dvec2(0.5, 0.5)) e["at"] = {at.x, at.y};
    return addEvent(e);
  }
  Script& clickItem(const std::string& name, glm::dvec2 at = {0.5, 0.5}) { return moveItem(name, at).down().up(); }
  Script& doubleClickItem(const std::string& name, glm::dvec2 at = {0.5, 0.5}) {
    return moveItem(name, at).down().up().down().up();
  }
  // A menu of the main menu bar, then one of its items (menus open on the next frame):
  // menu("View", "Dope Sheet") clicks "View", then "View/Dope Sheet".
  Script& menu(const std::string& title, const std::string& item) {
    return clickItem(title).wait(2).clickItem(title + "/" + item).wait(2);
  }
  // Selects a joint by its outliner row.
  Script& select(const std::string& joint) { return clickItem("Outliner/" + joint).wait(1); }
  // Types `degrees` into the active joint's Euler field `axis` of the properties panel (a
  // double click enters text mode), then Enter.
  Script& euler(int axis, double degrees) {
    doubleClickItem("Properties/Rotation/" + std::to_string(axis)).wait(1);
    return type(std::to_string(degrees)).key("ENTER").wait(3);
  }
  // File > Save As through its shortcut and the file dialog's path field.
  Script& saveAs(const std::string& path) {
    chord("S", {"ctrl", "shift"}).wait(2);
    return type(path).key("ENTER").wait(4);
  }
  // The mouse wheel over a panel's title bar (the window named by recordWindow): negative
  // notches scroll its content up, so widgets below its bottom come into view.
  Script& scrollPanel(const std::string& window, double notches) {
    return moveItem(window, {0.5, 0.02}).wait(1).scroll(notches).wait(2);
  }
  Script& key(const char* name) { return add(std::string("\"type\":\"key\",\"key\":\"") + name + "\""); }
  Script& keyDown(const char* name) { return add(std::string("\"type\":\"key_down\",\"key\":\"") + name + "\""); }
  Script& keyUp(const char* name) { return add(std::string("\"type\":\"key_up\",\"key\":\"") + name + "\""); }
  // A key with modifiers held ("ctrl", "shift", "alt"), then the modifiers let go as a user
  // would (ImGui ignores typed characters while Ctrl is down).
  Script& chord(const char* name, const std::vector<std::string>& mods) {
    addEvent(json{{"type", "key"}, {"key", name}, {"mods", mods}}).wait(1);
    return keyUp("LEFT_CONTROL").keyUp("LEFT_SHIFT");
  }
  Script& type(const std::string& text) { return addEvent(json{{"type", "text"}, {"text", text}}); }
  Script& scroll(double y) { return add("\"type\":\"scroll\",\"y\":" + num(y)); }
  // Runs an editor command by id, as its menu item or key would (docs/cli.md).
  Script& command(const std::string& id) { return add("\"type\":\"command\",\"id\":\"" + id + "\""); }
  Script& wait(int frames) {
    frame_ += frames;
    return *this;
  }
  // Mouse path in `steps` straight moves from the current position `a` to `b`.
  Script& path(glm::dvec2 a, glm::dvec2 b, int steps = 6) {
    for (int i = 1; i <= steps; ++i) move(a + (b - a) * (double(i) / steps));
    return *this;
  }
  const std::string& text() const { return lines_; }
  // The frame the last event added happens in (3 before any).
  long long lastFrame() const { return frame_ - 1; }

 private:
  static std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return b;
  }
  Script& add(const std::string& body) {
    lines_ += "{\"frame\":" + std::to_string(frame_++) + "," + body + "}\n";
    return *this;
  }
  Script& addEvent(json event) {
    event["frame"] = frame_++;
    lines_ += event.dump() + "\n";
    return *this;
  }
  std::string lines_;
  long long frame_ = 3;
};

// Runs the editor on the default character (or `file`) at windowSize() with the script;
// recent and recovery files (XDG_CONFIG_HOME, XDG_STATE_HOME) stay in `dir`; the last frame
// goes to `shotDir`/NAME.png; `extra`: more arguments ("--compare ccd-steps"). The window is
// always given its size (--size wins over anything remembered). Returns the dumped state
// (null when the run failed).
inline json runEditor(const std::string& dir, const std::string& shotDir, const Script& script, const std::string& name,
                      const std::string& file = "", const std::string& extra = "") {
  const std::string scriptPath = dir + "/" + name + ".jsonl", dump = dir + "/" + name + ".json";
  std::ofstream(scriptPath) << script.text();
  std::string out, err;
  const int rc = runCommand(xvfb() + editorEnvironment(dir) + KINEMA_BINARY + " edit " +
                                (file.empty() ? std::string() : "'" + file + "' ") + (extra.empty() ? "" : extra + " ") +
                                "--size " + windowSize() + " --script " + scriptPath + " --dump-state " + dump +
                                " --screenshot " + shotDir + "/" + name + ".png",
                            &out, &err);
  EXPECT_EQ(rc, 0) << err;
  return rc == 0 ? readJson(dump) : json();
}

// A suite whose tests each launch the editor themselves: a fresh temporary folder (dir_) per
// test, skipped without xvfb-run; screenshots go to the build dir's Suite::kShotFolder.
template <typename Suite>
class TempDirSuite : public ::testing::Test {
 protected:
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    dir_ = makeTempDir();
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }
  static std::string shotDir() {
    const std::string dir = std::string(KINEMA_BUILD_DIR) + "/" + Suite::kShotFolder;
    runCommand("mkdir -p '" + dir + "'");
    return dir;
  }
  std::string dir_;
};

// A suite whose tests start from the editor's front view on the default character: the
// editor runs once for the suite (front_: its dump, the camera for pixel maths), each test
// gets a fresh temporary folder (dir_), and screenshots go to the build dir's
// Suite::kShotFolder. Suite names kShotFolder; the window is windowSize().
template <typename Suite>
class FrontViewSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (runCommand("command -v xvfb-run") != 0) return;
    const std::string dir = makeTempDir();
    const json d = runEditor(dir, shotDir(), Script(), "front");
    if (d.is_object()) front_ = d;
    runCommand("rm -rf '" + dir + "'");
  }
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    ASSERT_TRUE(front_.is_object()) << "the front-view run failed";
    dir_ = makeTempDir();
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }
  static std::string shotDir() {
    const std::string dir = std::string(KINEMA_BUILD_DIR) + "/" + Suite::kShotFolder;
    runCommand("mkdir -p '" + dir + "'");
    return dir;
  }
  json run(const Script& script, const std::string& name, const std::string& file = "") {
    return runEditor(dir_, shotDir(), script, name, file);
  }

  static inline json front_;
  std::string dir_;
};

inline glm::dvec3 jointIn(const json& d, const std::string& name, const char* field = "world_position") {
  for (const json& j : d["joints"])
    if (j["name"] == name) return vec3(j[field]);
  ADD_FAILURE() << "no joint " << name;
  return glm::dvec3(NAN);
}

// A joint's local rotation from the dump, dumped as [x, y, z, w].
inline glm::dquat rotationIn(const json& d, const std::string& name) {
  for (const json& j : d["joints"])
    if (j["name"] == name) return glm::dquat(j["rotation"][3], j["rotation"][0], j["rotation"][1], j["rotation"][2]);
  ADD_FAILURE() << "no joint " << name;
  return glm::dquat(NAN, NAN, NAN, NAN);
}

inline void expectNear(glm::dvec3 a, glm::dvec3 b, double tol, const std::string& what) {
  EXPECT_LE(glm::length(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", "
                                     << b.y << ", " << b.z << ")";
}

// Same rotation (q and -q are one rotation).
inline void expectRotation(glm::dquat a, glm::dquat e, double tol, const std::string& what) {
  EXPECT_NEAR(std::abs(glm::dot(a, e)), 1.0, tol) << what << ": got (" << a.x << ", " << a.y << ", " << a.z << ", "
                                                  << a.w << ") for (" << e.x << ", " << e.y << ", " << e.z << ", "
                                                  << e.w << ")";
}

}  // namespace kinema::test::e2e
