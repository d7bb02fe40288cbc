#pragma once
// Reading an L-system grammar file (the format is sim/lsystem_grammar.h's).
#include <string>

#include "core/result.h"
#include "sim/lsystem_grammar.h"

namespace kinema {

// Reads and parses the grammar file at `path` (at most 16 MiB): errors name the file and line.
Result<LSystemGrammar> loadLSystemGrammar(const std::string& path);

}  // namespace kinema
