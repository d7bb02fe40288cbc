#pragma once
// An L-system plant (sim/lsystem_skeleton.h's turtle and tube) as a whole scene.
#include <string>

#include "core/result.h"
#include "scene/scene.h"

namespace kinema {

// The plant as a scene: the skeleton, the tube mesh on the root joint with its skin and a
// bark-green material, no clips. `radius` <= 0 means a tenth of the segment length.
Result<Scene> makeLSystemScene(const std::string& symbols, double angleDegrees, float segmentLength, float radius);

}  // namespace kinema
