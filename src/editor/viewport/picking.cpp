#include "editor/viewport/picking.h"

#include <algorithm>
#include <limits>

#include "editor/viewport/viewport_controller.h"
#include "render/shape_meshes.h"

namespace kinema {

float rayTriangleDistance(const PickRay& ray, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  // Moller-Trumbore: solve origin + t dir = a + u (b - a) + v (c - a).
  const glm::vec3 e1 = b - a, e2 = c - a;
  const glm::vec3 p = glm::cross(ray.direction, e2);
  const float det = glm::dot(e1, p);
  const float scale = glm::length(e1) * glm::length(e2);
  if (std::abs(det) <= 1e-9f * scale) return -1.0f;  // parallel to the triangle's plane
  const float inv = 1.0f / det;
  const glm::vec3 s = ray.origin - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return -1.0f;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(ray.direction, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return -1.0f;
  const float t = glm::dot(e2, q) * inv;
  return t >= 0.0f ? t : -1.0f;
}

float raySphereDistance(const PickRay& ray, const glm::vec3& center, float radius) {
  // |o + t d - c|^2 = r^2 with |d| = 1: t^2 + 2 b t + k = 0.
  const glm::vec3 oc = ray.origin - center;
  const float b = glm::dot(oc, ray.direction);
  const float k = glm::dot(oc, oc) - radius * radius;
  const float disc = b * b - k;
  if (disc < 0.0f) return -1.0f;
  const float root = std::sqrt(disc);
  const float t0 = -b - root, t1 = -b + root;
  if (t0 >= 0.0f) return t0;
  return t1 >= 0.0f ? 0.0f : -1.0f;  // the origin is inside: hit at once
}

namespace {
// The joint sphere i stands for: spheres skip the joints that are not drawn (a glTF
// character's helper nodes), so the index is the joint only in lists that draw them all.
int jointOfSphere(const SkeletonDrawList& list, size_t i) {
  return i < list.joints.size() ? list.joints[i] : static_cast<int>(i);
}
}  // namespace

SkeletonPick pickSkeleton(const SkeletonDrawList& list, const PickRay& ray) {
  static const ShapeMesh bone = makeOctahedralBone();
  SkeletonPick best;
  float bestT = std::numeric_limits<float>::infinity();
  const size_t bones = std::min({list.boneMatrices.size(), list.boneParents.size(), list.boneChildren.size()});
  for (size_t k = 0; k < bones; ++k) {
    const glm::mat4& m = list.boneMatrices[k];
    for (int v = 0; v + 2 < bone.vertexCount(); v += 3) {
      const glm::vec3 a(m * glm::vec4(bone.positions[v], 1.0f));
      const glm::vec3 b(m * glm::vec4(bone.positions[v + 1], 1.0f));
      const glm::vec3 c(m * glm::vec4(bone.positions[v + 2], 1.0f));
      const float t = rayTriangleDistance(ray, a, b, c);
      if (t >= 0.0f && t < bestT) {
        bestT = t;
        best.joint = list.boneParents[k];
        best.boneChild = list.boneChildren[k];
        best.distance = t;
      }
    }
  }
  for (size_t i = 0; i < list.jointMatrices.size(); ++i) {
    const glm::mat4& m = list.jointMatrices[i];
    const float t = raySphereDistance(ray, glm::vec3(m[3]), glm::length(glm::vec3(m[0])));
    if (t >= 0.0f && t <= bestT) {  // <=: the sphere wins a tie with the bone it sits on
      bestT = t;
      best.joint = jointOfSphere(list, i);
      best.boneChild = -1;
      best.distance = t;
    }
  }
  return best;
}

SkeletonPick pickSkeletonAt(const SkeletonDrawList& list, const ViewportView& view, glm::vec2 cursor,
                            float fallbackRadiusPixels) {
  SkeletonPick pick = pickSkeleton(list, view.rayThrough(cursor));
  if (pick.hit()) return pick;
  const int sphere = pickJoint(list.jointMatrices, view.viewProjection(), view.size, cursor - view.origin,
                               fallbackRadiusPixels);
  if (sphere >= 0) {
    pick.joint = jointOfSphere(list, static_cast<size_t>(sphere));
    const glm::vec3 p(list.jointMatrices[sphere][3]);
    pick.distance = glm::length(p - view.rayThrough(cursor).origin);
  }
  return pick;
}

}  // namespace kinema
