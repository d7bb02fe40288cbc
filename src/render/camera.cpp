#include "render/camera.h"

#include <algorithm>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace kinema {

void Bounds::add(const glm::vec3& p) {
  if (empty) {
    min = max = p;
    empty = false;
    return;
  }
  min = glm::min(min, p);
  max = glm::max(max, p);
}

Bounds jointBounds(const std::vector<glm::mat4>& world) {
  Bounds b;
  for (const glm::mat4& m : world) b.add(glm::vec3(m[3]));
  return b;
}

glm::vec3 OrbitCamera::forward() const {
  const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  // The eye sits at (sin az cos el, sin el, cos az cos el) from the target; forward points back.
  return -glm::vec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
}

glm::mat4 OrbitCamera::view() const {
  const glm::vec3 f = forward();
  // Straight up or down, the world's Y cannot serve as "up"; use the azimuth's forward instead.
  glm::vec3 up(0.0f, 1.0f, 0.0f);
  if (std::abs(f.y) > 0.9999f) {
    const float az = glm::radians(azimuthDeg);
    // Continuous with the view just short of the pole: looking down, screen-up is the horizontal
    // direction away from the eye (-Z at azimuth 0); looking up, towards it.
    up = glm::vec3(-std::sin(az), 0.0f, -std::cos(az)) * (f.y < 0 ? 1.0f : -1.0f);
  }
  return glm::lookAt(eye(), target, up);
}

glm::mat4 OrbitCamera::projection(float aspect) const {
  if (orthographic) {
    // The perspective view's height at the target's depth, so toggling keeps the framing there.
    const float halfHeight = distance * std::tan(glm::radians(fovYDeg) * 0.5f);
    const float halfWidth = halfHeight * aspect;
    return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane);
  }
  return glm::perspective(glm::radians(fovYDeg), aspect, nearPlane, farPlane);
}

float OrbitCamera::unitsPerPixelAtTarget(float viewportHeight) const {
  if (!(viewportHeight > 0.0f)) return 0.0f;
  return 2.0f * distance * std::tan(glm::radians(fovYDeg) * 0.5f) / viewportHeight;
}

void OrbitCamera::frame(const Bounds& bounds, float aspect, float fill) {
  const float radius = std::max(bounds.radius(), 1e-3f);
  target = bounds.empty ? glm::vec3(0.0f) : bounds.center();
  // The sphere must fit the narrower of the two half-angles of the view.
  const float halfY = glm::radians(fovYDeg) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * aspect);
  const float half = std::min(halfX, halfY);
  // A sphere of radius r seen from distance d subtends asin(r / d); ask for asin = fill * half.
  distance = radius / std::sin(half * fill);
  fitClipPlanes(radius);
}

void OrbitCamera::fitClipPlanes(float sceneRadius) {
  const float r = std::max(sceneRadius, 1e-3f);
  // The grid reaches a few radii past the skeleton; the near plane stays a small fraction
  // of the far one so depth precision holds even when the eye is inside the scene.
  farPlane = distance + r * 12.0f;
  nearPlane = std::max(distance - r * 4.0f, farPlane * 1e-3f);
}

std::string OrbitCamera::validate() const {
  if (!std::isfinite(azimuthDeg) || !std::isfinite(elevationDeg)) return "camera angles must be finite";
  if (!std::isfinite(distance) || distance <= 0.0f) return "camera distance must be a positive number";
  if (!isFinite(target)) return "camera target must be finite";
  if (!(fovYDeg > 0.0f && fovYDeg < 180.0f)) return "camera field of view must be between 0 and 180 degrees";
  if (!(nearPlane > 0.0f && farPlane > nearPlane)) return "camera clip planes must satisfy 0 < near < far";
  return {};
}

float steadySceneRadius(float radius) {
  if (!(radius > 1e-3f) || !std::isfinite(radius)) return 1e-3f;
  const double step = std::log(1.25);
  return static_cast<float>(std::exp(std::ceil(std::log(double(radius)) / step) * step));
}

float gridCellSize(float sceneRadius) {
  if (!(sceneRadius > 0.0f) || !std::isfinite(sceneRadius)) return 1.0f;
  const float raw = sceneRadius / 4.0f;  // a diameter of about eight cells
  const float decade = std::pow(10.0f, std::floor(std::log10(raw)));
  for (float step : {1.0f, 2.5f, 5.0f})
    if (raw <= step * decade * 1.5f) return step * decade;
  return 10.0f * decade;
}

}  // namespace kinema
