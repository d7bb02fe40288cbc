#include "io/lsystem_grammar_file.h"

#include "io/text_file.h"

namespace kinema {

Result<LSystemGrammar> loadLSystemGrammar(const std::string& path) {
  std::string text;
  if (std::string bad = readTextFile(path, text, size_t(16) << 20); !bad.empty())
    return Result<LSystemGrammar>::failure(bad);
  return parseLSystemGrammar(text, path);
}

}  // namespace kinema
