#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace kinema {

// What bakeDeformers did: the morph targets it added and how far the baked scene strays
// from the deformed one (metres, world space) over the samples it compared.
struct DeformerBakeReport {
  int targets = 0;             // morph targets added, over all meshes
  double largestError = 0.0;   // the largest vertex distance found
  int errorClip = -1;          // where it was found (-1: the rest pose, no clip)
  double errorTime = 0.0;
  int samples = 0;             // poses compared
  std::vector<std::string> lines;  // one per baked instance, for the user
};

// Replaces every mesh instance's deformer stack by morph targets, for formats without
// deformers (glTF): "Apply deformer as shape" at each key.
//  - A stack none of whose parameters a clip animates becomes one target made at the rest
//    pose, with default weight 1.
//  - Otherwise, for each clip with "deformers/NAME/PARAM" channels on the instance's joint,
//    one target per key time of those channels (the deformation at that time's pose and
//    parameters), with default weight 0 and a "weights/K" channel that is 1 at its own key
//    and 0 at the neighbouring keys (linear), so at each key the baked mesh equals the
//    deformed one and in between it blends the two neighbouring shapes.
// A target is a bind-space delta: the world-space displacement the stack adds, taken back
// through each vertex's skinning matrix at that pose (linear blend; the joint's matrix for a
// rigid instance). Meshes shared with instances that are not baked are copied first. The
// deformer channels and the stacks are removed. The report's error compares the deformed
// scene with the baked one at every frame of every clip (at most `maxSamplesPerClip`, evenly
// spread) and at the keys' midpoints, or at the rest pose when there are no clips.
struct BakeDeformersJob {
  const Scene* scene = nullptr;
  int maxSamplesPerClip = 2000;
  Scene* out = nullptr;
  DeformerBakeReport* report = nullptr;

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
