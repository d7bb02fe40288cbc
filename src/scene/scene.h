#pragma once
#include <optional>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/result.h"
#include "core/mesh.h"
#include "core/pose.h"
#include "core/skeleton.h"
#include "deform/deformer_stack.h"
#include "ik/ik_rig.h"
#include "sim/simulation_settings.h"

namespace kinema {

// Where the editor's timeline stood when a .kinema file was saved: the clip it plays
// (an index into Scene::clips; 0 when the scene has none) and the time in seconds (any
// finite number: the playhead may stand outside the clip, as in Blender).
struct ScenePlayhead {
  int clip = 0;
  double time = 0.0;
  bool operator==(const ScenePlayhead& o) const { return clip == o.clip && time == o.time; }
};

// What a file holds once loaded: a skeleton (every glTF node is a joint), its clips,
// and the meshes it shows.
struct Scene {
  std::string source;  // the path it came from, for messages and titles
  // The document's frame rate (frames per second, kMinFrameRate..kMaxFrameRate; .kinema
  // "frame_rate"): the rate of every clip that has none of its own (Clip::frameTime 0).
  double frameRate = kDefaultFrameRate;
  Skeleton skeleton;
  std::vector<Clip> clips;
  IkRig ik;  // joint limits and saved IK targets (optional in files)
  // Dynamic chains and ragdolls (.kinema "simulation"; optional): what `kinema simulate`
  // and the editor's Bake simulate.
  SimulationSettings simulation;
  // The editor's working pose as saved (.kinema "pose"); empty = the rest pose.
  Pose pose;
  // The editor's playhead as saved (.kinema "playhead"); empty for glTF, BVH and .kinema
  // files written before it existed: the editor opens those at the clip's start frame.
  std::optional<ScenePlayhead> playhead;

  // glTF keeps the file's node order for reports: the node index of each joint (the
  // skeleton is sorted parent-first, the file need not be). Empty for BVH and .kinema
  // files that did not come from glTF. Morph-weight animation is a Scalar channel on the
  // node's joint with property "weights/K" (K = morph target index).
  std::vector<int> nodeOfJoint;
  std::vector<Mesh> meshes;
  std::vector<Skin> skins;
  std::vector<MeshInstance> meshInstances;
  // The deformer stack of each mesh instance (same order), run after its morph targets and
  // skinning, in world space (SceneDeformationJob); empty when no instance has deformers.
  // Their parameters are animated by Scalar channels "deformers/NAME/PARAM" on the
  // instance's joint (anim/scalar_property.h).
  std::vector<DeformerStack> deformers;
  std::vector<Material> materials;
  std::vector<TextureImage> images;
  // glTF: each node's name as the file gives it, indexed by node ("" when unnamed). Names
  // may repeat in a file, so the skeleton holds made-unique ones; reports print these.
  std::vector<std::string> nodeNames;
  // What the loader dropped or could not keep (cameras, lights, point and line primitives,
  // extra UV sets...), one line each, for the user to see.
  std::vector<std::string> warnings;

  // The frame grid clip `clip` counts in (frameGridOf with this document's rate); the
  // document's own grid for an index that names no clip. Every "frame N" goes through here.
  FrameGrid frameGrid(int clip) const {
    return clip >= 0 && clip < static_cast<int>(clips.size()) ? frameGridOf(clips[clip], frameRate)
                                                               : documentFrameGrid(frameRate);
  }
  // The file index of each joint: nodeOfJoint when present, else the joint index.
  int fileIndexOf(int joint) const { return nodeOfJoint.empty() ? joint : nodeOfJoint[joint]; }
  // Instance i's deformer stack, or null when it has none (no deformers at all).
  const DeformerStack* deformerStack(size_t instance) const {
    return instance < deformers.size() && !deformers[instance].empty() ? &deformers[instance] : nullptr;
  }
  // Instance i's stack for editing: `deformers` grows to one per instance first.
  DeformerStack& editDeformerStack(size_t instance) {
    if (deformers.size() < meshInstances.size()) deformers.resize(meshInstances.size());
    return deformers[instance];
  }
};

// A copy of clip `clip` that carries the grid it counts in (Clip::frameTime set from
// Scene::frameGrid): what the jobs below the scene layer need, which count in a clip's own
// rate (ownFrameGrid). An index that names no clip gives an empty clip at the document's rate.
Clip clipOnItsGrid(const Scene& scene, int clip);

// An image that failed to decode on loading (the reader warned): no pixels at all.
inline bool isUndecodedImage(const TextureImage& image) {
  return image.width == 0 && image.height == 0 && image.rgba.empty();
}
// The scene without its undecoded images; materials that showed one keep their base colour
// without a texture and the other images' indices close up. Writers save this, so a file
// that loads with such a warning also converts. `dropped` gets the removed image indices.
Scene withoutUndecodedImages(const Scene& scene, std::vector<int>* dropped = nullptr);
bool hasUndecodedImages(const Scene& scene);

}  // namespace kinema
