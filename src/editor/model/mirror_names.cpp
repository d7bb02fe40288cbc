#include "editor/model/mirror_names.h"

#include <cctype>

namespace kinema {

namespace {

bool isSeparator(char c) { return c == '.' || c == '_' || c == '-' || c == ' '; }

char flipLetter(char c) {
  switch (c) {
    case 'L': return 'R';
    case 'R': return 'L';
    case 'l': return 'r';
    case 'r': return 'l';
    default: return 0;
  }
}

// "Left" -> "Right" keeping the word's case style (left, Left, LEFT).
std::string flipWord(const std::string& word) {
  const bool left = word.size() == 4;
  const std::string lower = left ? "right" : "left";
  std::string out;
  const bool allUpper = std::isupper(static_cast<unsigned char>(word[0])) &&
                        std::isupper(static_cast<unsigned char>(word[1]));
  for (size_t i = 0; i < lower.size(); ++i) {
    const bool upper = allUpper || (i == 0 && std::isupper(static_cast<unsigned char>(word[0])));
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(lower[i]))) : lower[i];
  }
  return out;
}

bool equalsNoCase(const std::string& s, size_t at, const char* word) {
  for (size_t i = 0; word[i]; ++i) {
    if (at + i >= s.size()) return false;
    if (std::tolower(static_cast<unsigned char>(s[at + i])) != word[i]) return false;
  }
  return true;
}

std::string flipBody(const std::string& s) {
  const size_t n = s.size();
  if (n < 2) return "";
  // Single letter suffix after a separator ("Hand.L") or prefix before one ("L_Hand").
  if (isSeparator(s[n - 2]) && flipLetter(s[n - 1])) return s.substr(0, n - 1) + flipLetter(s[n - 1]);
  if (isSeparator(s[1]) && flipLetter(s[0])) return std::string(1, flipLetter(s[0])) + s.substr(1);
  // Whole words as a prefix or a suffix ("LeftHand", "hand_right").
  for (const char* word : {"right", "left"}) {
    const size_t len = std::string(word).size();
    if (n > len && equalsNoCase(s, 0, word)) return flipWord(s.substr(0, len)) + s.substr(len);
    if (n > len && equalsNoCase(s, n - len, word)) return s.substr(0, n - len) + flipWord(s.substr(n - len));
  }
  return "";
}

}  // namespace

std::string mirroredJointName(const std::string& name) {
  // Keep a Blender-style number suffix ("Hand.L.001").
  size_t end = name.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
  if (end < name.size() && end > 0 && name[end - 1] == '.') {
    const std::string flipped = flipBody(name.substr(0, end - 1));
    return flipped.empty() ? "" : flipped + name.substr(end - 1);
  }
  return flipBody(name);
}

}  // namespace kinema
