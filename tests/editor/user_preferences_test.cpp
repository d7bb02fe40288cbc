// Edit > Preferences' file (user_preferences.h): the JSON round trip, bad files reported and
// never fatal, the presentation preset, and where the window opens.
#include <gtest/gtest.h>

#include <filesystem>

#include "editor/model/editor_state.h"
#include "editor/model/user_preferences.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

UserPreferences everythingChanged() {
  UserPreferences p;
  p.uiScale = 1.75f;
  p.lineScale = 3.0f;
  p.theme = UiTheme::Light;
  p.loop = false;
  p.keys.interpolation = Interpolation::Step;
  p.keys.handles = HandleType::Vector;
  p.keys.locRotOnly = true;
  p.panels.leftWidth = 180.5f;
  p.panels.rightWidth = 400.0f;
  p.panels.outlinerFraction = 0.3f;
  p.panels.propertiesFraction = 0.7f;
  p.panels.animationEditorHeight = 333.0f;
  p.window = {12, -34, 1500, 950, true};
  return p;
}

TEST(UserPreferences, EveryFieldSurvivesTheFileRoundTrip) {
  const std::string dir = test::makeTempDir();
  const std::string path = dir + "/deeper/kinema/preferences.json";  // the folder is created
  const UserPreferences p = everythingChanged();
  ASSERT_NE(p, UserPreferences{});
  ASSERT_EQ(saveUserPreferences(p, path), "");
  std::vector<std::string> problems;
  const UserPreferences back = loadUserPreferences(problems, path);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(back, p);
  EXPECT_EQ(back.uiScale, 1.75f);
  EXPECT_EQ(back.theme, UiTheme::Light);
  EXPECT_EQ(back.keys.interpolation, Interpolation::Step);
  EXPECT_EQ(back.window.y, -34);
}

TEST(UserPreferences, AMissingFileIsTheDefaultsWithoutComplaint) {
  std::vector<std::string> problems;
  EXPECT_EQ(loadUserPreferences(problems, test::makeTempDir() + "/none.json"), UserPreferences{});
  EXPECT_TRUE(problems.empty());
}

TEST(UserPreferences, ABadFileIsReportedAndTheDefaultsUsed) {
  std::vector<std::string> problems;
  const UserPreferences p = parsePreferences("{ not json", "prefs.json", problems);
  EXPECT_EQ(p, UserPreferences{});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].rfind("prefs.json: ", 0), 0u) << problems[0];
}

TEST(UserPreferences, BadMembersAreReportedOneByOneAndTheGoodOnesKept) {
  std::vector<std::string> problems;
  const UserPreferences p = parsePreferences(
      R"({"ui_scale": 9, "theme": "neon", "loop": false, "line_scale": "thick",
          "new_keys": {"interpolation": "linear", "handles": 3},
          "panels": {"left_width": 300}, "window": {"width": 800, "height": 600}, "future": 1})",
      "p.json", problems);
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_EQ(problems[0], "p.json: ui_scale: expected a number from 0.75 to 3");
  EXPECT_NE(problems[1].find("line_scale"), std::string::npos) << problems[1];
  EXPECT_NE(problems[2].find("theme: unknown value \"neon\""), std::string::npos) << problems[2];
  EXPECT_NE(problems[3].find("new_keys.handles"), std::string::npos) << problems[3];
  EXPECT_EQ(p.uiScale, 1.0f);  // the defaults where the file was wrong
  EXPECT_EQ(p.theme, UiTheme::Dark);
  EXPECT_EQ(p.lineScale, 1.0f);
  EXPECT_EQ(p.keys.handles, HandleType::AutoClamped);
  EXPECT_FALSE(p.loop);  // the file's where it was right
  EXPECT_EQ(p.keys.interpolation, Interpolation::Linear);
  EXPECT_EQ(p.panels.leftWidth, 300.0f);
  EXPECT_EQ(p.panels.rightWidth, PanelSizes{}.rightWidth);
  EXPECT_EQ(p.window.width, 800);
  EXPECT_FALSE(p.window.positioned);
}

TEST(UserPreferences, TheFileLivesInTheConfigFolder) {
  const std::string xdg = test::makeTempDir();
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_CONFIG_HOME", xdg.c_str(), 1);
  EXPECT_EQ(userPreferencesPath(), xdg + "/kinema/preferences.json");
  if (old) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
  else unsetenv("XDG_CONFIG_HOME");
}

TEST(UserPreferences, PresentationDoublesTheTextAndThickensLinesAndDeskUndoesIt) {
  const UserPreferences base = everythingChanged();
  const UserPreferences shown = presentationPreset(base);
  EXPECT_EQ(shown.uiScale, 2.0f);
  EXPECT_GT(shown.lineScale, 1.0f);
  EXPECT_TRUE(isPresentation(shown));
  EXPECT_FALSE(isPresentation(UserPreferences{}));
  EXPECT_EQ(shown.theme, base.theme);  // the rest is left as it was
  EXPECT_EQ(shown.panels, base.panels);
  const UserPreferences desk = deskPreset(shown);
  EXPECT_EQ(desk.uiScale, 1.0f);
  EXPECT_EQ(desk.lineScale, 1.0f);
}

TEST(UserPreferences, TheSessionsLoopAndKeyDefaultsAreTheOnesSaved) {
  EditorState state;
  UserPreferences p;
  p.loop = false;
  p.keys.interpolation = Interpolation::Linear;
  p.uiScale = 1.5f;
  applyPreferences(state, p);
  EXPECT_FALSE(state.loop);
  EXPECT_EQ(state.doc.autoKey.preferences.interpolation, Interpolation::Linear);
  state.loop = true;  // the timeline's switch
  state.doc.autoKey.preferences.interpolation = Interpolation::Step;  // its Keys popup
  const UserPreferences now = currentPreferences(state);
  EXPECT_TRUE(now.loop);
  EXPECT_EQ(now.keys.interpolation, Interpolation::Step);
  EXPECT_EQ(now.uiScale, 1.5f);
}

TEST(WindowPlacement, DefaultIsMostOfTheScreenCentred) {
  const ScreenArea screen{0, 0, 1600, 1000};
  const WindowPlacement p = initialWindowPlacement(WindowPlacement{}, screen);
  EXPECT_EQ(p.width, 1440);
  EXPECT_EQ(p.height, 900);
  EXPECT_TRUE(p.positioned);
  EXPECT_EQ(p.x, 80);
  EXPECT_EQ(p.y, 50);
}

TEST(WindowPlacement, RememberedSizeAndPlaceButNeverLargerThanTheScreen) {
  const ScreenArea screen{0, 30, 1600, 970};  // a top bar takes 30 px
  EXPECT_EQ(initialWindowPlacement({100, 130, 1000, 700, true}, screen), (WindowPlacement{100, 130, 1000, 700, true}));
  const WindowPlacement big = initialWindowPlacement({50, 40, 3000, 2000, true}, screen);
  EXPECT_EQ(big.width, 1600);
  EXPECT_EQ(big.height, 970);
  EXPECT_EQ(big.x, 0);  // it does not fit where it was: on the work area
  EXPECT_EQ(big.y, 30);
  const WindowPlacement off = initialWindowPlacement({5000, 100, 800, 600, true}, screen);  // a monitor now gone
  EXPECT_EQ(off.x, 400);
  EXPECT_EQ(off.y, 30 + 185);
}

TEST(WindowPlacement, UnknownScreenKeepsTheRememberedSize) {
  EXPECT_EQ(initialWindowPlacement({0, 0, 900, 500, false}, ScreenArea{}), (WindowPlacement{0, 0, 900, 500, false}));
  EXPECT_EQ(initialWindowPlacement(WindowPlacement{}, ScreenArea{}).width, 1280);
}

}  // namespace
}  // namespace kinema
