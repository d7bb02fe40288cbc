#include "io/message_text.h"

#include <algorithm>

namespace kinema {

namespace {

const char kEllipsis[] = "\xe2\x80\xa6";  // "…", 3 bytes of UTF-8

// Appends `c` to `out`, a control character as \xNN (or a space for line breaks when asked).
void appendVisible(std::string& out, char c, bool breaksAsSpace) {
  const auto u = static_cast<unsigned char>(c);
  if (breaksAsSpace && (c == '\n' || c == '\r')) {
    out += ' ';
  } else if (u < 0x20 || u == 0x7f) {
    static const char hex[] = "0123456789abcdef";
    out += "\\x";
    out += hex[u >> 4];
    out += hex[u & 0xf];
  } else {
    out += c;
  }
}

// Cuts `s` to at most `maxBytes` bytes with an ellipsis, at a UTF-8 character boundary.
std::string cutAtBoundary(std::string s, size_t maxBytes) {
  if (s.size() <= maxBytes) return s;
  size_t keep = maxBytes >= 3 ? maxBytes - 3 : 0;
  while (keep > 0 && (static_cast<unsigned char>(s[keep]) & 0xC0) == 0x80) --keep;  // not mid-character
  s.resize(keep);
  return s + kEllipsis;
}

}  // namespace

std::string cutForMessage(const std::string& text, size_t maxBytes) {
  std::string out;
  // Escaping at most quadruples a byte; looking further than that cannot change the result.
  const size_t look = std::min(text.size(), maxBytes + 4);
  for (size_t i = 0; i < look; ++i) appendVisible(out, text[i], false);
  if (text.size() > look) out += "...";  // forces the cut below
  return cutAtBoundary(out, maxBytes);
}

std::string oneLineMessage(const std::string& message) {
  std::string out;
  const size_t look = std::min(message.size(), kMaxMessageBytes + 4);
  for (size_t i = 0; i < look; ++i) appendVisible(out, message[i], true);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  if (message.size() > look) out += "...";
  return cutAtBoundary(out, kMaxMessageBytes);
}

}  // namespace kinema
