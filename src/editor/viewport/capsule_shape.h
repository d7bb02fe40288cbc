#pragma once
// The wireframe of a spring-bone collision capsule (issue 23) for the 3D view: the segment
// a-b swept by a radius, drawn as a ring at each end, four lines along its sides and two
// half-circle caps per end, all in world space.
#include <vector>

#include "core/math.h"

namespace kinema {

struct CapsuleWire {
  std::vector<std::vector<glm::vec3>> polylines;  // open polylines; rings repeat their first point
};

// `a`, `b`: the segment's ends in world space; `radius` > 0 in world units; `segments` per
// full circle (at least 8). A zero-length segment gives a sphere's three great circles.
CapsuleWire capsuleWire(const glm::vec3& a, const glm::vec3& b, float radius, int segments = 24);

}  // namespace kinema
