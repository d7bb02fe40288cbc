#pragma once
// The hand-derivation camera of the viewport tests: eye on +Z at (0, 0, 10) looking at the
// origin down -Z, 90 degree vertical field (tan 45 = 1), 200 x 200 pixels. Then
//   perspective:  (x, y, z) -> pixel (100 + 100 x / (10 - z), 100 - 100 y / (10 - z)),
//   orthographic: half-height 10 * tan 45 = 10, so (x, y, z) -> pixel (100 + 10 x, 100 - 10 y);
// both take 0.1 world units per pixel at the origin's depth.
#include "editor/viewport/viewport_view.h"

namespace kinema::test {

inline OrbitCamera handCamera(bool orthographic) {
  OrbitCamera c;
  c.azimuthDeg = 0;
  c.elevationDeg = 0;
  c.distance = 10;
  c.target = glm::vec3(0.0f);
  c.fovYDeg = 90;
  c.nearPlane = 0.1f;
  c.farPlane = 100;
  c.orthographic = orthographic;
  return c;
}

inline ViewportView handView(bool orthographic) { return ViewportView::of(handCamera(orthographic), {200, 200}); }

}  // namespace kinema::test
