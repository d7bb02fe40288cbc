#pragma once
#include <string>
#include <vector>

#include "core/math.h"

namespace kinema {

// An axis-aligned box; empty until a point is added.
struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool empty = true;
  void add(const glm::vec3& p);
  glm::vec3 center() const { return (min + max) * 0.5f; }
  float radius() const { return empty ? 0.0f : glm::length(max - min) * 0.5f; }  // of the enclosing sphere
};

// The box around the positions of a set of world matrices (the joints of a posed skeleton).
Bounds jointBounds(const std::vector<glm::mat4>& world);

// An orbit camera: it looks at `target` from `distance` away, from the direction given by
// azimuth (degrees about +Y, 0 = in front on +Z, 90 = on +X) and elevation (degrees above
// the ground plane). Y is up. Degrees because that is what users type (--camera AZ,EL,DIST).
struct OrbitCamera {
  float azimuthDeg = 30.0f;
  float elevationDeg = 15.0f;
  float distance = 5.0f;
  glm::vec3 target{0.0f};
  float fovYDeg = 35.0f;
  float nearPlane = 0.01f;  // set from the framed size by frame()
  float farPlane = 100.0f;
  // Orthographic projection with half-height distance * tan(fov/2): the target's plane keeps
  // the same framing when toggled (Blender's numpad 5). Zooming still changes `distance`.
  bool orthographic = false;

  glm::vec3 forward() const;  // unit vector from the eye to the target
  glm::vec3 eye() const { return target - forward() * distance; }
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;  // aspect = width / height; honours `orthographic`
  // World units per pixel at the target's depth for a viewport this many pixels high.
  float unitsPerPixelAtTarget(float viewportHeight) const;
  // Moves target and distance so that the sphere around `bounds` fits the view with a
  // margin (`fill` = the fraction of the narrower half-field it spans), keeping the angles.
  void frame(const Bounds& bounds, float aspect, float fill = 0.85f);
  // Near and far planes that keep a scene of this radius around the target in view from
  // the current distance (frame() calls it; call it again after changing the distance).
  void fitClipPlanes(float sceneRadius);
  // Empty when usable; otherwise what is wrong (non-finite numbers, distance <= 0, ...).
  std::string validate() const;
};

// A scene radius rounded up to the next power of 1.25 (at least 1e-3): the editor sizes its
// grid and clip planes with it, so a pose that moves a little (an IK drag, a played clip)
// keeps the same grid and depth range, and the view outside what moved stays the same
// picture (SceneDamageJob redraws only the moved part). Non-finite or non-positive: 1e-3.
float steadySceneRadius(float radius);

// The ground grid's cell size for a scene of this size: a 1-2.5-5 step chosen so that the
// scene spans roughly eight cells, whatever the file's units (metres, centimetres, inches).
float gridCellSize(float sceneRadius);

}  // namespace kinema
