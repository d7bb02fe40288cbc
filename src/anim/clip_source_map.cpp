#include "anim/clip_source_map.h"

#include <unordered_set>

namespace kinema {

std::string ClipSourceMap::validate(int jointCount) const {
  if (clip < 0) return "the source clip index must not be negative";
  if (pairs.empty() && (!file.empty() || clip != 0)) return "a bone map needs at least one pair";
  std::unordered_set<std::string> sources;
  std::unordered_set<int> targets;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const SourceMapPair& p = pairs[i];
    const std::string where = "bone map pair " + std::to_string(i);
    if (p.source.empty()) return where + " has an empty source joint name";
    if (p.target < 0 || p.target >= jointCount)
      return where + " drives joint " + std::to_string(p.target) + ", which does not exist";
    if (!sources.insert(p.source).second) return where + ": source joint '" + p.source + "' is mapped twice";
    if (!targets.insert(p.target).second) return where + ": target joint " + std::to_string(p.target) + " is mapped twice";
  }
  return {};
}

}  // namespace kinema
