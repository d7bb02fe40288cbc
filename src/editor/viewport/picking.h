#pragma once
#include <vector>

#include "editor/viewport/viewport_view.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

// Ray-casting against the shapes the renderer actually draws (SkeletonDrawList's octahedra
// and joint spheres). A click on the bone parent -> child selects the PARENT (the bone's head
// joint): that joint's rotation moves the bone, and skeleton_draw_list highlights a joint's
// outgoing bones, so the clicked bone lights up. A click on a joint sphere selects that joint.
struct SkeletonPick {
  int joint = -1;          // the selected joint, -1 = nothing hit
  int boneChild = -1;      // when a bone was hit: its tail joint (joint is its head); else -1
  float distance = 0.0f;   // along the ray to the hit
  bool hit() const { return joint >= 0; }
};

// Distance along the ray to triangle abc (either side), or a negative number when missed.
float rayTriangleDistance(const PickRay& ray, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
// Distance to the first crossing of a sphere's surface in front of the origin, or negative.
float raySphereDistance(const PickRay& ray, const glm::vec3& center, float radius);

// The nearest shape of `list` hit by `ray`. Needs list.boneParents/boneChildren (filled by
// SkeletonDrawJob). Joint spheres win ties with bones (the sphere sits on the bone's head).
SkeletonPick pickSkeleton(const SkeletonDrawList& list, const PickRay& ray);

// Click and hover (call it on every mouse move): the ray under `cursor` first; when it hits nothing, the joint whose screen
// position is nearest within `fallbackRadiusPixels` (tiny or far-away bones stay clickable).
SkeletonPick pickSkeletonAt(const SkeletonDrawList& list, const ViewportView& view, glm::vec2 cursor,
                            float fallbackRadiusPixels = 8.0f);

}  // namespace kinema
