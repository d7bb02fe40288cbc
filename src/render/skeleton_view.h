#pragma once
#include <vector>

#include "render/camera.h"

namespace kinema {

// The camera Kinema starts with for a posed skeleton (or the union of its poses over a
// sequence): three-quarter view from the front right, slightly above, framing the bounds.
OrbitCamera defaultCamera(const Bounds& bounds, float aspect);

}  // namespace kinema
