#include "io/bone_map_file.h"

#include "io/json_document.h"
#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

namespace {

// A joint by name, else the joint the humanoid reading gives a canonical bone name; -1.
int resolve(const BoneMapSide& side, const std::string& name) {
  const int j = side.skeleton->find(name);
  if (j >= 0) return j;
  if (!side.humanoid) return -1;
  const std::optional<HumanoidBone> bone = humanoidBoneFromString(name);
  return bone ? (*side.humanoid)[*bone] : -1;
}

}  // namespace

Result<BoneMap> parseBoneMapJson(const std::string& text, const std::string& source, const BoneMapSide& from,
                                 const BoneMapSide& to, const InputLimits& limits) {
  using R = Result<BoneMap>;
  nlohmann::ordered_json doc;
  const std::string syntax = parseJsonDocument(text, source, limits, doc);
  if (!syntax.empty()) return R::failure(syntax);
  if (!doc.is_object()) return R::failure(source + ": expected a JSON object from source joint names to target joint names");
  if (doc.empty()) return R::failure(source + ": the map pairs no joints");
  BoneMap map;
  std::vector<std::string> usedBy(to.skeleton->size());
  std::vector<char> sourceUsed(from.skeleton->size(), 0);
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string where = source + ": \"" + cutForMessage(it.key()) + "\": ";
    if (!it.value().is_string()) return R::failure(where + "expected a target joint name (a string)");
    const std::string targetName = it.value().get<std::string>();
    const int s = resolve(from, it.key());
    if (s < 0) return R::failure(where + from.label + " has no joint or humanoid bone named '" + cutForMessage(it.key()) + "'");
    const int t = resolve(to, targetName);
    if (t < 0) return R::failure(where + to.label + " has no joint or humanoid bone named '" + cutForMessage(targetName) + "'");
    if (sourceUsed[s]) return R::failure(where + "source joint '" + cutForMessage(from.skeleton->names[s]) + "' is mapped twice");
    if (!usedBy[t].empty())
      return R::failure(where + "target joint '" + cutForMessage(to.skeleton->names[t]) + "' is already mapped from '" + cutForMessage(usedBy[t]) + "'");
    sourceUsed[s] = 1;
    usedBy[t] = it.key();
    map.pairs.push_back({s, t});
  }
  std::sort(map.pairs.begin(), map.pairs.end(), [](const BonePair& a, const BonePair& b) { return a.target < b.target; });
  return map;
}

Result<BoneMap> loadBoneMapFile(const std::string& path, const BoneMapSide& from, const BoneMapSide& to,
                                const InputLimits& limits) {
  std::string text;
  const std::string error = readTextFile(path, text, limits.maxFileBytes);
  if (!error.empty()) return Result<BoneMap>::failure(error);
  return parseBoneMapJson(text, path, from, to, limits);
}

nlohmann::ordered_json boneMapJson(const BoneMap& map, const Skeleton& source, const Skeleton& target) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const BonePair& p : map.pairs) out[source.names[p.source]] = target.names[p.target];
  return out;
}

}  // namespace kinema
