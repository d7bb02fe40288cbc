#include "editor/viewport_controller.h"

#include <algorithm>

namespace kinema {

void ViewportController::orbit(OrbitCamera& camera, glm::vec2 d) const {
  camera.azimuthDeg = std::fmod(camera.azimuthDeg - d.x * orbitDegreesPerPixel, 360.0f);
  camera.elevationDeg = std::clamp(camera.elevationDeg + d.y * orbitDegreesPerPixel, -89.9f, 89.9f);
}

void ViewportController::pan(OrbitCamera& camera, glm::vec2 d, float viewportHeight) const {
  if (viewportHeight <= 0) return;
  // World units per pixel at the target's depth: the view's height there is 2 d tan(fov/2).
  const float unitsPerPixel = 2.0f * camera.distance * std::tan(glm::radians(camera.fovYDeg) * 0.5f) / viewportHeight;
  const glm::mat4 view = camera.view();
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]);  // rows of the view rotation
  const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
  // Dragging right moves the scene right, so the target moves left; screen y grows downwards.
  camera.target += (-right * d.x + up * d.y) * unitsPerPixel;
}

void ViewportController::zoom(OrbitCamera& camera, float notches) const {
  // Clip planes are refitted by the caller each frame (it knows the scene's size).
  camera.distance = std::max(camera.distance / std::pow(zoomStep, notches), 1e-4f);
}

void ViewportController::frameAll(OrbitCamera& camera, const Bounds& bounds, float aspect) const {
  camera.frame(bounds, aspect);
}

int pickJoint(const std::vector<glm::mat4>& world, const glm::mat4& viewProjection, glm::vec2 size, glm::vec2 cursor,
              float radiusPixels) {
  int best = -1;
  float bestDistance = radiusPixels;
  for (size_t i = 0; i < world.size(); ++i) {
    const glm::vec4 clip = viewProjection * glm::vec4(glm::vec3(world[i][3]), 1.0f);
    if (clip.w <= 0) continue;  // behind the eye
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec2 pixel((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y);
    const float d = glm::length(pixel - cursor);
    if (d <= bestDistance) {
      bestDistance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace kinema
