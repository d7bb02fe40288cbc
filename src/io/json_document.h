#pragma once
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "io/input_limits.h"

namespace kinema {

// Parses JSON text into a tree with the tree's memory counted before it is built: a first
// pass counts values, containers and string bytes without allocating, and text whose tree
// would take more than jsonTreeBudgetBytes (InputLimits) is refused, as is nesting deeper
// than InputLimits::maxJsonDepth. A 200 MB file of "0,0,0,..." would otherwise need 3 GB
// as nlohmann values. Returns "" or a one-line error "SOURCE: line L, column C: what"
// (syntax) or "SOURCE: ... (InputLimits::field)" (limits).
std::string parseJsonDocument(const std::string& text, const std::string& source, const InputLimits& limits,
                              nlohmann::ordered_json& out);

// What the tree of `text` would take in memory, in bytes (an estimate from the count pass,
// an upper bound for glibc's allocator on 64-bit); 0 when the text is not valid JSON.
size_t jsonTreeBytes(const char* text, size_t size);

}  // namespace kinema
