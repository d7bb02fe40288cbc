#pragma once
// The working state every solver shares: the joints a set of targets moves ("slots"),
// their world transforms, and the goals. Internal to src/ik.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "ik/ik_solver.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// The small helpers below go inline wherever they are used: GCC stops inlining them into
// a function once it has grown large (the whole two-bone solve), and a call per quaternion
// product costs more than the product.
#if defined(__GNUC__) || defined(__clang__)
#define KINEMA_IK_INLINE [[gnu::always_inline]] inline
#else
#define KINEMA_IK_INLINE inline
#endif

namespace kinema::ik_detail {

// The quaternion product a * b and the rotation q * v, written out for the solvers' inner
// loops (the same formulas as glm's, which GCC's vectoriser turns into shuffle-heavy code
// when inlined there). With SSE2 the product runs one component per lane, each lane
// adding its four terms in the scalar order (a negated term added is exactly a term
// subtracted), so both paths give the same bits.
KINEMA_IK_INLINE glm::quat mul(const glm::quat& a, const glm::quat& b) {
#if defined(__SSE2__)
  // glm stores x y z w. Lanes: x = aw bx + ax bw + ay bz - az by, y = aw by - ax bz + ay bw
  // + az bx, z = aw bz + ax by - ay bx + az bw, w = aw bw - ax bx - ay by - az bz.
  const __m128 A = _mm_loadu_ps(&a.x), B = _mm_loadu_ps(&b.x);
  const __m128 ax = _mm_shuffle_ps(A, A, _MM_SHUFFLE(0, 0, 0, 0)), ay = _mm_shuffle_ps(A, A, _MM_SHUFFLE(1, 1, 1, 1)),
               az = _mm_shuffle_ps(A, A, _MM_SHUFFLE(2, 2, 2, 2)), aw = _mm_shuffle_ps(A, A, _MM_SHUFFLE(3, 3, 3, 3));
  const __m128 t2 = _mm_xor_ps(_mm_mul_ps(ax, _mm_shuffle_ps(B, B, _MM_SHUFFLE(0, 1, 2, 3))),
                               _mm_set_ps(-0.0f, 0.0f, -0.0f, 0.0f));  // bw bz by bx; + - + -
  const __m128 t3 = _mm_xor_ps(_mm_mul_ps(ay, _mm_shuffle_ps(B, B, _MM_SHUFFLE(1, 0, 3, 2))),
                               _mm_set_ps(-0.0f, -0.0f, 0.0f, 0.0f));  // bz bw bx by; + + - -
  const __m128 t4 = _mm_xor_ps(_mm_mul_ps(az, _mm_shuffle_ps(B, B, _MM_SHUFFLE(2, 3, 0, 1))),
                               _mm_set_ps(-0.0f, 0.0f, 0.0f, -0.0f));  // by bx bw bz; - + + -
  const __m128 r = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(aw, B), t2), t3), t4);
  glm::quat q;
  _mm_storeu_ps(&q.x, r);
  return q;
#else
  return glm::quat(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                   a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w);
#endif
}
KINEMA_IK_INLINE glm::vec3 rotate(const glm::quat& q, const glm::vec3& v) {
  // t = 2 (q.xyz x v); q v q* = v + w t + q.xyz x t.
  const float tx = 2.0f * (q.y * v.z - q.z * v.y), ty = 2.0f * (q.z * v.x - q.x * v.z),
              tz = 2.0f * (q.x * v.y - q.y * v.x);
  return glm::vec3(v.x + q.w * tx + (q.y * tz - q.z * ty), v.y + q.w * ty + (q.z * tx - q.x * tz),
                   v.z + q.w * tz + (q.x * ty - q.y * tx));
}

// std::sqrt's IEEE result without its errno branch (sqrtss on SSE2): the same bits.
KINEMA_IK_INLINE float sqrtFloat(float x) {
#if defined(__SSE2__)
  return _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x)));
#else
  return std::sqrt(x);
#endif
}

// Normalises a quaternion that is already nearly unit (a product of unit quaternions):
// at most one square root, where safeNormalize guards against denormal, huge and NaN input
// (still the fallback here) at several times the cost in the solvers' inner loops.
KINEMA_IK_INLINE glm::quat renormalize(const glm::quat& q) {
#if defined(__SSE2__)
  // glm::dot's order, (w w + x x) + (y y + z z), in two lanes.
  const __m128 Q = _mm_loadu_ps(&q.x), sq = _mm_mul_ps(Q, Q);
  const __m128 pairs = _mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 1, 2, 3)));  // x+w, y+z
  const float d = _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(1, 1, 1, 1))));
  if (std::abs(d - 1.0f) < 1e-3f) {
    glm::quat r;
    _mm_storeu_ps(&r.x, _mm_mul_ps(Q, _mm_set1_ps(1.5f - 0.5f * d)));
    return r;
  }
#else
  const float d = glm::dot(q, q);
  // Within 1e-3 of unit length one Newton step for 1/sqrt(d) is exact to ~1e-6: no root.
  if (std::abs(d - 1.0f) < 1e-3f) return q * (1.5f - 0.5f * d);
#endif
  if (d > 0.25f && d < 4.0f) return q * (1.0f / std::sqrt(d));
  return safeNormalize(q);
}

#if defined(__SSE2__)
// The same three operations on values held in SSE registers (quaternions as x y z w,
// 3-vectors as x y z and a lane that is ignored), for the loops that chain them: FK and
// the CCD sweep keep a rotation in a register from one joint to the next instead of
// going through glm types in memory. Bit-identical to mul / rotate / renormalize.
namespace simd {
KINEMA_IK_INLINE __m128 load(const glm::quat& q) { return _mm_loadu_ps(&q.x); }
KINEMA_IK_INLINE void store(glm::quat& q, __m128 v) { _mm_storeu_ps(&q.x, v); }
KINEMA_IK_INLINE __m128 load3(const glm::vec3& v) { return _mm_set_ps(0.0f, v.z, v.y, v.x); }
KINEMA_IK_INLINE void store3(glm::vec3& v, __m128 x) {
  _mm_storel_pi(reinterpret_cast<__m64*>(&v.x), x);
  _mm_store_ss(&v.z, _mm_shuffle_ps(x, x, _MM_SHUFFLE(2, 2, 2, 2)));
}
KINEMA_IK_INLINE __m128 conjugate(__m128 q) { return _mm_xor_ps(q, _mm_set_ps(0.0f, -0.0f, -0.0f, -0.0f)); }
KINEMA_IK_INLINE __m128 mul(__m128 A, __m128 B) {
  const __m128 ax = _mm_shuffle_ps(A, A, _MM_SHUFFLE(0, 0, 0, 0)), ay = _mm_shuffle_ps(A, A, _MM_SHUFFLE(1, 1, 1, 1)),
               az = _mm_shuffle_ps(A, A, _MM_SHUFFLE(2, 2, 2, 2)), aw = _mm_shuffle_ps(A, A, _MM_SHUFFLE(3, 3, 3, 3));
  const __m128 t2 = _mm_xor_ps(_mm_mul_ps(ax, _mm_shuffle_ps(B, B, _MM_SHUFFLE(0, 1, 2, 3))),
                               _mm_set_ps(-0.0f, 0.0f, -0.0f, 0.0f));
  const __m128 t3 = _mm_xor_ps(_mm_mul_ps(ay, _mm_shuffle_ps(B, B, _MM_SHUFFLE(1, 0, 3, 2))),
                               _mm_set_ps(-0.0f, -0.0f, 0.0f, 0.0f));
  const __m128 t4 = _mm_xor_ps(_mm_mul_ps(az, _mm_shuffle_ps(B, B, _MM_SHUFFLE(2, 3, 0, 1))),
                               _mm_set_ps(-0.0f, 0.0f, 0.0f, -0.0f));
  return _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(aw, B), t2), t3), t4);
}
// q.xyz x v, lane by lane in rotate()'s order (a.y b.z - a.z b.y, ...).
KINEMA_IK_INLINE __m128 cross(__m128 a, __m128 b) {
  const __m128 ayzx = _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1)), azxy = _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 byzx = _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 0, 2, 1)), bzxy = _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 1, 0, 2));
  return _mm_sub_ps(_mm_mul_ps(ayzx, bzxy), _mm_mul_ps(azxy, byzx));
}
KINEMA_IK_INLINE __m128 rotate(__m128 q, __m128 v) {
  const __m128 t = _mm_mul_ps(_mm_set1_ps(2.0f), cross(q, v));
  return _mm_add_ps(_mm_add_ps(v, _mm_mul_ps(_mm_shuffle_ps(q, q, _MM_SHUFFLE(3, 3, 3, 3)), t)), cross(q, t));
}
}  // namespace simd
#endif

#if defined(__SSE2__)
namespace simd {
KINEMA_IK_INLINE __m128 renormalize(__m128 Q) {
  const __m128 sq = _mm_mul_ps(Q, Q);
  const __m128 pairs = _mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 1, 2, 3)));
  const float d = _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(1, 1, 1, 1))));
  if (std::abs(d - 1.0f) < 1e-3f) return _mm_mul_ps(Q, _mm_set1_ps(1.5f - 0.5f * d));
  glm::quat q;
  store(q, Q);
  return load(ik_detail::renormalize(q));
}
}  // namespace simd
#endif

// The local rotation that turns a joint of world rotation `world` by the world turn
// `delta`, under a parent of world rotation `parentRot`: renormalize(parentRot^-1 delta world).
KINEMA_IK_INLINE glm::quat turnedLocal(const glm::quat& parentRot, const glm::quat& delta, const glm::quat& world) {
#if defined(__SSE2__)
  glm::quat q;
  simd::store(q, simd::renormalize(simd::mul(simd::mul(simd::conjugate(simd::load(parentRot)), simd::load(delta)),
                                             simd::load(world))));
  return q;
#else
  return renormalize(mul(mul(glm::conjugate(parentRot), delta), world));
#endif
}

// A valid pose may hold non-unit rotations (they still encode a rotation); the solvers
// make the ones they may move unit first, so the pose they hand back is unit where they
// worked even for joints they did not need to turn. Unit input is left bit for bit.
KINEMA_IK_INLINE void makeUnit(glm::quat& q) {
#if defined(__SSE2__)
  // glm::dot(q, q)'s order, (w w + x x) + (y y + z z), in two lanes.
  const __m128 v = _mm_loadu_ps(&q.x), sq = _mm_mul_ps(v, v);
  const __m128 pairs = _mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 1, 2, 3)));
  const float d = _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(1, 1, 1, 1))));
#else
  const float d = glm::dot(q, q);
#endif
  if (std::abs(d - 1.0f) > 1e-6f) q = safeNormalize(q);
}

// The shortest rotation taking direction `from` onto `to` (neither need be unit), given
// their squared lengths: the half-way quaternion (|a||b| + a.b, a x b), whose squared
// length is 2 |a||b| (|a||b| + a.b), so two square roots and no normalisation of the
// inputs. Zero or opposite inputs go to fromToRotation.
inline glm::quat fastFromTo(const glm::vec3& from, const glm::vec3& to, float fromSq, float toSq) {
  const float ll = std::sqrt(fromSq * toSq);
  const float d = glm::dot(from, to);
  if (!(ll > 0.0f) || d < -0.999999f * ll) return fromToRotation(from, to);
  const glm::vec3 c = glm::cross(from, to);
  const float n2 = 2.0f * ll * (ll + d);
  // Tiny or huge lengths under- or overflow n2: normalise the slow, safe way there.
  if (!(n2 > 1e-30f && n2 < 1e30f)) return safeNormalize(glm::quat(ll + d, c.x, c.y, c.z));
  const float s = 1.0f / std::sqrt(n2);
  return glm::quat((ll + d) * s, c.x * s, c.y * s, c.z * s);
}
inline glm::quat fastFromTo(const glm::vec3& from, const glm::vec3& to) {
  return fastFromTo(from, to, glm::dot(from, from), glm::dot(to, to));
}

// True when none of the n floats at p is infinite or NaN (exponent bits not all ones):
// integer tests, where std::isfinite costs a classification per float.
inline bool finiteFloats(const float* p, int n) {
  uint32_t bad = 0;
  for (int i = 0; i < n; ++i) {
    uint32_t bits;
    std::memcpy(&bits, p + i, sizeof bits);
    bad |= static_cast<uint32_t>((bits & 0x7f800000u) == 0x7f800000u);
  }
  return bad == 0;
}
static_assert(sizeof(Transform) == 10 * sizeof(float), "Transform is ten floats");
// Transform::isFinite's answer.
inline bool finiteTransform(const Transform& t) {
#if defined(__SSE2__)
  // Floats 0-3, 4-7 and 6-9 (the last two loads overlap), exponent bits compared at once.
  const float* p = &t.translation.x;
  const __m128i exponent = _mm_set1_epi32(0x7f800000);
  auto bad = [&](const float* q) {
    return _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(_mm_loadu_ps(q)), exponent), exponent);
  };
  return _mm_movemask_epi8(_mm_or_si128(_mm_or_si128(bad(p), bad(p + 4)), bad(p + 6))) == 0;
#else
  return finiteFloats(&t.translation.x, 10);
#endif
}
// finiteTransform, and the scale is exactly 1 (scale == glm::vec3(1.0f), NaN failing).
inline bool finiteUnscaled(const Transform& t) {
#if defined(__SSE2__)
  const float* p = &t.translation.x;
  const __m128i exponent = _mm_set1_epi32(0x7f800000);
  const __m128 l0 = _mm_loadu_ps(p), l1 = _mm_loadu_ps(p + 4), l2 = _mm_loadu_ps(p + 6);  // l2: rotation.w, scale
  auto bad = [&](__m128 l) { return _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(l), exponent), exponent); };
  const int nonFinite = _mm_movemask_epi8(_mm_or_si128(_mm_or_si128(bad(l0), bad(l1)), bad(l2)));
  const int scaled = _mm_movemask_ps(_mm_cmpneq_ps(l2, _mm_set1_ps(1.0f))) & 0xe;
  return (nonFinite | scaled) == 0;
#else
  return finiteTransform(t) && t.scale == glm::vec3(1.0f);
#endif
}

// The x y z of the four columns of a placement are finite (what IkProblem::validate asks).
inline bool finitePlacement(const glm::mat4& m) {
#if defined(__SSE2__)
  const __m128i exponent = _mm_set1_epi32(0x7f800000);
  __m128i bad = _mm_setzero_si128();
  for (int c = 0; c < 4; ++c)
    bad = _mm_or_si128(bad, _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(_mm_loadu_ps(&m[c].x)), exponent), exponent));
  return (_mm_movemask_ps(_mm_castsi128_ps(bad)) & 0x7) == 0;
#else
  for (int c = 0; c < 4; ++c)
    if (!finiteFloats(&m[c].x, 3)) return false;
  return true;
#endif
}

// m == glm::mat4(1.0f), column by column in SSE registers (glm's operator== compares the
// sixteen floats one branch at a time): the same answer, NaN and -0 included.
inline bool isIdentity(const glm::mat4& m) {
#if defined(__SSE2__)
  const __m128 one = _mm_set_ss(1.0f);  // 1 0 0 0
  __m128 eq = _mm_cmpeq_ps(_mm_loadu_ps(&m[0].x), one);
  eq = _mm_and_ps(eq, _mm_cmpeq_ps(_mm_loadu_ps(&m[1].x), _mm_shuffle_ps(one, one, _MM_SHUFFLE(1, 1, 0, 1))));
  eq = _mm_and_ps(eq, _mm_cmpeq_ps(_mm_loadu_ps(&m[2].x), _mm_shuffle_ps(one, one, _MM_SHUFFLE(1, 0, 1, 1))));
  eq = _mm_and_ps(eq, _mm_cmpeq_ps(_mm_loadu_ps(&m[3].x), _mm_shuffle_ps(one, one, _MM_SHUFFLE(0, 1, 1, 1))));
  return _mm_movemask_ps(eq) == 0xf;
#else
  return m == glm::mat4(1.0f);
#endif
}

// IkProblem::validate in two parts: a check that the problem is plainly valid (every
// check passes; no message is built), and the full checks that name the first problem.
// validate() runs the second only where the first says no; they agree (ik tests).
bool plainlyValid(const IkProblem& problem, bool twoBone);
std::string validateInFull(const IkProblem& problem, bool twoBone);

struct Goal {
  int slot = -1;      // the effector's slot
  int rootSlot = -1;  // the IK root's slot
  glm::vec3 position{0.0f};
  bool hasOrientation = false;
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
  float weight = 1.0f;
};

struct IkChain {
  const Skeleton* skeleton = nullptr;
  Pose* pose = nullptr;
  const IkRig* rig = nullptr;
  // Slots in depth-first preorder, so a slot's descendants are [s + 1, s + subtreeSize[s]).
  std::vector<int> joints;          // skeleton joint of each slot
  std::vector<int> parentSlot;      // -1: the parent lies outside and never moves
  std::vector<int> subtreeSize;     // this slot and the slots below it
  std::vector<glm::mat4> fixedParent;  // world of the parent, for slots with parentSlot -1
  std::vector<glm::quat> fixedRotation;  // its rotation (scale removed), computed once
  std::vector<glm::vec3> fixedPosition;  // and its position
  std::vector<glm::vec3> positions;  // current world position of each slot
  std::vector<glm::quat> rotation;   // its world rotation (scale removed)
  // Its whole world transform, kept only when some scale is present (!rigid): a rigid
  // chain is fully described by positions and rotations, half the work to update.
  std::vector<glm::mat4> world;
  std::vector<const JointLimit*> limit;
  std::vector<Goal> goals;
  std::vector<float> history;       // error after each iteration, for stall detection
  // build()'s scratch, kept so that a reused chain (see workspace()) allocates nothing.
  std::vector<int> slotOfScratch, orderScratch, stackScratch, fillScratch, dfsScratch;
  std::vector<char> inScratch;
  // No scale anywhere (slots and fixed parents): FK then needs only quaternion products,
  // and a world matrix is its rotation plus its position.
  bool rigid = false;
  bool anyLimit = false;  // some slot has a joint limit (set by build)
  bool chain = false;     // one target: slot i's parent is slot i - 1 (slot 0's is fixed)
  bool anyOrientation = false;  // some goal has an orientation target (set by build)

  // Fills the slots from the problem; returns an error message or "".
  std::string build(const IkProblem& problem, bool twoBone = false);
  // What every iterative solver does first: validate the problem, build the slots and
  // record the starting pose in the trace. Returns the error message, or "" to go on.
  std::string begin(const IkProblem& problem, const IkSettings& settings);
  // Recomputes world transforms of every slot from the pose.
  void forwardKinematics();
  // Recomputes slot s only (its parent must be up to date).
  void forwardSlot(int s);
  // The same after only s's local rotation changed (its position stays where it is).
  void forwardRotation(int s) {
    if (!rigid) return forwardSlot(s);
    rotation[s] = renormalize(mul(parentRotation(s), pose->local[joints[s]].rotation));
  }
  glm::vec3 position(int s) const { return positions[s]; }
  // Where a child slot sits given its parent's current transform (the child's own world
  // may be stale).
  glm::vec3 childPosition(int child) const;
  glm::quat parentRotation(int s) const { return parentSlot[s] >= 0 ? rotation[parentSlot[s]] : fixedRotation[s]; }
  // Turns slot s by `delta` (a world rotation about its own position), clamps the result
  // to the joint's limit, and carries its sub-tree along rigidly. Returns the rotation
  // actually applied.
  glm::quat rotateJoint(int s, const glm::quat& delta);
  // Sets slot s's local rotation (limited), then refreshes its sub-tree by FK.
  void setLocalRotation(int s, const glm::quat& local);
  float goalError(const Goal& g) const { return distanceInDouble(position(g.slot), g.position); }
  // One goal (the common case) inline: the same value as the loop over goals.
  float maxError() const { return goals.size() == 1 ? std::max(0.0f, goalError(goals[0])) : maxErrorOfAll(); }
  float maxErrorOfAll() const;
  float orientationError() const;  // largest angle (radians) to an orientation target
  bool converged(const IkSettings& settings) const { return converged(maxError(), settings); }
  // The same, given maxError() of the current pose. Orientation targets share the
  // tolerance, read as radians; without any, orientationError() is 0.
  bool converged(float error, const IkSettings& settings) const {
    return error <= settings.tolerance &&
           (anyOrientation ? orientationError() : 0.0f) <= std::max(settings.tolerance, 1e-3f);
  }
  // True when the last stallWindow iterations improved the error by less than
  // stallFraction; records `error` first.
  bool stalled(float error, const IkSettings& settings);
  bool hasLimits() const { return anyLimit; }
  // The sum of bone lengths from the goal's root to its effector.
  // boneLength (optional): each slot's distance to its parent slot, as computed here.
  float reach(const Goal& g, const float* boneLength = nullptr) const;
  // Single goal beyond reach and no limits: point every bone straight at the target.
  bool straightenIfUnreachable(const float* boneLength = nullptr);
  void record(IkTrace* trace, int iteration, IkStep step, int joint = -1) const;
  void recordPositions(IkTrace* trace, int iteration, IkStep step, const std::vector<glm::vec3>& positions,
                       float error) const;
  IkResult result(int iterations, const IkSettings& settings) const;
};

// This thread's chain for one solver call: its vectors keep their capacity from call to
// call, so an interactive drag (a solve per frame) stops allocating after the first.
// Solvers never nest, so one per thread is enough.
IkChain& workspace();

}  // namespace kinema::ik_detail
