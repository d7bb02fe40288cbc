#pragma once
#include "core/math.h"
#include "render/camera.h"

namespace kinema {

// Blender-style viewport navigation as plain math on an OrbitCamera (no GL, no window), so
// it is unit-tested: the window feeds it mouse deltas in pixels.
struct ViewportController {
  float orbitDegreesPerPixel = 0.4f;
  float zoomStep = 1.2f;  // one wheel notch divides (or multiplies) the distance by this

  // Drag right turns the view to the right around the target (azimuth decreases, as in
  // Blender's turntable); drag up looks from higher. Elevation stays within +-89.9 degrees.
  void orbit(OrbitCamera& camera, glm::vec2 deltaPixels) const;
  // Moves the target in the view plane so the point under the cursor follows the cursor
  // (exactly at the target's depth), given the viewport's height in pixels.
  void pan(OrbitCamera& camera, glm::vec2 deltaPixels, float viewportHeight) const;
  // Positive notches move closer. The distance stays positive.
  void zoom(OrbitCamera& camera, float notches) const;
  // Frames the bounds from the current direction (Blender's Home / View All).
  void frameAll(OrbitCamera& camera, const Bounds& bounds, float aspect) const;
};

// The joint whose screen position is nearest `cursor` (pixels, origin top left) within
// `radiusPixels`, or -1. `viewProjection` maps world to clip space for a viewport of `size`.
int pickJoint(const std::vector<glm::mat4>& world, const glm::mat4& viewProjection, glm::vec2 size,
              glm::vec2 cursor, float radiusPixels);

}  // namespace kinema
