#pragma once
#include <vector>

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

// Blender's numpad views with Y up and the character facing +Z: Front (1) from +Z, Right (3)
// from +X, Top (7) from +Y; Ctrl+numpad gives Back (-Z), Left (-X), Bottom (-Y). The target
// and distance are kept.
enum class ViewPreset { Front, Back, Right, Left, Top, Bottom };
void applyViewPreset(OrbitCamera& camera, ViewPreset preset);
// Numpad 5: perspective <-> orthographic (the framing at the target is kept by construction).
void toggleOrthographic(OrbitCamera& camera);
// F: frames the selected joints' positions (all joints when none is selected) from the current
// direction; a box smaller than `minRadius` is grown to it so one joint is not filled to the edges.
void frameSelected(OrbitCamera& camera, const std::vector<glm::mat4>& world, const std::vector<int>& selected,
                   float aspect, float minRadius);

// The joint whose screen position is nearest `cursor` (pixels, origin top left) within
// `radiusPixels`, or -1. `viewProjection` maps world to clip space for a viewport of `size`.
int pickJoint(const std::vector<glm::mat4>& world, const glm::mat4& viewProjection, glm::vec2 size,
              glm::vec2 cursor, float radiusPixels);

}  // namespace kinema
