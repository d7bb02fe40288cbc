#pragma once
#include "core/math.h"

namespace kinema {

// A joint's local transform: scale, then rotate, then translate (glTF TRS order).
struct Transform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit quaternion, glm::quat(w, x, y, z)
  glm::vec3 scale{1.0f};

  static Transform identity() { return {}; }
  static Transform fromTranslation(const glm::vec3& t) {
    Transform x;
    x.translation = t;
    return x;
  }

  // The 4x4 affine matrix T * R * S.
  glm::mat4 toMatrix() const;
  // Inline: validation runs it on every chain joint of every IK solve.
  bool isFinite() const {
    return kinema::isFinite(translation) && kinema::isFinite(rotation) && kinema::isFinite(scale);
  }
  bool operator==(const Transform& o) const {
    return translation == o.translation && rotation == o.rotation && scale == o.scale;
  }
  bool operator!=(const Transform& o) const { return !(*this == o); }
};

}  // namespace kinema
