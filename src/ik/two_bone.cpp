// Analytic two-bone IK on a pose: walks FK to the three joints, hands their model-space
// transforms to TwoBoneIkJob (the law-of-cosines geometry, ik/two_bone_job.cpp) and
// applies its corrections. Joints between root, middle and effector stay rigid.
#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "ik/ik_chain.h"
#include "ik/two_bone_job_core.h"

namespace kinema {

namespace {

constexpr int kMaxDepth = 64;

// core's rotationOf, with the solver's inlined renormalisation (this sits on the solve's hot path).
glm::quat inlinedRotationOf(const glm::mat4& m) {
  const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])));
  return ik_detail::renormalize(glm::quat_cast(r));
}

// World positions and rotations of every joint from root down to
// `effector`. Rigid paths (no scale, placement without scale) use quaternion products only;
// any scale falls back to affine matrices. Rotations are renormalised where they are read.
struct PathWorld {
  int joints[kMaxDepth];
  glm::vec3 position[kMaxDepth];
  glm::quat rotation[kMaxDepth];  // world rotations (products of unit quaternions)
  int count = 0;

  bool compute(const Skeleton& s, const Pose& pose, const glm::mat4& placement, int root, int effector) {
    int up[kMaxDepth];
    int n = 0;
    bool rigid = true;
    for (int j = effector; j >= 0; j = s.parents[j]) {
      if (n == kMaxDepth) return false;
      up[n++] = j;
      rigid = rigid && pose.local[j].scale == glm::vec3(1.0f);
    }
    const bool identity = ik_detail::isIdentity(placement);
    if (!identity) {
      const glm::mat3 l(placement);
      const glm::mat3 ltl = glm::transpose(l) * l;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) rigid = rigid && std::abs(ltl[a][b] - (a == b ? 1.0f : 0.0f)) < 1e-6f;
    }
    glm::quat q = identity ? glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : inlinedRotationOf(placement);
    count = 0;
    bool inPath = false;
    if (rigid) {
      glm::vec3 p = identity ? glm::vec3(0.0f) : glm::vec3(placement[3]);
      const Transform* local = pose.local.data();
#if defined(__SSE2__)
      // The same products in SSE registers (ik_detail::simd: the same bits), the rotation
      // and position carried from joint to joint. Under an identity placement the top
      // joint's world rotation is its local one as it is, -0 components included.
      namespace simd = ik_detail::simd;
      __m128 qv = simd::load(q), pv = simd::load3(p);
      for (int i = n - 1; i >= 0; --i) {
        const Transform& t = local[up[i]];
        if (up[i] == root) inPath = true;
        // t.translation is followed by t.rotation: a 4-float load stays inside t.
        pv = _mm_add_ps(pv, simd::rotate(qv, _mm_loadu_ps(&t.translation.x)));
        qv = identity && i == n - 1 ? simd::load(t.rotation) : simd::mul(qv, simd::load(t.rotation));
        if (inPath) {
          joints[count] = up[i];
          simd::store(rotation[count], qv);
          simd::store3(position[count++], pv);
        }
      }
#else
      for (int i = n - 1; i >= 0; --i) {
        const Transform& t = local[up[i]];
        if (up[i] == root) inPath = true;
        p += ik_detail::rotate(q, t.translation);
        q = identity && i == n - 1 ? t.rotation : ik_detail::mul(q, t.rotation);
        if (inPath) {
          joints[count] = up[i];
          rotation[count] = q;
          position[count++] = p;
        }
      }
#endif
      return inPath;
    }
    glm::mat4 w = placement;
    for (int i = n - 1; i >= 0; --i) {
      const Transform& t = pose.local[up[i]];
      if (up[i] == root) inPath = true;
      w = multiplyAffine(w, t.toMatrix());
      q = ik_detail::renormalize(q * t.rotation);
      if (inPath) {
        joints[count] = up[i];
        rotation[count] = q;
        position[count++] = glm::vec3(w[3]);
      }
    }
    return inPath;
  }
  int indexOf(int joint) const {
    for (int i = 0; i < count; ++i)
      if (joints[i] == joint) return i;
    return -1;
  }
};

#if defined(__SSE2__)
// One transform read float by float into lanes: translation (x y z 0) and rotation
// (x y z w); true when all ten floats are finite and the scale is exactly 1. A caller that
// has just copied the pose (memcpy's wide, overlapping stores) would make a 16-byte load
// that straddles two of those stores wait until they reach the cache (a failed store
// forward); 4-byte loads always forward.
KINEMA_IK_INLINE bool loadFloatByFloat(const Transform& t, __m128& translation, __m128& rotation) {
  const float* p = &t.translation.x;
  auto lanes = [](const float* f, __m128 w) {
    return _mm_movelh_ps(_mm_unpacklo_ps(_mm_load_ss(f), _mm_load_ss(f + 1)), _mm_unpacklo_ps(_mm_load_ss(f + 2), w));
  };
  translation = lanes(p, _mm_setzero_ps());
  rotation = lanes(p + 3, _mm_load_ss(p + 6));
  const __m128 scale = lanes(p + 7, _mm_set_ss(1.0f));
  const __m128i exponent = _mm_set1_epi32(0x7f800000);
  auto bad = [&](__m128 l) { return _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(l), exponent), exponent); };
  const int nonFinite = _mm_movemask_epi8(_mm_or_si128(_mm_or_si128(bad(translation), bad(rotation)), bad(scale)));
  const int scaled = _mm_movemask_ps(_mm_cmpneq_ps(scale, _mm_set1_ps(1.0f)));
  return (nonFinite | scaled) == 0;
}

// ik_detail::makeUnit on a rotation already in lanes (the same test, the same bits);
// `stored`, where it came from, is written only when it changes.
KINEMA_IK_INLINE void makeUnitInLanes(__m128& rotation, glm::quat& stored) {
  const __m128 sq = _mm_mul_ps(rotation, rotation);
  const __m128 pairs = _mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 1, 2, 3)));
  const float d = _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(1, 1, 1, 1))));
  if (std::abs(d - 1.0f) > 1e-6f) {
    ik_detail::makeUnit(stored);
    rotation = ik_detail::simd::load(stored);
  }
}
#endif

// The job on one arm and its corrections applied to the pose: a (root), b (middle) and c
// (effector) at model-space positions pa, pb, pc with world rotations ra, rb (raw FK
// products) and rcp (c's parent's). Returns where the effector ends, the turns taken
// before any limit; `limited` tells that a joint limit changed a rotation (then the
// caller measures the effector by FK instead).
inline glm::vec3 applyArm(const IkProblem& problem, const IkSettings& settings, const IkTarget& target, int a, int b,
                          int c, const glm::vec3& pa, const glm::vec3& pb, const glm::vec3& pc, const glm::quat& rawA,
                          const glm::quat& rawB, const glm::quat& rawCp, bool& limited) {
  const Skeleton& s = *problem.skeleton;
  Pose& pose = *problem.pose;
  // The job does the geometry; the path gives it model-space inputs.
  const glm::quat ra = ik_detail::renormalize(rawA);
  const glm::quat rb = ik_detail::renormalize(rawB);
  glm::quat correctionA, correctionB, deltaA, deltaB;
  TwoBoneIkJob job;
  job.startPosition = pa;
  job.startRotation = ra;
  job.midPosition = pb;
  job.midRotation = rb;
  job.endPosition = pc;
  job.target = target.position;
  if (target.hasPole) job.pole = target.pole - pa;  // zero: bend to the current side
  if (settings.twoBoneSoften > 0.0f) {
    const float reach = glm::length(pb - pa) + glm::length(pc - pb);
    if (reach > 0.0f) job.soften = std::min(settings.twoBoneSoften / reach, 1.0f);
  }
  job.startCorrection = &correctionA;
  job.midCorrection = &correctionB;
  job.startTurn = &deltaA;
  job.midTurn = &deltaB;
  ik_detail::runTwoBoneJob(job);  // runUnchecked, inline: inputs come from a validated problem
  pose.local[a].rotation = ik_detail::renormalize(ik_detail::mul(pose.local[a].rotation, correctionA));
  pose.local[b].rotation = ik_detail::renormalize(ik_detail::mul(pose.local[b].rotation, correctionB));
  // The world turns behind the corrections: of the start joint, and of everything from
  // the mid joint down (the mid's own turn after the start's).
  const glm::quat deltaBA = ik_detail::mul(deltaA, deltaB);
  limited = false;
  if (problem.rig) {
    for (int j : {a, b}) {
      if (const JointLimit* l = problem.rig->limitOf(j)) {
        pose.local[j].rotation = applyJointLimit(*l, s.rest[j].rotation, pose.local[j].rotation);
        limited = true;
      }
    }
  }
  if (target.hasOrientation) {
    const glm::quat rcp = ik_detail::renormalize(rawCp);
    // The effector's parent turned with the root, then with the middle joint.
    const glm::quat effectorParentRot = ik_detail::renormalize(ik_detail::mul(deltaBA, rcp));
    pose.local[c].rotation = ik_detail::renormalize(glm::conjugate(effectorParentRot) * ik_detail::renormalize(target.orientation));
    if (problem.rig)
      if (const JointLimit* l = problem.rig->limitOf(c))
        pose.local[c].rotation = applyJointLimit(*l, s.rest[c].rotation, pose.local[c].rotation);
  }
  // Where the effector ended: pb turned about pa by deltaA, pc about pb by deltaBA.
#if defined(__SSE2__)
  namespace simd = ik_detail::simd;
  const __m128 a4 = simd::load3(pa), b4 = simd::load3(pb);
  glm::vec3 end;
  simd::store3(end, _mm_add_ps(_mm_add_ps(a4, simd::rotate(simd::load(deltaA), _mm_sub_ps(b4, a4))),
                               simd::rotate(simd::load(deltaBA), _mm_sub_ps(simd::load3(pc), b4))));
  return end;
#else
  return pa + ik_detail::rotate(deltaA, pb - pa) + ik_detail::rotate(deltaBA, pc - pb);
#endif
}

// The common case in one pass: one target, no rig, no trace, no placement, no scale on
// the effector's ancestors, at most kMaxDepth of them, all finite. The checks that
// IkProblem::validate(true) makes are made on the way up from the effector (stricter:
// every ancestor finite), and the path's FK is PathWorld's rigid branch: the same
// results as the general loop below (ik tests), without its path arrays and messages.
// Returns false, having changed nothing, where the case is not this one.
bool solvePlain(const IkProblem& problem, const IkSettings& settings, IkResult& out) {
  if (problem.targets.size() != 1 || problem.rig || settings.trace || !problem.skeleton || !problem.pose) return false;
  const Skeleton& s = *problem.skeleton;
  Pose& pose = *problem.pose;
  const int n = s.size();
  if (pose.size() != n || !ik_detail::isIdentity(problem.rootTransform)) return false;
  const IkTarget& t = problem.targets[0];
  const int c = t.effector;
  if (c < 0 || c >= n || t.root >= n || t.mid >= n) return false;
  if (!ik_detail::finiteFloats(&t.position.x, 3) || !std::isfinite(t.weight) || !(t.weight > 0.0f)) return false;
  if (t.hasOrientation && (!ik_detail::finiteFloats(&t.orientation.x, 4) ||
                           !(glm::dot(t.orientation, t.orientation) >= 1e-12f)))
    return false;
  if (t.hasPole && !ik_detail::finiteFloats(&t.pole.x, 3)) return false;
  const int* parents = s.parents.data();
  Transform* local = pose.local.data();
  const int b = t.mid >= 0 ? t.mid : parents[c];
  if (b < 0 || b == c) return false;
  const int a = t.root >= 0 ? t.root : parents[b];
  if (a < 0 || a == b) return false;
  // Up from the effector to the top: every joint finite and unscaled; b above c, a above b.
  int up[kMaxDepth];
  int depth = 0, ib = -1, ia = -1;
#if defined(__SSE2__)
  namespace simd = ik_detail::simd;
  __m128 translations[kMaxDepth], rotations[kMaxDepth];  // of up[i], read once
  for (int j = c; j >= 0; j = parents[j]) {
    if (depth == kMaxDepth || !loadFloatByFloat(local[j], translations[depth], rotations[depth])) return false;
#else
  for (int j = c; j >= 0; j = parents[j]) {
    if (depth == kMaxDepth || !ik_detail::finiteUnscaled(local[j])) return false;
#endif
    if (j == b && ib < 0) ib = depth;
    if (j == a && ib >= 0 && ia < 0) ia = depth;
    up[depth++] = j;
  }
  if (ib < 1 || ia <= ib) return false;
  // Valid: from here on the general path would do the same.
  out.iterations = 1;
  out.converged = true;
  // FK down from the top (identity placement): positions and raw world rotations.
  glm::vec3 pa, pb, pc;
  glm::quat ra, rb, rcp;
#if defined(__SSE2__)
  for (int i = 0; i <= ia; ++i) makeUnitInLanes(rotations[i], local[up[i]].rotation);
  // The top joint: 0 + rotate(identity, t) is 0 + t bit for bit (x + 0 = x for x != 0, and
  // every sum of zeros that starts from +0 is +0), and its world rotation is its local one.
  __m128 q = rotations[depth - 1];
  __m128 p = _mm_add_ps(_mm_setzero_ps(), translations[depth - 1]);
  for (int i = depth - 1; i >= 0; --i) {
    if (i < depth - 1) {
      p = _mm_add_ps(p, simd::rotate(q, translations[i]));
      q = simd::mul(q, rotations[i]);
    }
    if (i == ia) simd::store(ra, q), simd::store3(pa, p);
    if (i == ib) simd::store(rb, q), simd::store3(pb, p);
    if (i == 1) simd::store(rcp, q);
  }
  simd::store3(pc, p);
#else
  for (int i = 0; i <= ia; ++i) ik_detail::makeUnit(local[up[i]].rotation);
  glm::quat q(1.0f, 0.0f, 0.0f, 0.0f);
  glm::vec3 p(0.0f);
  for (int i = depth - 1; i >= 0; --i) {
    const Transform& tr = local[up[i]];
    p += ik_detail::rotate(q, tr.translation);
    q = i == depth - 1 ? tr.rotation : ik_detail::mul(q, tr.rotation);
    if (i == ia) ra = q, pa = p;
    if (i == ib) rb = q, pb = p;
    if (i == 1) rcp = q;
  }
  pc = p;
#endif
  bool limited = false;
  const glm::vec3 finalC = applyArm(problem, settings, t, a, b, c, pa, pb, pc, ra, rb, rcp, limited);
  const float err = distanceInDouble(finalC, t.position);
  out.error = std::max(out.error, err);
  if (!(err <= settings.tolerance)) out.converged = false;
  return true;
}

}  // namespace

IkResult solveTwoBone(const IkProblem& problem, const IkSettings& settings) {
  IkResult out;
  if (solvePlain(problem, settings, out)) return out;
  out.message = problem.validate(true);
  if (!out.message.empty()) return out;
  const Skeleton& s = *problem.skeleton;
  Pose& pose = *problem.pose;
  out.iterations = 1;
  out.converged = true;
  for (const IkTarget& target : problem.targets) {
    const int c = target.effector;
    const int b = target.mid >= 0 ? target.mid : s.parents[c];
    const int a = ikRootOf(s, target, true);
    for (int j = c; j >= 0; j = s.parents[j]) {
      ik_detail::makeUnit(pose.local[j].rotation);
      if (j == a) break;
    }
    PathWorld path;
    if (!path.compute(s, pose, problem.rootTransform, a, c)) {
      out.message = "two-bone: the chain from '" + s.names[a] + "' is deeper than " + std::to_string(kMaxDepth) + " joints";
      out.converged = false;
      return out;
    }
    const int ib = path.indexOf(b), ic = path.count - 1;
    const glm::vec3 pa = path.position[0], pb = path.position[ib], pc = path.position[ic];
    if (settings.trace) {
      IkTrace& t = *settings.trace;
      if (t.joints.empty()) t.joints.assign(path.joints, path.joints + path.count);
      IkTraceEntry e;
      e.step = IkStep::Start;
      e.error = distanceInDouble(pc, target.position);
      for (int i = 0; i < path.count; ++i) e.positions.push_back(path.position[i]);
      t.entries.push_back(std::move(e));
    }
    bool limited = false;
    glm::vec3 finalC = applyArm(problem, settings, target, a, b, c, pa, pb, pc, path.rotation[0], path.rotation[ib],
                                path.rotation[ic - 1], limited);
    if (limited || settings.trace) {
      path.compute(s, pose, problem.rootTransform, a, c);
      finalC = path.position[ic];
    }
    const float err = distanceInDouble(finalC, target.position);
    out.error = std::max(out.error, err);
    if (!(err <= settings.tolerance)) out.converged = false;
    if (settings.trace) {
      IkTraceEntry e;
      e.iteration = 1;
      e.step = IkStep::TwoBone;
      e.error = err;
      for (int i = 0; i < path.count; ++i) e.positions.push_back(path.position[i]);
      settings.trace->entries.push_back(std::move(e));
    }
  }
  return out;
}

}  // namespace kinema
