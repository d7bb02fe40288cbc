#include "editor/commands/key_chord.h"

#include <cctype>
#include <vector>

#include "editor/model/input_events.h"
#include "editor/model/key_codes.h"
#include "io/text_file.h"

namespace kinema {

namespace {

struct NamedKey {
  int key;
  const char* name;
};

// Keys with a name other than their one character (letters and digits are handled by rule).
const NamedKey kNamedKeys[] = {
    {keys::SPACE, "Space"},        {keys::APOSTROPHE, "'"},         {keys::COMMA, ","},
    {keys::MINUS, "-"},            {keys::PERIOD, "."},             {keys::SLASH, "/"},
    {keys::SEMICOLON, ";"},        {keys::EQUAL, "="},              {keys::LEFT_BRACKET, "["},
    {keys::BACKSLASH, "\\"},       {keys::RIGHT_BRACKET, "]"},      {keys::GRAVE_ACCENT, "`"},
    {keys::ESCAPE, "Esc"},         {keys::ENTER, "Enter"},          {keys::TAB, "Tab"},
    {keys::BACKSPACE, "Backspace"}, {keys::INSERT, "Insert"},       {keys::DELETE, "Delete"},
    {keys::RIGHT, "Right"},        {keys::LEFT, "Left"},            {keys::DOWN, "Down"},
    {keys::UP, "Up"},              {keys::PAGE_UP, "Page Up"},      {keys::PAGE_DOWN, "Page Down"},
    {keys::HOME, "Home"},          {keys::END, "End"},              {keys::KP_DECIMAL, "Numpad ."},
    {keys::KP_DIVIDE, "Numpad /"}, {keys::KP_MULTIPLY, "Numpad *"}, {keys::KP_SUBTRACT, "Numpad -"},
    {keys::KP_ADD, "Numpad +"},    {keys::KP_ENTER, "Numpad Enter"}, {keys::KP_EQUAL, "Numpad ="},
    {keys::MENU, "Menu"},
};

struct Modifier {
  int bit;
  const char* name;
};
const Modifier kModifiers[] = {{kModCtrl, "Ctrl"}, {kModShift, "Shift"}, {kModAlt, "Alt"}, {kModSuper, "Super"}};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "numpad1" and "numpad 1" alike: the name without spaces, in lower case.
std::string squeezed(const std::string& s) {
  std::string out;
  for (char c : lower(s))
    if (c != ' ') out += c;
  return out;
}

int keyFromName(const std::string& text) {
  const std::string name = squeezed(text);
  if (name.empty()) return -1;
  for (int k = keys::A; k <= keys::Z; ++k)
    if (name == lower(chordKeyName(k))) return k;
  for (int k = keys::Num0; k <= keys::Num9; ++k)
    if (name == chordKeyName(k)) return k;
  for (int k = keys::KP_0; k <= keys::KP_9; ++k)
    if (name == squeezed(chordKeyName(k))) return k;
  for (int k = keys::F1; k <= keys::F25; ++k)
    if (name == lower(chordKeyName(k))) return k;
  for (const NamedKey& n : kNamedKeys)
    if (name == squeezed(n.name)) return n.key;
  if (name == "escape") return keys::ESCAPE;  // Blender's long names
  if (name == "return") return keys::ENTER;
  if (name == "del") return keys::DELETE;
  // A script's GLFW name ("KP_1", "ESCAPE", "PAGE_UP").
  std::string upper = trim(text);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const int glfw = keyCodeFromName(upper);
  return isModifierKey(glfw) ? -1 : glfw;
}

}  // namespace

std::string chordKeyName(int key) {
  if (key >= keys::A && key <= keys::Z) return std::string(1, char('A' + key - keys::A));
  if (key >= keys::Num0 && key <= keys::Num9) return std::string(1, char('0' + key - keys::Num0));
  if (key >= keys::KP_0 && key <= keys::KP_9) return "Numpad " + std::string(1, char('0' + key - keys::KP_0));
  if (key >= keys::F1 && key <= keys::F25) return "F" + std::to_string(key - keys::F1 + 1);
  for (const NamedKey& n : kNamedKeys)
    if (n.key == key) return n.name;
  return "";
}

std::string formatChord(KeyChord chord) {
  const std::string key = chord.valid() ? chordKeyName(chord.key) : "";
  if (key.empty()) return "";
  std::string out;
  for (const Modifier& m : kModifiers)
    if (chord.mods & m.bit) out += std::string(m.name) + "+";
  return out + key;
}

std::optional<KeyChord> parseChord(const std::string& text) {
  KeyChord chord;
  std::string rest = trim(text);
  // Modifiers are prefixes ending in '+'; what is left is the key, which may itself hold a
  // '+' ("Numpad +") or be one character ("-").
  for (bool found = true; found;) {
    found = false;
    for (const Modifier& m : kModifiers) {
      const std::string prefix = lower(m.name);
      if (lower(rest.substr(0, prefix.size())) != prefix) continue;
      const std::string after = trim(rest.substr(prefix.size()));
      if (after.size() < 2 || after[0] != '+') continue;
      chord.mods |= m.bit;
      rest = trim(after.substr(1));
      found = true;
    }
  }
  chord.key = keyFromName(rest);
  if (!chord.valid()) return std::nullopt;
  return chord;
}

}  // namespace kinema
