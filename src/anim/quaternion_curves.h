#pragma once
#include "core/math.h"

namespace kinema {

// log of a unit quaternion: axis * half-angle (w >= 0 is not assumed).
glm::vec3 quatLog(const glm::quat& q);
// exp of a pure quaternion (0, v): (cos|v|, sin|v| v/|v|).
glm::quat quatExp(const glm::vec3& v);

// Normalised linear blend along the shortest arc. Faster than slerp; its angular velocity
// is not constant (it speeds up in the middle of wide arcs).
glm::quat nlerpShortest(const glm::quat& a, const glm::quat& b, float t);

// Shoemake's squad between q1 and q2 (u in [0, 1]) with the neighbours q0 and q3 (pass
// q1 for a missing q0, q2 for a missing q3) and key times t0..t3. The intermediate
// quaternions are chosen so the angular velocity at each key is
//   (log(q[k]^-1 q[k+1]) - log(q[k]^-1 q[k-1])) / (t[k+1] - t[k-1])
// on both sides (C1 in time even for uneven key spacing; Shoemake's original for even
// spacing), and chord / interval at an end key. Signs are aligned for the shortest arc.
glm::quat squad(const glm::quat& q0, const glm::quat& q1, const glm::quat& q2, const glm::quat& q3,
                float t0, float t1, float t2, float t3, bool hasPrevious, bool hasNext, float u);

// glTF CUBICSPLINE rotation: Hermite on the four components with tangents (per second)
// scaled by the key interval, then normalised.
glm::quat gltfCubicRotation(const glm::vec4& v0, const glm::vec4& outTangent0, const glm::vec4& v1,
                            const glm::vec4& inTangent1, float dt, float u);

}  // namespace kinema
