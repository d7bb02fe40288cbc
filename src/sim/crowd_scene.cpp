#include "sim/crowd_scene.h"

#include <filesystem>

namespace kinema {

Result<Scene> loadCrowdCharacter(const CrowdSettings& crowd, const Scene& own, const std::string& ownSource,
                                 const InputLimits& limits) {
  Scene character;
  if (crowd.character.empty()) {
    character = own;
  } else {
    namespace fs = std::filesystem;
    const fs::path path = fs::path(crowd.character).is_absolute()
                              ? fs::path(crowd.character)
                              : fs::path(ownSource).parent_path() / fs::path(crowd.character);
    Result<Scene> loaded = loadScene(path.string(), limits);
    if (!loaded) return Result<Scene>::failure("crowd '" + crowd.name + "': character: " + loaded.error());
    character = std::move(loaded.value());
  }
  if (crowd.clip >= static_cast<int>(character.clips.size()))
    return Result<Scene>::failure("crowd '" + crowd.name + "': its character has no clip " + std::to_string(crowd.clip) +
                                  " (it has " + std::to_string(character.clips.size()) + ")");
  return character;
}

Result<CrowdBake> bakeCrowd(const CrowdSettings& crowd, const Scene& character, long long first, long long last) {
  if (crowd.clip < 0 || crowd.clip >= static_cast<int>(character.clips.size()))
    return Result<CrowdBake>::failure("crowd '" + crowd.name + "': its character has no clip " + std::to_string(crowd.clip));
  if (first < 0 || last < first) return Result<CrowdBake>::failure("crowd '" + crowd.name + "': bad frame range");
  const Clip& clip = character.clips[static_cast<size_t>(crowd.clip)];
  CrowdBake bake;
  bake.motion = analyseCrowdClip(character.skeleton, clip, crowd);
  Result<CrowdRun> run = runCrowd(crowd, bake.motion, clip.secondsPerFrame(), last + 1);
  if (!run) return Result<CrowdBake>::failure(run.error());
  bake.run = std::move(run.value());
  bake.clips.reserve(static_cast<size_t>(crowd.members));
  for (int m = 0; m < crowd.members; ++m)
    bake.clips.push_back(bakeCrowdMember(character.skeleton, clip, bake.motion, bake.run, m, first, last,
                                         crowdMemberName(crowd.name, m)));
  return bake;
}

void appendCrowdCharacters(Scene& out, const CrowdSettings& crowd, const Scene& character, const CrowdBake& bake) {
  const Skeleton& s = character.skeleton;
  if (out.clips.empty()) {
    Clip clip;
    clip.name = "crowd";
    clip.frameTime = bake.run.dt;
    out.clips.push_back(clip);
  }
  const int meshBase = static_cast<int>(out.meshes.size());
  const int materialBase = static_cast<int>(out.materials.size());
  const int imageBase = static_cast<int>(out.images.size());
  for (Material m : character.materials) {
    if (m.baseColorImage >= 0) m.baseColorImage += imageBase;
    out.materials.push_back(std::move(m));
  }
  out.images.insert(out.images.end(), character.images.begin(), character.images.end());
  for (Mesh mesh : character.meshes) {
    for (MeshPrimitive& p : mesh.primitives)
      if (p.material >= 0) p.material += materialBase;
    out.meshes.push_back(std::move(mesh));
  }
  out.nodeOfJoint.clear();  // the joints are the crowd's now, not a file's nodes
  out.nodeNames.clear();
  for (size_t m = 0; m < bake.clips.size(); ++m) {
    const std::string prefix = crowdMemberName(crowd.name, static_cast<int>(m)) + "/";
    const int base = out.skeleton.size();
    for (int j = 0; j < s.size(); ++j)
      out.skeleton.addJoint(prefix + s.names[j], s.parents[j] < 0 ? -1 : base + s.parents[j], s.rest[j]);
    const int skinBase = static_cast<int>(out.skins.size());
    for (Skin skin : character.skins) {
      skin.name = prefix + skin.name;
      for (int& j : skin.joints) j += base;
      if (skin.skeletonRoot >= 0) skin.skeletonRoot += base;
      out.skins.push_back(std::move(skin));
    }
    for (MeshInstance mi : character.meshInstances) {
      mi.joint += base;
      mi.mesh += meshBase;
      if (mi.skin >= 0) mi.skin += skinBase;
      out.meshInstances.push_back(std::move(mi));
    }
    for (Channel c : bake.clips[m].channels) {
      c.joint += base;
      out.clips[0].channels.push_back(std::move(c));
    }
  }
}

}  // namespace kinema
