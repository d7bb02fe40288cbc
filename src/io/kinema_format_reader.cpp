#include "io/kinema_format_reader.h"

#include <cmath>

#include "core/rotation.h"
#include "io/json_number.h"

namespace kinema::kinema_format {

const double kFloatOverflow = std::ldexp(1.0, 128) - std::ldexp(1.0, 103);

Json vec(const float* v, int n) {
  Json a = Json::array();
  for (int i = 0; i < n; ++i) a.push_back(jsonFloat(v[i]));
  return a;
}

// Normalise only quaternions that are visibly off unit length, so a saved unit
// quaternion reads back bit for bit.
glm::quat normalizeIfNeeded(const glm::quat& q) {
  const float len2 = glm::dot(q, q);
  if (std::abs(len2 - 1.0f) < 1e-6f) return q;
  return safeNormalize(q);  // glm::normalize overflows to zero for components near 1e20 and up
}

// The optional "translation", "rotation" ([x, y, z, w], normalised) and "scale" members of a
// joint or pose entry at `p`, over what `t` holds.
bool readTransform(Reader& r, const Json& j, const std::string& p, Transform& t) {
  const Json* v;
  if ((v = r.member(j, p, "translation", false)) && !r.floats(*v, p + ".translation", 3, &t.translation.x))
    return false;
  if ((v = r.member(j, p, "rotation", false))) {
    float q[4];
    if (!r.floats(*v, p + ".rotation", 4, q)) return false;
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return r.fail(p + ".rotation", "zero quaternion");
    t.rotation = normalizeIfNeeded(glm::quat(q[3], q[0], q[1], q[2]));
  }
  if ((v = r.member(j, p, "scale", false)) && !r.floats(*v, p + ".scale", 3, &t.scale.x)) return false;
  return true;
}

// The transform's members as readTransform reads them, into `j`.
void writeTransform(const Transform& t, Json& j) {
  j["translation"] = vec(&t.translation.x, 3);
  const float q[4] = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
  j["rotation"] = vec(q, 4);
  j["scale"] = vec(&t.scale.x, 3);
}

bool readJointName(Reader& r, const Json& obj, const std::string& p, const char* key, const Skeleton& s,
                   bool required, int& out) {
  const Json* v = r.member(obj, p, key, required);
  if (!v) return !required;
  std::string name;
  if (!r.string(*v, p + "." + key, name)) return false;
  out = r.joint(s, name);
  if (out < 0) return r.fail(p + "." + key, "no joint named '" + cutForMessage(name) + "'");
  return true;
}

bool readFloat(Reader& r, const Json& j, const std::string& path, float& out) {
  double v = 0.0;
  if (!r.number(j, path, v)) return false;
  if (std::abs(v) >= kFloatOverflow) return r.fail(path, "number out of float range");
  out = static_cast<float>(v);
  return true;
}

}  // namespace kinema::kinema_format
