#pragma once
#include "core/math.h"
#include "render/camera.h"

namespace kinema {

// A ray in world space (unit direction), e.g. the one under the cursor.
struct PickRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};
  glm::vec3 at(float t) const { return origin + direction * t; }
};

// One camera seen through a viewport of `size` pixels whose top left corner is at `origin`
// in the window (pixels, y down; Blender's 3D view region between the panels): the mapping
// between world points, WINDOW pixels and rays that picking, gizmos and drags share.
struct ViewportView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec2 size{1.0f};
  glm::vec2 origin{0.0f};  // the viewport's top left corner in window pixels
  bool orthographic = false;

  static ViewportView of(const OrbitCamera& camera, glm::vec2 size, glm::vec2 origin = glm::vec2(0.0f));
  glm::mat4 viewProjection() const { return projection * view; }
  glm::vec3 eye() const;         // perspective: the camera position; ortho: a point far back on the axis
  glm::vec3 forward() const;     // unit, from the eye into the scene
  glm::vec3 right() const;       // unit, screen +x in world
  glm::vec3 up() const;          // unit, screen up (pixel -y) in world
  // Unit vector from `point` towards the viewer (ortho: -forward everywhere).
  glm::vec3 towardViewer(const glm::vec3& point) const;
  // World -> window pixel. False (pixel untouched) when the point is behind the eye (perspective).
  bool project(const glm::vec3& world, glm::vec2& pixel) const;
  // The ray through a pixel: from the eye (perspective) or from the near plane along the view
  // axis (orthographic).
  PickRay rayThrough(glm::vec2 pixel) const;
  // World units per pixel at the depth of `point` (ortho: everywhere the same).
  float unitsPerPixelAt(const glm::vec3& point) const;
};

}  // namespace kinema
