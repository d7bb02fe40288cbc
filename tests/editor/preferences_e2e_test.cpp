// Edit > Preferences end to end (issue 18): --ui-scale 2 makes the text twice as tall on
// screen (measured in the screenshot's pixels), a bad preferences file is reported but not
// fatal, preferences changed in the window survive into the next launch, the splitters move
// and the status bar's messages reach View > Log in full.
#include <gtest/gtest.h>

#include <fstream>

#include "e2e_harness.h"
#include "io/image.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using e2e::json;
using e2e::Script;

const std::string kShots = std::string(KINEMA_BUILD_DIR) + "/preferences_e2e";

// The editor on the default character with `args` (the window size among them), the config
// folder `config`; returns the dump, the screenshot in kShots/NAME.png.
json launch(const std::string& config, const std::string& name, const Script& script, const std::string& args) {
  runCommand("mkdir -p '" + kShots + "'");
  const std::string scriptPath = config + "/" + name + ".jsonl", dump = config + "/" + name + ".json";
  std::ofstream(scriptPath) << script.text();
  std::string out, err;
  const int rc = runCommand(e2e::xvfb() + e2e::editorEnvironment(config) + KINEMA_BINARY + " edit " + args + " --script " +
                                scriptPath + " --dump-state " + dump + " --screenshot " + kShots + "/" + name + ".png",
                            &out, &err);
  EXPECT_EQ(rc, 0) << err;
  return rc == 0 ? e2e::readJson(dump) : json();
}

// Rows of `img` inside rectangle r holding text: a pixel much brighter than the rectangle's
// own background (its top left corner). Returns the height from the first to the last.
int textRowsHeight(const Image& img, const e2e::Rect& r) {
  const int x0 = int(r.x), x1 = int(r.right()), y0 = int(r.y), y1 = int(r.bottom());
  const std::uint8_t* bg = img.pixel(x0, y0);
  const int background = bg[0] + bg[1] + bg[2];
  int first = -1, last = -1;
  for (int y = y0; y < y1 && y < img.height; ++y)
    for (int x = x0; x < x1 && x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (p[0] + p[1] + p[2] > background + 3 * 90) {
        if (first < 0) first = y;
        last = y;
        break;
      }
    }
  return first < 0 ? 0 : last - first + 1;
}

// The menu bar's height in pixels: from the top, the first row at x whose colour differs
// from the bar's (the panels' title bars start there).
int menuBarPixels(const Image& img, int x) {
  const std::uint8_t* top = img.pixel(x, 1);
  for (int y = 1; y < img.height; ++y) {
    const std::uint8_t* p = img.pixel(x, y);
    if (std::abs(p[0] - top[0]) + std::abs(p[1] - top[1]) + std::abs(p[2] - top[2]) > 12) return y;
  }
  return img.height;
}

TEST(PreferencesCli, UiScaleOutsideItsRangeIsOneLineAndExitOne) {
  for (const char* bad : {"5", "0.5", "0"}) {
    std::string out, err;
    EXPECT_EQ(runCommand(std::string(KINEMA_BINARY) + " edit --ui-scale " + bad, &out, &err), 1) << bad;
    EXPECT_EQ(err, std::string("kinema: --ui-scale ") + bad + ": expected a scale from 0.75 to 3\n");
  }
}

class PreferencesE2e : public e2e::TempDirSuite<PreferencesE2e> {};  // no screenshots: no kShotFolder

TEST_F(PreferencesE2e, UiScaleTwoMakesTheTextTwiceAsTallAndABadFileIsReportedNotFatal) {
  const std::string one = dir_ + "/one", two = dir_ + "/two";
  runCommand("mkdir -p '" + one + "' '" + two + "/kinema'");
  // The second run's preferences file has one bad member: reported, the rest of it used.
  writeFile(two + "/kinema/preferences.json", R"({"theme": "neon", "loop": false})");
  const json d1 = launch(one, "scale1", Script().wait(3), "--size 1280x720");
  const json d2 = launch(two, "scale2", Script().wait(3), "--size 1280x720 --ui-scale 2");
  ASSERT_TRUE(d1.is_object() && d2.is_object());
  EXPECT_EQ(d1["ui_scale"], 1.0);
  EXPECT_EQ(d2["ui_scale"], 2.0);
  ASSERT_EQ(d2["errors"].size(), 1u) << d2["errors"].dump();
  EXPECT_EQ(d2["errors"][0], "preferences: " + two + "/kinema/preferences.json: theme: unknown value \"neon\"");
  EXPECT_FALSE(d2["timeline"]["loop"].get<bool>());  // the good member was applied
  EXPECT_EQ(d2["log"][0]["text"], d2["errors"][0]);  // and View > Log has it
  EXPECT_TRUE(d2["log"][0]["error"].get<bool>());

  const Result<Image> s1 = loadPng(kShots + "/scale1.png"), s2 = loadPng(kShots + "/scale2.png");
  ASSERT_TRUE(s1.ok() && s2.ok());
  // The "File" menu title's letters: F and l reach from the baseline to the cap height.
  const int t1 = textRowsHeight(s1.value(), e2e::itemRect(d1, "File")),
            t2 = textRowsHeight(s2.value(), e2e::itemRect(d2, "File"));
  ASSERT_GE(t1, 7) << "no text found in the File menu title";
  EXPECT_NEAR(double(t2) / t1, 2.0, 0.25) << t1 << " px vs " << t2 << " px";
  // The menu bar itself, measured down the File title's left padding (no text there).
  const int b1 = menuBarPixels(s1.value(), int(e2e::itemRect(d1, "File").x) + 2),
            b2 = menuBarPixels(s2.value(), int(e2e::itemRect(d2, "File").x) + 2);
  EXPECT_NEAR(double(b2) / b1, 2.0, 0.15) << b1 << " px vs " << b2 << " px";
  EXPECT_NEAR(b1, e2e::itemRect(d1, "File").height, 1.0);
  // The panels follow: the outliner starts under the taller bar and its column is wider.
  EXPECT_NEAR(e2e::itemRect(d2, "Outliner").y, b2, 1.0);
  EXPECT_GT(e2e::itemRect(d2, "Outliner").width, e2e::itemRect(d1, "Outliner").width);
  // On exit the window's size is saved, --ui-scale is not (it was for that run); a file with
  // a bad member is left as the user wrote it.
  const json saved1 = e2e::readJson(one + "/kinema/preferences.json");
  EXPECT_EQ(saved1["ui_scale"], 1.0);
  EXPECT_EQ(saved1["window"]["width"], 1280);
  EXPECT_EQ(saved1["window"]["height"], 720);
  EXPECT_EQ(e2e::readJson(two + "/kinema/preferences.json"), json::parse(R"({"theme": "neon", "loop": false})"));
}

TEST_F(PreferencesE2e, ChangesInThePreferencesWindowAndTheSplittersSurviveARestart) {
  // First launch: Edit > Preferences, the Light theme, UI scale 1.5x, new keys Linear; the
  // left column's splitter dragged 40 px right; a key inserted (its message in the log).
  Script first;
  first.select("Hand.L")
      .menu("Edit", "Preferences...")
      .clickItem("Preferences/Theme/Light")
      .wait(1)
      .clickItem("Preferences/Keys/linear")
      .wait(1)
      .moveItem("Splitter/Left column")
      .wait(1)
      .down()
      .wait(1);
  // The splitter sits at x = 250 (the left column's width at scale 1) before the scale changes.
  first.move({270.0, 300.0}).move({290.0, 300.0}).wait(1).up().wait(2);
  first.clickItem("Preferences/UI scale/1.5x").wait(3).command("anim.insert_keyframe").wait(3);
  const json d1 = launch(dir_, "first", first, "--size 1280x720");
  ASSERT_TRUE(d1.is_object());
  EXPECT_EQ(d1["preferences"]["theme"], "light");
  EXPECT_EQ(d1["ui_scale"], 1.5);
  EXPECT_EQ(d1["timeline"]["key_interpolation"], "linear");
  EXPECT_NEAR(d1["preferences"]["panels"]["left_width"].get<double>(), 290.0, 1.0);
  EXPECT_NEAR(e2e::itemRect(d1, "Outliner").width, 290.0 * 1.5, 1.0);  // stored at scale 1, shown at 1.5
  // The key's message, in full in the log as on the status line.
  bool logged = false;
  for (const json& e : d1["log"]) logged |= e["text"] == d1["status"];
  EXPECT_TRUE(logged) << d1["log"].dump();

  // Second launch, no --size: everything as left, the window at its remembered size.
  const json d2 = launch(dir_, "second", Script().wait(3), "");
  ASSERT_TRUE(d2.is_object());
  EXPECT_EQ(d2["preferences"]["theme"], "light");
  EXPECT_EQ(d2["ui_scale"], 1.5);
  EXPECT_EQ(d2["timeline"]["key_interpolation"], "linear");
  EXPECT_NEAR(d2["preferences"]["panels"]["left_width"].get<double>(), 290.0, 1.0);
  EXPECT_EQ(d2["window"]["width"], 1280);
  EXPECT_EQ(d2["window"]["height"], 720);
  EXPECT_NEAR(d2["preferences"]["font_size"].get<double>(), 21.0, 0.01);  // 14 px x 1.5
  const json saved = e2e::readJson(dir_ + "/kinema/preferences.json");
  EXPECT_EQ(saved["theme"], "light");
  EXPECT_EQ(saved["new_keys"]["interpolation"], "linear");
}

}  // namespace
}  // namespace kinema::test
