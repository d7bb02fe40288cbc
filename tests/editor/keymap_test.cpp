// The keymap (commands/keymap.h): defaults from the registry, a user file's overrides,
// unbinding, and bad lines reported by line number while the rest applies.
#include <cstdlib>

#include "editor/commands/keymap.h"
#include "editor/model/input_events.h"
#include "editor/model/key_codes.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

const KeyChord kR{keys::R, 0}, kShiftR{keys::R, kModShift}, kCtrlZ{keys::Z, kModCtrl};

TEST(Keymap, StartsFromTheRegistrysDefaults) {
  const Keymap keymap;
  EXPECT_EQ(keymap.chords("tool.rotate"), std::vector<KeyChord>{kR});
  EXPECT_EQ(keymap.shortcut("edit.redo"), "Ctrl+Shift+Z");
  EXPECT_EQ(keymap.shortcuts("edit.redo"), "Ctrl+Shift+Z, Ctrl+Y");
  ASSERT_NE(keymap.holder(CommandScope::Viewport, kR), nullptr);
  EXPECT_EQ(keymap.holder(CommandScope::Viewport, kR)->id, "tool.rotate");
  EXPECT_EQ(keymap.holder(CommandScope::Global, kR), nullptr) << "R is the 3D view's";
  EXPECT_EQ(keymap.holder(CommandScope::Compare, kR)->id, "compare.reset");
}

TEST(Keymap, AGoodOverrideRebindsAndLaterLinesAddChords) {
  Keymap keymap;
  const std::vector<std::string> problems =
      keymap.apply("# my keys\ntool.rotate = Shift+R   # Blender users beware\ntool.rotate = F9\n", "keymap.txt");
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(keymap.chords("tool.rotate"), (std::vector<KeyChord>{kShiftR, KeyChord{keys::F9, 0}}));
  EXPECT_EQ(keymap.holder(CommandScope::Viewport, kR), nullptr) << "the default R is replaced";
  EXPECT_EQ(keymap.holder(CommandScope::Viewport, kShiftR)->id, "tool.rotate");
  EXPECT_EQ(keymap.shortcut("tool.rotate"), "Shift+R");
}

TEST(Keymap, NoneUnbindsAndFreesTheChordForAnotherCommand) {
  Keymap keymap;
  const std::vector<std::string> problems = keymap.apply("tool.rotate = none\nselect.all = R\n", "k.txt");
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_TRUE(keymap.chords("tool.rotate").empty());
  EXPECT_EQ(keymap.shortcut("tool.rotate"), "");
  EXPECT_EQ(keymap.holder(CommandScope::Viewport, kR)->id, "select.all");
}

TEST(Keymap, BadLinesAreReportedWithTheirLineNumberAndIgnoredWhileLaterLinesApply) {
  Keymap keymap;
  const std::vector<std::string> problems = keymap.apply(
      "# comments and blank lines count as lines\n"
      "\n"
      "tool.spin = R\n"                // 3: no such command
      "edit.undo = Ctrl+Banana\n"      // 4: no such key
      "edit.redo = Ctrl+Z\n"           // 5: undo holds Ctrl+Z (both Global)
      "just some words\n"              // 6: not a binding
      "tool.grab = Shift+G\n",         // 7: fine
      "/home/me/.config/kinema/keymap.txt");
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_EQ(problems[0].rfind("/home/me/.config/kinema/keymap.txt:3: unknown command 'tool.spin'", 0), 0u) << problems[0];
  EXPECT_EQ(problems[1].rfind("/home/me/.config/kinema/keymap.txt:4: 'Ctrl+Banana' is not a key chord", 0), 0u)
      << problems[1];
  EXPECT_EQ(problems[2], "/home/me/.config/kinema/keymap.txt:5: Ctrl+Z is already bound to edit.undo (Everywhere)");
  EXPECT_EQ(problems[3].rfind("/home/me/.config/kinema/keymap.txt:6: expected 'command.id = Chord'", 0), 0u) << problems[3];
  // The refused lines changed nothing; the good one after them applied.
  EXPECT_EQ(keymap.holder(CommandScope::Global, kCtrlZ)->id, "edit.undo");
  EXPECT_EQ(keymap.shortcuts("edit.redo"), "Ctrl+Shift+Z, Ctrl+Y");
  EXPECT_EQ(keymap.shortcut("tool.grab"), "Shift+G");
}

TEST(Keymap, TheSameChordMayServeTwoScopes) {
  // Home frames the 3D view, the dope sheet and the curve editor, each over its own area.
  const Keymap keymap;
  const KeyChord home{keys::HOME, 0};
  EXPECT_EQ(keymap.holder(CommandScope::Viewport, home)->id, "view.frame_all");
  EXPECT_EQ(keymap.holder(CommandScope::DopeSheet, home)->id, "dopesheet.frame_all");
  EXPECT_EQ(keymap.holder(CommandScope::CurveEditor, home)->id, "curves.frame_all");
  Keymap mine;
  EXPECT_TRUE(mine.apply("dopesheet.frame_all = F\n", "k").empty()) << "F is the 3D view's, not the dope sheet's";
}

// Sets an environment variable for one test, restoring it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) had_ = true, old_ = old;
    if (value) setenv(name, value, 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (had_) setenv(name_, old_.c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  bool had_ = false;
  std::string old_;
};

TEST(Keymap, TheUserFileLivesInTheXdgConfigFolderOrUnderHome) {
  const std::string xdg = makeTempDir(), home = makeTempDir();
  runCommand("mkdir -p '" + xdg + "/kinema' '" + home + "/.config/kinema'");
  writeFile(xdg + "/kinema/keymap.txt", "tool.rotate = Shift+R\ntool.rotate = Ctrl+Q\n");
  writeFile(home + "/.config/kinema/keymap.txt", "tool.grab = Shift+G\n");
  {
    ScopedEnv a("XDG_CONFIG_HOME", xdg.c_str()), b("HOME", home.c_str());
    EXPECT_EQ(userKeymapPath(), xdg + "/kinema/keymap.txt");
    std::vector<std::string> problems;
    const Keymap keymap = loadUserKeymap(editorCommands(), problems);
    EXPECT_EQ(keymap.shortcut("tool.rotate"), "Shift+R");
    EXPECT_EQ(keymap.shortcut("tool.grab"), "G");
    ASSERT_EQ(problems.size(), 0u) << "Ctrl+Q is the quit key, but quit is Global and rotate the 3D view's";
  }
  {
    ScopedEnv a("XDG_CONFIG_HOME", nullptr), b("HOME", home.c_str());
    EXPECT_EQ(userKeymapPath(), home + "/.config/kinema/keymap.txt");
    std::vector<std::string> problems;
    const Keymap keymap = loadUserKeymap(editorCommands(), problems);
    EXPECT_EQ(keymap.shortcut("tool.grab"), "Shift+G");
    EXPECT_EQ(keymap.shortcut("tool.rotate"), "R");
    EXPECT_TRUE(problems.empty());
  }
  {
    ScopedEnv a("XDG_CONFIG_HOME", nullptr), b("HOME", (home + "/nowhere").c_str());
    std::vector<std::string> problems;
    const Keymap keymap = loadUserKeymap(editorCommands(), problems);  // no file: the defaults, no problem
    EXPECT_EQ(keymap.shortcut("tool.grab"), "G");
    EXPECT_TRUE(problems.empty());
  }
  writeFile(xdg + "/kinema/keymap.txt", "tool.grab = Ctrl+Shift+Banana\n");
  {
    ScopedEnv a("XDG_CONFIG_HOME", xdg.c_str());
    std::vector<std::string> problems;
    loadUserKeymap(editorCommands(), problems);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind(xdg + "/kinema/keymap.txt:1: ", 0), 0u) << problems[0];
  }
  runCommand("rm -rf '" + xdg + "' '" + home + "'");
}

}  // namespace
}  // namespace kinema::test
