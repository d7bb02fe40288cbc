#include "core/forward_kinematics.h"

#include <algorithm>
#include <array>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kinema {

namespace {

// The first joint whose parent index is not -1 <= parents[i] < i, or count when all are.
int firstBadParent(const int* parents, int count) {
  for (int i = 0; i < count; ++i)
    if (parents[i] < -1 || parents[i] >= i) return i;
  return count;
}

// Same answer as firstBadParent(...) == count, without an early exit, so that the
// compiler can check several parents per instruction.
bool parentsValid(const int* parents, int count) {
  unsigned bad = 0;
  for (int i = 0; i < count; ++i) bad |= static_cast<unsigned>(parents[i] < -1) | static_cast<unsigned>(parents[i] >= i);
  return bad == 0;
}

// out = parent * local.toMatrix(), fused: the rotation-scale columns are built in
// registers and combined with the parent's columns straight away, never forming the
// local 4x4 matrix. The arithmetic is that of Transform::toMatrix() followed by
// multiplyAffine(), operation for operation (no reassociation, no fused multiply-add),
// so the result is bit-identical to the unfused version.
// `out` may not alias `parent` (a joint is never its own parent).
inline void localToWorld(const glm::mat4& parent, const Transform& t, glm::mat4& out) {
  const float x = t.rotation.x, y = t.rotation.y, z = t.rotation.z, w = t.rotation.w;
  const float xx = x * x, yy = y * y, zz = z * z;
  const float xy = x * y, xz = x * z, yz = y * z;
  const float wx = w * x, wy = w * y, wz = w * z;
  const float sx = t.scale.x, sy = t.scale.y, sz = t.scale.z;
  // Columns of the local matrix T * R * S (the fourth row is 0 0 0 1).
  const float m00 = (1.0f - 2.0f * (yy + zz)) * sx, m01 = 2.0f * (xy + wz) * sx, m02 = 2.0f * (xz - wy) * sx;
  const float m10 = 2.0f * (xy - wz) * sy, m11 = (1.0f - 2.0f * (xx + zz)) * sy, m12 = 2.0f * (yz + wx) * sy;
  const float m20 = 2.0f * (xz + wy) * sz, m21 = 2.0f * (yz - wx) * sz, m22 = (1.0f - 2.0f * (xx + yy)) * sz;
  const float tx = t.translation.x, ty = t.translation.y, tz = t.translation.z;
#if defined(__SSE2__)
  const float* p = &parent[0][0];
  const __m128 a0 = _mm_loadu_ps(p), a1 = _mm_loadu_ps(p + 4), a2 = _mm_loadu_ps(p + 8), a3 = _mm_loadu_ps(p + 12);
  auto column = [&](float bx, float by, float bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a0, _mm_set1_ps(bx)), _mm_mul_ps(a1, _mm_set1_ps(by))),
                      _mm_mul_ps(a2, _mm_set1_ps(bz)));
  };
  float* o = &out[0][0];
  _mm_storeu_ps(o, column(m00, m01, m02));
  _mm_storeu_ps(o + 4, column(m10, m11, m12));
  _mm_storeu_ps(o + 8, column(m20, m21, m22));
  _mm_storeu_ps(o + 12, _mm_add_ps(column(tx, ty, tz), a3));
#else
  const glm::vec4 a0 = parent[0], a1 = parent[1], a2 = parent[2], a3 = parent[3];
  out[0] = a0 * m00 + a1 * m01 + a2 * m02;
  out[1] = a0 * m10 + a1 * m11 + a2 * m12;
  out[2] = a0 * m20 + a1 * m21 + a2 * m22;
  out[3] = a0 * tx + a1 * ty + a2 * tz + a3;
#endif
}

#if defined(__SSE2__)
// Local matrices of four consecutive joints at once, one joint per SIMD lane (ozz's SoA
// layout): the same formulas as localToWorld(), lane by lane, so results are bit-identical.
// Writes 12 rows of 4 lanes: m00 m01 m02 m10 m11 m12 m20 m21 m22 tx ty tz.
inline void localMatrices4(const Transform* t, float (*rows)[4]) {
  // Transform is 10 floats: tx ty tz qx qy qz qw sx sy sz.
  static_assert(sizeof(Transform) == 10 * sizeof(float), "Transform must be 10 packed floats");
  const float* f = &t[0].translation.x;
  __m128 t0 = _mm_loadu_ps(f), t1 = _mm_loadu_ps(f + 10), t2 = _mm_loadu_ps(f + 20), t3 = _mm_loadu_ps(f + 30);
  __m128 q0 = _mm_loadu_ps(f + 3), q1 = _mm_loadu_ps(f + 13), q2 = _mm_loadu_ps(f + 23), q3 = _mm_loadu_ps(f + 33);
  __m128 s0 = _mm_loadu_ps(f + 6), s1 = _mm_loadu_ps(f + 16), s2 = _mm_loadu_ps(f + 26), s3 = _mm_loadu_ps(f + 36);
  _MM_TRANSPOSE4_PS(t0, t1, t2, t3);  // tx ty tz qx
  _MM_TRANSPOSE4_PS(q0, q1, q2, q3);  // qx qy qz qw
  _MM_TRANSPOSE4_PS(s0, s1, s2, s3);  // qw sx sy sz
  const __m128 x = q0, y = q1, z = q2, w = q3, sx = s1, sy = s2, sz = s3;
  const __m128 one = _mm_set1_ps(1.0f), two = _mm_set1_ps(2.0f);
  const __m128 xx = _mm_mul_ps(x, x), yy = _mm_mul_ps(y, y), zz = _mm_mul_ps(z, z);
  const __m128 xy = _mm_mul_ps(x, y), xz = _mm_mul_ps(x, z), yz = _mm_mul_ps(y, z);
  const __m128 wx = _mm_mul_ps(w, x), wy = _mm_mul_ps(w, y), wz = _mm_mul_ps(w, z);
  auto twice = [&](__m128 a) { return _mm_mul_ps(two, a); };
  _mm_store_ps(rows[0], _mm_mul_ps(_mm_sub_ps(one, twice(_mm_add_ps(yy, zz))), sx));
  _mm_store_ps(rows[1], _mm_mul_ps(twice(_mm_add_ps(xy, wz)), sx));
  _mm_store_ps(rows[2], _mm_mul_ps(twice(_mm_sub_ps(xz, wy)), sx));
  _mm_store_ps(rows[3], _mm_mul_ps(twice(_mm_sub_ps(xy, wz)), sy));
  _mm_store_ps(rows[4], _mm_mul_ps(_mm_sub_ps(one, twice(_mm_add_ps(xx, zz))), sy));
  _mm_store_ps(rows[5], _mm_mul_ps(twice(_mm_add_ps(yz, wx)), sy));
  _mm_store_ps(rows[6], _mm_mul_ps(twice(_mm_add_ps(xz, wy)), sz));
  _mm_store_ps(rows[7], _mm_mul_ps(twice(_mm_sub_ps(yz, wx)), sz));
  _mm_store_ps(rows[8], _mm_mul_ps(_mm_sub_ps(one, twice(_mm_add_ps(xx, yy))), sz));
  _mm_store_ps(rows[9], t0);
  _mm_store_ps(rows[10], t1);
  _mm_store_ps(rows[11], t2);
}

// out = parent * local, with local's entries taken from lane J of `rows`; each entry is
// broadcast with a single pshufd (J is a constant), and GCC keeps `rows` in registers.
template <int J>
inline void multiplyLane(const glm::mat4& parent, const float (*rows)[4], glm::mat4& out) {
  const float* p = &parent[0][0];
  const __m128 a0 = _mm_loadu_ps(p), a1 = _mm_loadu_ps(p + 4), a2 = _mm_loadu_ps(p + 8), a3 = _mm_loadu_ps(p + 12);
  auto lane = [&](int r) {
    return _mm_castsi128_ps(
        _mm_shuffle_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(rows[r])), _MM_SHUFFLE(J, J, J, J)));
  };
  auto column = [&](int r) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a0, lane(r)), _mm_mul_ps(a1, lane(r + 1))), _mm_mul_ps(a2, lane(r + 2)));
  };
  float* o = &out[0][0];
  _mm_storeu_ps(o, column(0));
  _mm_storeu_ps(o + 4, column(3));
  _mm_storeu_ps(o + 8, column(6));
  _mm_storeu_ps(o + 12, _mm_add_ps(column(9), a3));
}
#endif

}  // namespace

std::string LocalToWorldJob::validate() const {
  if (count < 0) return "negative joint count";
  if (count > 0 && (!parents || !local || !world)) return "missing parents, local or world array";
  if (subtreeRoot < -1 || subtreeRoot >= count)
    return "sub-tree root " + std::to_string(subtreeRoot) + " is not a joint";
  const int i = firstBadParent(parents, count);
  if (i < count)
    return "joint " + std::to_string(i) + " has parent " + std::to_string(parents[i]) +
           " (parents must come first)";
  return {};
}

bool LocalToWorldJob::run() const {
  // The checks of validate(), without building a message.
  if (count < 0 || (count > 0 && (!parents || !local || !world)) || subtreeRoot < -1 || subtreeRoot >= count ||
      !parentsValid(parents, count))
    return false;
  // Locals, so the compiler need not reload the job's fields after each store to world[].
  const int* const par = parents;
  const Transform* const loc = local;
  glm::mat4* const out = world;
  const int n = count;
  const glm::mat4 rootMatrix = root;
  if (subtreeRoot < 0) {
    int i = 0;
#if defined(__SSE2__)
    // Four joints' local matrices at a time, then the parent products one joint after
    // another (a joint's parent may be one of the four).
    alignas(16) float rows[12][4];
    for (; i + 4 <= n; i += 4) {
      localMatrices4(loc + i, rows);
      const int* pp = par + i;
      multiplyLane<0>(pp[0] < 0 ? rootMatrix : out[pp[0]], rows, out[i]);
      multiplyLane<1>(pp[1] < 0 ? rootMatrix : out[pp[1]], rows, out[i + 1]);
      multiplyLane<2>(pp[2] < 0 ? rootMatrix : out[pp[2]], rows, out[i + 2]);
      multiplyLane<3>(pp[3] < 0 ? rootMatrix : out[pp[3]], rows, out[i + 3]);
    }
#endif
    for (; i < n; ++i) {
      const int p = par[i];
      localToWorld(p < 0 ? rootMatrix : out[p], loc[i], out[i]);
    }
    return true;
  }
  // Descendants of subtreeRoot are exactly the later joints whose parent is marked.
  const int s = subtreeRoot;
  const size_t span = static_cast<size_t>(n - s);
  std::array<char, 1024> small;  // no allocation for the usual sub-tree (a limb, a chain)
  std::vector<char> large;
  char* inSubtree = small.data();
  if (span > small.size()) {
    large.resize(span);
    inSubtree = large.data();
  }
  inSubtree[0] = 1;
  localToWorld(par[s] < 0 ? rootMatrix : out[par[s]], loc[s], out[s]);
  for (int i = s + 1; i < n; ++i) {
    const int p = par[i];
    const bool in = p >= s && inSubtree[p - s];
    inSubtree[i - s] = in;  // every mark is written before it is read: no clearing
    if (in) localToWorld(out[p], loc[i], out[i]);
  }
  return true;
}

void computeWorld(const Skeleton& skeleton, const Pose& pose, std::vector<glm::mat4>& world) {
  // A pose that does not fit the skeleton yields transforms only for the joints it covers.
  const int count = std::min(skeleton.size(), pose.size());
  world.resize(static_cast<size_t>(count));
  LocalToWorldJob job;
  job.parents = skeleton.parents.data();
  job.local = pose.local.data();
  job.world = world.data();
  job.count = count;
  job.run();
}

float restJointHeight(const Skeleton& skeleton) {
  if (skeleton.size() < 2) return 0.0f;
  float lo = 1e30f, hi = -1e30f;
  for (const glm::mat4& m : computeWorld(skeleton, Pose::rest(skeleton))) lo = std::min(lo, m[3].y), hi = std::max(hi, m[3].y);
  return hi > lo ? hi - lo : 0.0f;
}

std::vector<glm::mat4> computeWorld(const Skeleton& skeleton, const Pose& pose) {
  std::vector<glm::mat4> world;
  computeWorld(skeleton, pose, world);
  return world;
}

void updateSubtree(const Skeleton& skeleton, const Pose& pose, int joint,
                   std::vector<glm::mat4>& world) {
  LocalToWorldJob job;
  job.parents = skeleton.parents.data();
  job.local = pose.local.data();
  job.world = world.data();
  job.count = std::min({skeleton.size(), pose.size(), static_cast<int>(world.size())});
  job.subtreeRoot = joint;
  job.run();
}

}  // namespace kinema
