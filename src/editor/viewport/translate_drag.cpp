#include "editor/viewport/translate_drag.h"

namespace kinema {

bool cursorOnViewPlane(const ViewportView& view, const glm::vec3& point, glm::vec2 cursor, glm::vec3& out) {
  const PickRay ray = view.rayThrough(cursor);
  const glm::vec3 n = view.forward();  // the view plane at the point's depth is normal to it
  const float denom = glm::dot(ray.direction, n);
  if (std::abs(denom) < 1e-8f) return false;
  out = ray.at(glm::dot(point - ray.origin, n) / denom);
  return true;
}

glm::vec3 dragInViewPlane(const ViewportView& view, const glm::vec3& startPoint, glm::vec2 startCursor,
                          glm::vec2 cursor) {
  glm::vec3 grabbed, now;
  if (!cursorOnViewPlane(view, startPoint, startCursor, grabbed) || !cursorOnViewPlane(view, startPoint, cursor, now))
    return startPoint;
  return startPoint + (now - grabbed);
}

bool closestPointOnLineToRay(const glm::vec3& linePoint, const glm::vec3& lineDirection, const PickRay& ray,
                             glm::vec3& out) {
  // Minimise |P + s u - (O + t d)|: the normal equations give s = (b e - c w) / (a c - b^2).
  const glm::vec3& u = lineDirection;
  const glm::vec3& d = ray.direction;
  const glm::vec3 w0 = linePoint - ray.origin;
  const float a = glm::dot(u, u), b = glm::dot(u, d), c = glm::dot(d, d);
  const float w = glm::dot(u, w0), e = glm::dot(d, w0);
  const float denom = a * c - b * b;
  if (!(denom > 1e-8f * a * c)) return false;  // parallel (or a zero direction)
  out = linePoint + u * ((b * e - c * w) / denom);
  return true;
}

glm::vec3 dragAlongAxis(const ViewportView& view, const glm::vec3& startPoint, const glm::vec3& axis,
                        glm::vec2 startCursor, glm::vec2 cursor) {
  glm::vec3 grabbed, now;
  if (!closestPointOnLineToRay(startPoint, axis, view.rayThrough(startCursor), grabbed) ||
      !closestPointOnLineToRay(startPoint, axis, view.rayThrough(cursor), now))
    return startPoint;
  return startPoint + (now - grabbed);
}

}  // namespace kinema
