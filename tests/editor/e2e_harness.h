#pragma once
// Shared pieces of the editor's end-to-end tests: running the real `kinema edit` under
// xvfb-run with Mesa's llvmpipe on a --script, reading its --dump-state, and the test's own
// camera (rebuilt from the dumped eye, target, field of view and viewport rectangle) that
// turns world points into the window pixels a script clicks, independently of the editor.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "test_support.h"

namespace kinema::test::e2e {

using json = nlohmann::json;

inline const std::string kSoftware =
    "LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";
inline const std::string kXvfb = "xvfb-run -a -s '-screen 0 1280x800x24' ";

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

// Events at increasing frames from frame 3 (frames 1-2: the front view, then frame all).
// Panel clicks need the press and the release in different frames, as the editor's do.
class Script {
 public:
  Script() { lines_ = "{\"frame\":1,\"type\":\"key\",\"key\":\"KP_1\"}\n{\"frame\":2,\"type\":\"key\",\"key\":\"HOME\"}\n"; }
  Script& move(glm::dvec2 p) { return add("\"type\":\"mouse_move\",\"x\":" + num(p.x) + ",\"y\":" + num(p.y)); }
  Script& down(const char* button = "left") { return add(std::string("\"type\":\"button_down\",\"button\":\"") + button + "\""); }
  Script& up(const char* button = "left") { return add(std::string("\"type\":\"button_up\",\"button\":\"") + button + "\""); }
  Script& click(glm::dvec2 p) { return move(p).down().up(); }
  Script& doubleClick(glm::dvec2 p) { return move(p).down().up().down().up(); }
  Script& key(const char* name) { return add(std::string("\"type\":\"key\",\"key\":\"") + name + "\""); }
  Script& keyDown(const char* name) { return add(std::string("\"type\":\"key_down\",\"key\":\"") + name + "\""); }
  Script& keyUp(const char* name) { return add(std::string("\"type\":\"key_up\",\"key\":\"") + name + "\""); }
  Script& type(const std::string& text) { return add("\"type\":\"text\",\"text\":\"" + text + "\""); }
  Script& scroll(double y) { return add("\"type\":\"scroll\",\"y\":" + num(y)); }
  // Runs an editor command by id, as its menu item or key would (docs/cli.md).
  Script& command(const std::string& id) { return add("\"type\":\"command\",\"id\":\"" + id + "\""); }
  Script& wait(int frames) {
    frame_ += frames;
    return *this;
  }
  // A menu of the main menu bar, then one of its items (menus open on the next frame).
  Script& menu(glm::dvec2 title, glm::dvec2 item) { return click(title).wait(2).click(item).wait(2); }
  // Mouse path in `steps` straight moves from the current position `a` to `b`.
  Script& path(glm::dvec2 a, glm::dvec2 b, int steps = 6) {
    for (int i = 1; i <= steps; ++i) move(a + (b - a) * (double(i) / steps));
    return *this;
  }
  const std::string& text() const { return lines_; }

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
  std::string lines_;
  long long frame_ = 3;
};

// Runs the editor on the default character (or `file`) at `size` with the script; recent
// and recovery files stay in `dir`; the last frame goes to `shotDir`/NAME.png. Returns the
// dumped state (null when the run failed).
inline json runEditor(const std::string& dir, const std::string& shotDir, const Script& script, const std::string& name,
                      const std::string& size = "1280x720", const std::string& file = "") {
  const std::string scriptPath = dir + "/" + name + ".jsonl", dump = dir + "/" + name + ".json";
  std::ofstream(scriptPath) << script.text();
  std::string out, err;
  const std::string xdg = "XDG_STATE_HOME=" + dir + " XDG_CONFIG_HOME=" + dir + " ";
  const int rc = runCommand(kXvfb + "env " + xdg + kSoftware + KINEMA_BINARY + " edit " +
                                (file.empty() ? std::string() : "'" + file + "' ") + "--size " + size + " --script " +
                                scriptPath + " --dump-state " + dump + " --screenshot " + shotDir + "/" + name + ".png",
                            &out, &err);
  EXPECT_EQ(rc, 0) << err;
  return rc == 0 ? readJson(dump) : json();
}

// A suite whose tests start from the editor's front view on the default character: the
// editor runs once for the suite (front_: its dump, the camera for pixel maths), each test
// gets a fresh temporary folder (dir_), and screenshots go to the build dir's
// Suite::kShotFolder. Suite names kShotFolder and kWindowSize ("WxH").
template <typename Suite>
class FrontViewSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (runCommand("command -v xvfb-run") != 0) return;
    const std::string dir = makeTempDir();
    const json d = runEditor(dir, shotDir(), Script(), "front", Suite::kWindowSize);
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
    return runEditor(dir_, shotDir(), script, name, Suite::kWindowSize, file);
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
