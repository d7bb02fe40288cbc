#pragma once
#include <string>

namespace kinema {

// Writes `contents` to `path` without ever destroying the previous file: the data goes
// to a temporary file in the same folder, is flushed to disk, then renamed over `path`.
// On any failure the temporary file is removed and `path` is untouched.
// Returns an empty string on success, or "PATH: reason".
std::string writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace kinema
