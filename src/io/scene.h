#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/result.h"
#include "core/skeleton.h"
#include "ik/ik_rig.h"

namespace kinema {

// What a file holds once loaded: a skeleton and its clips.
struct Scene {
  std::string source;  // the path it came from, for messages and titles
  Skeleton skeleton;
  std::vector<Clip> clips;
  IkRig ik;  // joint limits and saved IK targets (optional in files)
};

// Loads .bvh or .kinema, chosen by the file's extension.
Result<Scene> loadScene(const std::string& path);

}  // namespace kinema
