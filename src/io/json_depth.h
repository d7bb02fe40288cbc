#pragma once
#include <cstddef>

namespace kinema {

// The deepest nesting of [ and { outside strings. Readers scan it before parsing so that a
// file of a million '[' is refused before a JSON library builds (or recurses into) anything.
int jsonNestingDepth(const char* text, size_t size);

}  // namespace kinema
