#include "editor/viewport/viewport_view.h"

namespace kinema {

ViewportView ViewportView::of(const OrbitCamera& camera, glm::vec2 size, glm::vec2 origin) {
  ViewportView v;
  v.size = glm::max(size, glm::vec2(1.0f));
  v.origin = origin;
  v.view = camera.view();
  v.projection = camera.projection(v.size.x / v.size.y);
  v.orthographic = camera.orthographic;
  return v;
}

// The view matrix is rigid, so its inverse's columns are the camera's axes and position.
glm::vec3 ViewportView::eye() const { return glm::vec3(glm::inverse(view)[3]); }
glm::vec3 ViewportView::forward() const { return -glm::normalize(glm::vec3(glm::inverse(view)[2])); }
glm::vec3 ViewportView::right() const { return glm::normalize(glm::vec3(glm::inverse(view)[0])); }
glm::vec3 ViewportView::up() const { return glm::normalize(glm::vec3(glm::inverse(view)[1])); }

glm::vec3 ViewportView::towardViewer(const glm::vec3& point) const {
  if (orthographic) return -forward();
  const glm::vec3 d = eye() - point;
  const float len = glm::length(d);
  return len > 0.0f ? d / len : -forward();
}

bool ViewportView::project(const glm::vec3& world, glm::vec2& pixel) const {
  const glm::vec4 clip = viewProjection() * glm::vec4(world, 1.0f);
  if (clip.w <= 1e-7f) return false;  // behind the eye (orthographic w is always 1)
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  pixel = origin + glm::vec2((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y);
  return true;
}

PickRay ViewportView::rayThrough(glm::vec2 pixel) const {
  // Built from the camera's axes rather than by inverting the view-projection, which loses
  // digits to the near/far ratio; OrbitCamera's frusta are symmetric, so projection[0][0] and
  // [1][1] (1 / tan of the half-angles, or 1 / the half-sizes) say all there is.
  const glm::vec2 local = pixel - origin;
  const glm::vec2 ndc(2.0f * local.x / size.x - 1.0f, 1.0f - 2.0f * local.y / size.y);
  const glm::vec2 half(1.0f / projection[0][0], 1.0f / projection[1][1]);
  const glm::vec3 side = right() * (ndc.x * half.x) + up() * (ndc.y * half.y);
  PickRay ray;
  if (orthographic) {
    const float nearDistance = (projection[3][2] + 1.0f) / projection[2][2];  // ortho: P32 = -(f+n)/(f-n), P22 = -2/(f-n)
    ray.origin = eye() + side + forward() * nearDistance;
    ray.direction = forward();
  } else {
    ray.origin = eye();
    ray.direction = glm::normalize(forward() + side);
  }
  return ray;
}

float ViewportView::unitsPerPixelAt(const glm::vec3& point) const {
  // projection[1][1] is 1 / tan(fov/2) (perspective) or 1 / half-height (orthographic).
  const float depth = orthographic ? 1.0f : std::max(glm::dot(point - eye(), forward()), 0.0f);
  return 2.0f * depth / (projection[1][1] * size.y);
}

}  // namespace kinema
