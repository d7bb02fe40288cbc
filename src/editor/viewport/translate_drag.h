#pragma once
#include "editor/viewport/viewport_view.h"

namespace kinema {

// Where the cursor ray meets the plane through `point` facing the viewer (the view plane at
// the point's depth). False when the ray runs parallel to the plane.
bool cursorOnViewPlane(const ViewportView& view, const glm::vec3& point, glm::vec2 cursor, glm::vec3& out);

// G / handle drag in the view plane: `startPoint` moves with the cursor and keeps its depth;
// the grab offset between the cursor and the point at `startCursor` is kept.
glm::vec3 dragInViewPlane(const ViewportView& view, const glm::vec3& startPoint, glm::vec2 startCursor,
                          glm::vec2 cursor);

// The point on the line (linePoint + s * lineDirection) closest to the ray; false when they
// are parallel (then `out` is untouched).
bool closestPointOnLineToRay(const glm::vec3& linePoint, const glm::vec3& lineDirection, const PickRay& ray,
                             glm::vec3& out);

// Constrained drag along a world axis: the closest point between the cursor ray and the
// axis line through `startPoint`, minus the same for `startCursor` (keeps the grab offset).
// Returns startPoint when the axis points straight at the viewer.
glm::vec3 dragAlongAxis(const ViewportView& view, const glm::vec3& startPoint, const glm::vec3& axis,
                        glm::vec2 startCursor, glm::vec2 cursor);

}  // namespace kinema
