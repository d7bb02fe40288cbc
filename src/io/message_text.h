#pragma once
#include <cstddef>
#include <string>

namespace kinema {

// Error messages are one line of at most kMaxMessageBytes bytes (docs/cli.md): text a file
// supplies (a token, a joint name, a library's exception) is cut before it is echoed.
constexpr size_t kMaxMessageBytes = 300;

// `text` for quoting inside a message: control characters shown as \xNN, and cut to at most
// `maxBytes` bytes (never inside a UTF-8 sequence) with "…" when longer.
std::string cutForMessage(const std::string& text, size_t maxBytes = 48);

// A whole message as one line (line breaks become spaces, other control characters \xNN)
// of at most kMaxMessageBytes bytes, the end cut with "…" when longer.
std::string oneLineMessage(const std::string& message);

}  // namespace kinema
