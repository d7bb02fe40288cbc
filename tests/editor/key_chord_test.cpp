// Key chords as Blender writes them (commands/key_chord.h): formatting, parsing, and the
// round trip over every nameable key and modifier combination.
#include "editor/commands/key_chord.h"
#include "editor/model/input_events.h"
#include "editor/model/key_codes.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(KeyChord, FormatsAsBlenderWritesThem) {
  EXPECT_EQ(formatChord({keys::Z, kModCtrl | kModShift}), "Ctrl+Shift+Z");
  EXPECT_EQ(formatChord({keys::R, kModAlt}), "Alt+R");
  EXPECT_EQ(formatChord({keys::KP_1, 0}), "Numpad 1");
  EXPECT_EQ(formatChord({keys::KP_1, kModCtrl}), "Ctrl+Numpad 1");
  EXPECT_EQ(formatChord({keys::F6, kModShift}), "Shift+F6");
  EXPECT_EQ(formatChord({keys::F1, 0}), "F1");
  EXPECT_EQ(formatChord({keys::SPACE, 0}), "Space");
  EXPECT_EQ(formatChord({keys::LEFT, kModShift}), "Shift+Left");
  EXPECT_EQ(formatChord({keys::ESCAPE, 0}), "Esc");
  EXPECT_EQ(formatChord({keys::Num7, kModSuper | kModAlt}), "Alt+Super+7");
  EXPECT_EQ(formatChord({-1, kModCtrl}), "");
  EXPECT_EQ(formatChord({keys::LEFT_SHIFT, 0}), "") << "a modifier key alone has no chord name";
}

TEST(KeyChord, FormatThenParseGivesTheChordBackForEveryNamedKey) {
  int named = 0;
  for (int key = 0; key <= keys::LAST; ++key) {
    if (chordKeyName(key).empty()) continue;
    ++named;
    for (int mods = 0; mods < 16; ++mods) {
      const KeyChord chord{key, mods};
      const std::string text = formatChord(chord);
      const std::optional<KeyChord> back = parseChord(text);
      ASSERT_TRUE(back.has_value()) << text;
      EXPECT_EQ(*back, chord) << text;
    }
  }
  EXPECT_GE(named, 26 + 10 + 10 + 25 + 30);  // letters, digits, numpad digits, F keys, named keys
}

TEST(KeyChord, ParsesAnyCaseSpacesAndScriptKeyNames) {
  EXPECT_EQ(parseChord("ctrl + shift + z"), (KeyChord{keys::Z, kModCtrl | kModShift}));
  EXPECT_EQ(parseChord("Shift+Ctrl+Z"), (KeyChord{keys::Z, kModCtrl | kModShift})) << "modifiers in any order";
  EXPECT_EQ(parseChord("numpad1"), (KeyChord{keys::KP_1, 0}));
  EXPECT_EQ(parseChord("KP_1"), (KeyChord{keys::KP_1, 0}));
  EXPECT_EQ(parseChord("Alt+ESCAPE"), (KeyChord{keys::ESCAPE, kModAlt}));
  EXPECT_EQ(parseChord("Escape"), (KeyChord{keys::ESCAPE, 0}));
  EXPECT_EQ(parseChord("Return"), (KeyChord{keys::ENTER, 0}));
  EXPECT_EQ(parseChord("Ctrl+Numpad +"), (KeyChord{keys::KP_ADD, kModCtrl}));
  EXPECT_EQ(parseChord("Ctrl+-"), (KeyChord{keys::MINUS, kModCtrl}));
  EXPECT_EQ(parseChord("page down"), (KeyChord{keys::PAGE_DOWN, 0}));
  for (const char* bad : {"", "Ctrl+", "Shift", "LEFT_SHIFT", "Hyper+A", "Ctrl+Foo", "F26", "Ctrl++", "AB"})
    EXPECT_FALSE(parseChord(bad).has_value()) << "'" << bad << "'";
}

}  // namespace
}  // namespace kinema::test
