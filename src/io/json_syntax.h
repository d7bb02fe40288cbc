#pragma once
#include <cstddef>
#include <string>

namespace kinema {

// Why `text` is not valid JSON, readable in one line: "line L, column C: unexpected ','"
// (lines and columns from 1, counted in bytes), or "" when it is valid. Readers use it
// instead of a JSON library's raw exception text, which names the library's internals and
// can echo the file's binary bytes.
std::string jsonSyntaxError(const char* text, size_t size);

}  // namespace kinema
