#include "core/transform.h"

namespace kinema {

glm::mat4 Transform::toMatrix() const {
  const float x = rotation.x, y = rotation.y, z = rotation.z, w = rotation.w;
  const float xx = x * x, yy = y * y, zz = z * z;
  const float xy = x * y, xz = x * z, yz = y * z;
  const float wx = w * x, wy = w * y, wz = w * z;
  glm::mat4 m(1.0f);
  m[0] = glm::vec4((1.0f - 2.0f * (yy + zz)) * scale.x, 2.0f * (xy + wz) * scale.x,
                   2.0f * (xz - wy) * scale.x, 0.0f);
  m[1] = glm::vec4(2.0f * (xy - wz) * scale.y, (1.0f - 2.0f * (xx + zz)) * scale.y,
                   2.0f * (yz + wx) * scale.y, 0.0f);
  m[2] = glm::vec4(2.0f * (xz + wy) * scale.z, 2.0f * (yz - wx) * scale.z,
                   (1.0f - 2.0f * (xx + yy)) * scale.z, 0.0f);
  m[3] = glm::vec4(translation, 1.0f);
  return m;
}

}  // namespace kinema
