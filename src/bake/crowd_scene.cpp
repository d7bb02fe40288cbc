#include "bake/crowd_scene.h"

#include <cmath>
#include <filesystem>

#include "evaluation/scene_poses.h"
#include "io/scene_files.h"

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
  // The members move as the character's scene plays (keyed IK targets, modifiers), not as its
  // bare keys; each member has its own clip time, so the live chains are left out.
  EvaluationStages stages;
  stages.dynamics = false;
  ScenePoses poses(character, crowd.clip, stages);
  bake.motion = analyseCrowdClip(character.skeleton, clip, crowd, &poses);
  Result<CrowdRun> run = runCrowd(crowd, bake.motion, character.frameGrid(crowd.clip).secondsPerFrame, last + 1);
  if (!run) return Result<CrowdBake>::failure(run.error());
  bake.run = std::move(run.value());
  bake.clips.reserve(static_cast<size_t>(crowd.members));
  for (int m = 0; m < crowd.members; ++m)
    bake.clips.push_back(bakeCrowdMember(character.skeleton, clip, bake.motion, bake.run, m, first, last,
                                         crowdMemberName(crowd.name, m), &poses));
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

void appendCrowdObstacles(Scene& out, const CrowdSettings& crowd) {
  const BoidsSettings& b = crowd.boids;
  if (b.spheres.empty() && b.boxes.empty()) return;
  MeshPrimitive p;
  auto vertex = [&](const glm::vec3& position, const glm::vec3& normal) {
    p.positions.push_back(position);
    p.normals.push_back(normal);
    return static_cast<uint32_t>(p.positions.size() - 1);
  };
  constexpr int kRings = 16, kSegments = 32;
  for (const BoidSphere& s : b.spheres) {
    const uint32_t base = static_cast<uint32_t>(p.positions.size());
    for (int r = 0; r <= kRings; ++r) {
      const float theta = 3.14159265f * static_cast<float>(r) / kRings;
      for (int k = 0; k <= kSegments; ++k) {
        const float phi = 6.28318531f * static_cast<float>(k) / kSegments;
        const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        vertex(s.centre + s.radius * n, n);
      }
    }
    for (int r = 0; r < kRings; ++r)
      for (int k = 0; k < kSegments; ++k) {
        const uint32_t a = base + static_cast<uint32_t>(r * (kSegments + 1) + k), c = a + kSegments + 1;
        p.indices.insert(p.indices.end(), {a, a + 1, c, a + 1, c + 1, c});
      }
  }
  for (const BoidBox& x : b.boxes) {
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {  // a face of 4 vertices with its own normal
        glm::vec3 n(0.0f);
        n[axis] = side ? 1.0f : -1.0f;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        uint32_t q[4];
        for (int corner = 0; corner < 4; ++corner) {
          glm::vec3 at;
          at[axis] = side ? x.max[axis] : x.min[axis];
          at[u] = (corner == 1 || corner == 2) ? x.max[u] : x.min[u];
          at[v] = corner >= 2 ? x.max[v] : x.min[v];
          q[corner] = vertex(at, n);
        }
        // Counter-clockwise seen from outside: flip the winding on the negative sides.
        if (side) p.indices.insert(p.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
        else p.indices.insert(p.indices.end(), {q[0], q[2], q[1], q[0], q[3], q[2]});
      }
  }
  Material sand;
  sand.name = crowd.name + "_obstacles";
  sand.baseColor = glm::vec4(0.85f, 0.72f, 0.35f, 1.0f);
  p.material = static_cast<int>(out.materials.size());
  out.materials.push_back(sand);
  Mesh mesh;
  mesh.name = crowd.name + "_obstacles";
  mesh.primitives.push_back(std::move(p));
  out.meshes.push_back(std::move(mesh));
  MeshInstance instance;
  instance.joint = out.skeleton.addJoint(crowd.name + "_obstacles", -1, Transform::identity());
  instance.mesh = static_cast<int>(out.meshes.size()) - 1;
  out.meshInstances.push_back(instance);
}

}  // namespace kinema
