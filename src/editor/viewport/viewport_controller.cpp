#include "editor/viewport/viewport_controller.h"

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

namespace kinema {

void applyViewPreset(OrbitCamera& camera, ViewPreset preset) {
  // Azimuth 0 puts the eye on +Z (the character's front), 90 on +X. Blender's Right view
  // looks from +X too, so both show the character's left side (Left joints lie at +X).
  switch (preset) {
    case ViewPreset::Front: camera.azimuthDeg = 0.0f; camera.elevationDeg = 0.0f; break;
    case ViewPreset::Back: camera.azimuthDeg = 180.0f; camera.elevationDeg = 0.0f; break;
    case ViewPreset::Right: camera.azimuthDeg = 90.0f; camera.elevationDeg = 0.0f; break;
    case ViewPreset::Left: camera.azimuthDeg = -90.0f; camera.elevationDeg = 0.0f; break;
    case ViewPreset::Top: camera.azimuthDeg = 0.0f; camera.elevationDeg = 90.0f; break;
    case ViewPreset::Bottom: camera.azimuthDeg = 0.0f; camera.elevationDeg = -90.0f; break;
  }
}

void toggleOrthographic(OrbitCamera& camera) { camera.orthographic = !camera.orthographic; }

void frameSelected(OrbitCamera& camera, const std::vector<glm::mat4>& world, const std::vector<int>& selected,
                   float aspect, float minRadius) {
  Bounds bounds;
  for (int i : selected)
    if (i >= 0 && i < static_cast<int>(world.size())) bounds.add(glm::vec3(world[i][3]));
  if (bounds.empty) bounds = jointBounds(world);
  if (bounds.empty) return;
  if (bounds.radius() < minRadius) {
    // Grow to a cube whose half-diagonal is minRadius, centred where the selection is.
    const glm::vec3 c = bounds.center();
    const glm::vec3 half(minRadius / std::sqrt(3.0f));
    bounds.add(c - half);
    bounds.add(c + half);
  }
  camera.frame(bounds, aspect);
}

}  // namespace kinema
