#pragma once
// Files <-> Scene: the one place that chooses a reader or a writer by the file's extension.
#include <functional>
#include <string>
#include <vector>

#include "core/result.h"
#include "core/rotation.h"
#include "evaluation/scene_evaluation_job.h"
#include "io/input_limits.h"
#include "io/up_axis.h"
#include "scene/scene.h"

namespace kinema {

// A path's extension with its dot, lower-cased (".glb"), or "" when it has none.
std::string lowerExtension(const std::string& path);

// Loads .bvh, .kinema, .gltf or .glb, chosen by the file's extension.
Result<Scene> loadScene(const std::string& path, const InputLimits& limits = {});
// The same, reading a .bvh file as `bvhUp`-up (other formats are Y-up by definition: glTF
// says so, .kinema files are Kinema's own).
Result<Scene> loadScene(const std::string& path, const InputLimits& limits, UpAxis bvhUp);

struct SceneSaveOptions {
  // Frames per second: BVH's frame rate and the rate glTF resamples curves it cannot hold
  // exactly; 0: each clip's own (Scene::frameGrid). Finite, >= 0.
  double frameRate = 0.0;
  EulerOrder bvhRotationOrder = EulerOrder::ZXY;
  // The clip a BVH file holds (BVH holds one motion); an index that names no clip: clip 0.
  int bvhClip = 0;
  // BVH: the evaluation stages each frame goes through (BVH holds only frames, so the scene's
  // keyed IK targets and live dynamic chains are baked into them); a clip that already holds
  // its simulation's bake turns dynamics off.
  EvaluationStages bvhStages;
  // BVH: called every few hundred frames with (frames written, total).
  std::function<void(long long, long long)> progress;
};

// True for the extensions saveScene writes: .bvh, .gltf, .glb, .kinema.
bool canSaveScene(const std::string& path);
// Writes the scene in the format its extension names, atomically (a failed save leaves the
// previous file). `report` gets one line for everything the format cannot hold (BVH: meshes,
// IK data, the other clips; both: what was resampled or dropped). Returns "" or the one-line
// error naming the file.
std::string saveScene(const std::string& path, const Scene& scene, const SceneSaveOptions& options = {},
                      std::vector<std::string>* report = nullptr);

}  // namespace kinema
