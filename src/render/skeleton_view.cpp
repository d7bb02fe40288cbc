#include "render/skeleton_view.h"

namespace kinema {

OrbitCamera defaultCamera(const Bounds& bounds, float aspect) {
  OrbitCamera camera;
  camera.azimuthDeg = 30.0f;
  camera.elevationDeg = 12.0f;
  camera.frame(bounds, aspect);
  return camera;
}

}  // namespace kinema
