#pragma once
#include <functional>
#include <string>

namespace kinema {

// The longest start of `text` that, followed by "…", fits in `maxWidth` as measured by
// `width` (pixels of a string in the UI font); `text` itself when it fits. Cuts between
// UTF-8 characters, never inside one, and drops trailing spaces before the ellipsis.
// "…" alone (or "" when not even that fits) for a very narrow width.
// `ellipsis`: "…" by default; "..." for a font without it.
std::string elideText(const std::string& text, float maxWidth, const std::function<float(const std::string&)>& width,
                      const std::string& ellipsis = "\xE2\x80\xA6");

}  // namespace kinema
