#pragma once
#include <optional>
#include <string>

namespace kinema {

// A key with the modifiers held with it, as a keymap binds it: a kinema::keys code
// (model/key_codes.h, GLFW's numbering) and InputMods bits (model/input_events.h). Matched
// exactly: Shift+A is not A.
struct KeyChord {
  int key = -1;  // -1: no key
  int mods = 0;  // kModShift | kModCtrl | kModAlt | kModSuper
  bool valid() const { return key >= 0; }
  bool operator==(const KeyChord& o) const { return key == o.key && mods == o.mods; }
  bool operator!=(const KeyChord& o) const { return !(*this == o); }
  bool operator<(const KeyChord& o) const { return key != o.key ? key < o.key : mods < o.mods; }
};

// As Blender writes chords: modifiers Ctrl, Shift, Alt, Super in that order, then the key:
// "Ctrl+Shift+Z", "Alt+R", "Numpad 1", "Shift+F6", "F1", "Space", "Left", "Esc". "" for an
// invalid chord or a key without a name.
std::string formatChord(KeyChord chord);
// The inverse, ignoring case and spaces around '+'. Also takes a script's GLFW key names
// ("KP_1", "ESCAPE") for the key. Modifier keys alone are not chords. nullopt when unparsable.
std::optional<KeyChord> parseChord(const std::string& text);
// The key's own name in chords ("Numpad 1", "Esc"), "" when it has none.
std::string chordKeyName(int key);

}  // namespace kinema
