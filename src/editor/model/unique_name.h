#pragma once
// Names for new items (clips, deformers, particle systems), as Blender gives them.
#include <functional>
#include <string>

namespace kinema {

// `base` when `taken` says it is free, else base.001, base.002, ... the first free one. A
// base that already ends in .NNN counts from its stem ("Walk.001" duplicated: "Walk.002").
std::string uniqueName(const std::string& base, const std::function<bool(const std::string&)>& taken);

}  // namespace kinema
