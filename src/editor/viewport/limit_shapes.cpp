#include "editor/viewport/limit_shapes.h"
#include "core/math.h"

#include <algorithm>

namespace kinema {

namespace {

// A unit vector perpendicular to `axis`: `hint` with its component along the axis removed,
// or any perpendicular when the hint is (nearly) parallel or zero.
glm::vec3 perpendicular(const glm::vec3& axis, const glm::vec3& hint) {
  glm::vec3 p = hint - axis * glm::dot(hint, axis);
  if (glm::length(p) > 1e-4f * std::max(glm::length(hint), 1e-20f) && glm::length(p) > 1e-12f) return glm::normalize(p);
  const glm::vec3 other = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  return glm::normalize(other - axis * glm::dot(other, axis));
}
}  // namespace

std::string LimitShapeJob::validate() const {
  const std::string bad = limit.validate();
  if (!bad.empty()) return bad;
  if (!isFinite(jointPosition) || !isFinite(restFrameWorld) || !isFinite(restBoneDirection))
    return "limit shape: joint position, rest frame and bone direction must be finite";
  if (!(size > 0.0f) || !std::isfinite(size)) return "limit shape: size must be a positive number";
  if (segments < 3 || segments > 4096) return "limit shape: segments must be between 3 and 4096";
  return {};
}

bool LimitShapeJob::run(LimitShape& out) const {
  out = LimitShape{};
  if (!validate().empty()) return false;
  const glm::quat frame = glm::normalize(restFrameWorld);
  auto world = [&](const glm::vec3& restDirection) { return jointPosition + frame * restDirection * size; };

  // Directions swept about `axis` from `from` by [lo, hi]; a closed loop when it covers a turn.
  auto arc = [&](const glm::vec3& axis, const glm::vec3& from, float lo, float hi, float radius, const glm::vec3& offset,
                 int axisTag) {
    LimitShape::Polyline line;
    line.axis = axisTag;
    const glm::vec3 side = glm::cross(axis, from);
    const float range = hi - lo;
    line.closed = range >= kTwoPi - 1e-5f;
    const int steps = line.closed ? segments : std::max(1, static_cast<int>(std::ceil(segments * range / kTwoPi)));
    const int count = line.closed ? steps : steps + 1;
    for (int k = 0; k < count; ++k) {
      const float a = lo + (line.closed ? kTwoPi : range) * static_cast<float>(k) / static_cast<float>(steps);
      line.points.push_back(world(offset + (from * std::cos(a) + side * std::sin(a)) * radius));
    }
    return line;
  };
  auto spokesToEnds = [&](const LimitShape::Polyline& line, const glm::vec3& from) {
    if (line.closed || line.points.empty()) return;
    for (const glm::vec3& end : {line.points.front(), line.points.back()}) {
      out.spokes.push_back(from);
      out.spokes.push_back(end);
    }
  };

  switch (limit.type) {
    case JointLimitType::None: break;
    case JointLimitType::Cone: {
      const glm::vec3 a = glm::normalize(limit.axis);
      const glm::vec3 u = perpendicular(a, restBoneDirection);
      // Rim: directions at the cone angle from the axis, one per segment.
      const float c = limit.coneAngle;
      const LimitShape::Polyline rim = arc(a, u, 0.0f, kTwoPi, std::sin(c), a * std::cos(c), -1);
      for (int k = 0; k < 8; ++k) {  // eight spokes from the joint to the rim
        out.spokes.push_back(jointPosition);
        out.spokes.push_back(rim.points[static_cast<size_t>(k) * rim.points.size() / 8]);
      }
      out.rims.push_back(rim);
      // Twist: an arc about the axis halfway along it, a quarter of the size across.
      if (limit.twistMax > limit.twistMin) {
        const LimitShape::Polyline twist = arc(a, u, limit.twistMin, limit.twistMax, 0.25f, a * 0.5f, -1);
        spokesToEnds(twist, world(a * 0.5f));
        out.rims.push_back(twist);
      }
      break;
    }
    case JointLimitType::Hinge: {
      const glm::vec3 a = glm::normalize(limit.axis);
      const LimitShape::Polyline hinge =
          arc(a, perpendicular(a, restBoneDirection), limit.minAngle, limit.maxAngle, 1.0f, glm::vec3(0.0f), -1);
      spokesToEnds(hinge, jointPosition);
      out.rims.push_back(hinge);
      break;
    }
    case JointLimitType::Euler: {
      for (int i = 0; i < 3; ++i) {
        if (!(limit.eulerMax[i] > limit.eulerMin[i])) continue;
        glm::vec3 a(0.0f);
        a[i] = 1.0f;
        const LimitShape::Polyline line =
            arc(a, perpendicular(a, restBoneDirection), limit.eulerMin[i], limit.eulerMax[i], 1.0f, glm::vec3(0.0f), i);
        spokesToEnds(line, jointPosition);
        out.rims.push_back(line);
      }
      break;
    }
  }
  return true;
}

}  // namespace kinema
