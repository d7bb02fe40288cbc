// FABRIK (Aristidou & Lasenby 2011; seed 002): a backward pass from the targets to the
// root and a forward pass from the fixed root. Several effectors: each sub-chain pulls
// its sub-base (the paper's multi-end rule); a sub-base with several children moves as
// one rigid body, fitted to their backward positions (see rigidFit).
// The forward pass turns positions into local rotations as it goes (the minimal rotation
// of each bone, so no spurious twist), clamping each joint to its limit before its
// children are placed: bones keep their length exactly and limits always hold; a joint
// above a hinge is twisted so the hinge's plane holds its target (twistForHingeChild).
// With limits or several effectors the passes alone crawl (or stall) near the goal, so
// the solver is a documented hybrid there: FABRIK passes while each gains >= 20 % (at
// most IkSettings::fabrikFinishAfter), then damped least squares steps finish.
#include <Eigen/Dense>
#include <algorithm>

#include "ik/ik_chain.h"
#include "ik/jacobian_step.h"

namespace kinema {

using ik_detail::Goal;
using ik_detail::IkChain;

namespace {

// The rotation taking the unit directions from[i] closest onto to[i] (Kabsch), for a
// sub-base with several children. Children on one line (a chest with two shoulders
// opposite each other) leave the turn about that line undetermined, and plain SVD then
// picks an arbitrary one, spinning the arms about the shoulder line every pass. A small
// pull towards no rotation fixes that; at convergence the best turn is none, so it does
// not move the fixed point.
glm::quat bestRotation(const std::vector<glm::vec3>& from, const std::vector<glm::vec3>& to,
                       const std::vector<float>* weight = nullptr, float pull = -1.0f) {
  if (pull < 0.0f) pull = 0.01f * static_cast<float>(from.size());
  Eigen::Matrix3f h = Eigen::Matrix3f::Identity() * pull;
  for (size_t i = 0; i < from.size(); ++i)
    h += (weight ? (*weight)[i] : 1.0f) * Eigen::Vector3f(from[i].x, from[i].y, from[i].z) *
         Eigen::Vector3f(to[i].x, to[i].y, to[i].z).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3f> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3f d = Eigen::Matrix3f::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0f ? -1.0f : 1.0f;
  const Eigen::Matrix3f r = svd.matrixV() * d * svd.matrixU().transpose();
  glm::mat3 m;
  for (int c = 0; c < 3; ++c)
    for (int rr = 0; rr < 3; ++rr) m[c][rr] = r(rr, c);
  return safeNormalize(glm::quat_cast(m));
}

// A sub-base with several children is one rigid body (a chest with two shoulders): where
// its children's backward positions ask it to be is the rigid motion that best carries
// the children (and the sub-base's own target, if any) onto them (weighted Kabsch with
// translation). The paper's centroid of per-child proposals treats each child's bone as
// free to swing about the sub-base; for a rigid chest that swing is not there, so a pull
// across a shoulder barely moved the chest and the error fell only like 1/sqrt(passes).
// Returns the sub-base's new position and the turn it makes; `from`/`to`/`w` are scratch.
// Children whose own limit asks for a particular frame of the sub-base (limitedParent,
// from the backward pass) add that frame's axes as direction pairs, so the fit turns the
// sub-base towards frames its children's limits allow.
glm::vec3 rigidFit(const IkChain& c, int s, const std::vector<glm::vec3>& reached, const Goal* goal,
                   const std::vector<glm::quat>& limitedParent, const std::vector<char>& hasLimitedParent,
                   std::vector<glm::vec3>& from, std::vector<glm::vec3>& to, std::vector<float>& w,
                   glm::quat& turn) {
  const glm::vec3 p = c.position(s);
  from.clear();
  to.clear();
  w.clear();
  for (int k = s + 1; k < s + c.subtreeSize[s]; k += c.subtreeSize[k]) {
    from.push_back(c.position(k) - p);
    to.push_back(reached[k]);
    w.push_back(1.0f);
  }
  if (goal) {
    from.push_back(glm::vec3(0.0f));
    to.push_back(goal->position);
    w.push_back(goal->weight);
  }
  glm::vec3 fc(0.0f), tc(0.0f);
  float total = 0.0f, scale = 0.0f;
  for (size_t i = 0; i < from.size(); ++i) {
    fc += w[i] * from[i];
    tc += w[i] * to[i];
    total += w[i];
  }
  fc /= total;
  tc /= total;
  for (size_t i = 0; i < from.size(); ++i) {
    from[i] -= fc;
    to[i] -= tc;
    scale += w[i] * glm::length(from[i]) * glm::length(to[i]);
  }
  // Direction pairs do not move the centroids: they are added after centring.
  const float armScale = from.size() > 0 ? scale / static_cast<float>(from.size()) : 1.0f;
  for (int k = s + 1; k < s + c.subtreeSize[s]; k += c.subtreeSize[k]) {
    if (!hasLimitedParent[k]) continue;
    const glm::quat now = c.rotation[s], wanted = limitedParent[k];
    for (int a = 0; a < 3; ++a) {
      glm::vec3 e(0.0f);
      e[a] = 1.0f;
      from.push_back(now * e);
      to.push_back(wanted * e);
      w.push_back(armScale > 0.0f ? armScale : 1.0f);
    }
  }
  // The same small pull towards no turn as bestRotation, relative to the body's size.
  turn = bestRotation(from, to, &w, 1e-3f * scale + 1e-20f);
  return tc - turn * fc;
}

constexpr float kSlowPass = 0.8f;  // a pass that keeps more than this of the error is slow

// A hinge child can bend its bone only in the plane normal to its axis, and that axis
// turns with this joint's twist about its own bone, which a minimal rotation never
// changes. Twist (by the smallest angle) so that the plane holds the child's next
// backward position; when no twist can, leave the rotation alone.
glm::quat twistForHingeChild(const IkChain& c, int s, const glm::quat& parentRot, const glm::quat& local,
                             const std::vector<glm::vec3>& reached) {
  const int k = s + 1;  // the only child (one child: the next slot in preorder)
  if (k >= s + c.subtreeSize[s] || c.subtreeSize[s] != 1 + c.subtreeSize[k]) return local;
  if (!c.limit[k] || c.limit[k]->type != JointLimitType::Hinge) return local;
  if (c.subtreeSize[k] < 2) return local;
  const int g = k + 1;  // k's first child
  const glm::quat world = parentRot * local;
  const glm::vec3 pk = c.position(s) + world * c.pose->local[c.joints[k]].translation;
  const glm::vec3 bone = pk - c.position(s);
  const float bl = glm::length(bone);
  if (!(bl > 1e-9f)) return local;
  const glm::vec3 b = bone / bl;
  const glm::vec3 a = world * (c.skeleton->rest[c.joints[k]].rotation * c.limit[k]->axis);
  const glm::vec3 w = reached[g] - pk;
  // a(phi) . w = A + B cos(phi) + C sin(phi), rotating a about b by phi.
  const glm::vec3 along = glm::dot(a, b) * b, across = a - along;
  const float A = glm::dot(along, w), B = glm::dot(across, w), C = glm::dot(glm::cross(b, across), w);
  const float r = std::sqrt(B * B + C * C);
  if (!(r > 1e-9f) || std::abs(A) > r) return local;
  const float base = std::atan2(C, B), off = std::acos(std::clamp(-A / r, -1.0f, 1.0f));
  float phi = base + off, other = base - off;
  auto wrap = [](float x) { return std::remainder(x, glm::two_pi<float>()); };
  phi = wrap(phi);
  other = wrap(other);
  if (std::abs(other) < std::abs(phi)) phi = other;
  return safeNormalize(glm::conjugate(parentRot) * glm::angleAxis(phi, b) * world);
}

// solveFabrik's per-slot arrays, kept per thread so that repeated solves allocate nothing.
struct FabrikScratch {
  std::vector<float> boneLength, count, fitWeight, fromSq, toSq;
  std::vector<int> goalOf, proposals, children;
  std::vector<glm::vec3> reached, sum, from, to;
  std::vector<glm::quat> backRot, limitedParent;
  std::vector<char> twisted, hasLimitedParent;
};

// The passes in the common case: one target without orientation (its slots run
// root..effector, each the parent of the next), no limits, a rigid chain, no trace. The
// general passes below reduce to this for such a chain, operation for operation (a
// single proposal per joint, a single child per bone, no twist, no fit), without their
// per-slot bookkeeping. Returns the number of passes.
#if defined(__SSE2__)
// The backward and forward passes below in SSE registers: the parent's rotation and
// position, the backward position and the effector carried from joint to joint instead of
// through the slot arrays (written once per joint for the next pass), and the scalar parts
// (lengths, fastFromTo) written out as in CCD's plainSweep. Operation for operation the
// same as the portable version after it (same order, sqrtss for std::sqrt): the same bits.
int plainPasses(IkChain& c, const IkSettings& settings, std::vector<float>& boneLength,
                std::vector<glm::vec3>& reached) {
  namespace simd = ik_detail::simd;
  using ik_detail::sqrtFloat;
  const int m = static_cast<int>(c.joints.size());
  const Goal& goal = c.goals[0];
  glm::vec3* pos = c.positions.data();
  glm::quat* rot = c.rotation.data();
  Transform* local = c.pose->local.data();
  const int* joints = c.joints.data();
  const float* bone = boneLength.data();
  glm::vec3* back = reached.data();
  // glm::dot of 3-vectors in SSE lanes, in its order: (x x + y y) + z z.
  auto dot3 = [](__m128 a, __m128 b) {
    const __m128 t = _mm_mul_ps(a, b);
    return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(t, _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 1, 1, 1))),
                                    _mm_shuffle_ps(t, t, _MM_SHUFFLE(2, 2, 2, 2))));
  };
  const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
  const glm::vec3 start = goal.weight * goal.position / goal.weight;
  const __m128 fixedRot = simd::load(c.fixedRotation[0]);
  int it = 0;
  float error = c.maxError();
  while (!c.converged(error, settings) && it < settings.maxIterations) {
    ++it;
    // Backward: from the target, each joint's parent at bone length towards where it is.
    float rx = start.x, ry = start.y, rz = start.z;
    back[m - 1] = start;
    for (int s = m - 1; s > 0; --s) {
      const glm::vec3 pp = pos[s - 1];
      float dx = pp.x - rx, dy = pp.y - ry, dz = pp.z - rz;
      float len = sqrtFloat(dx * dx + dy * dy + dz * dz);
      if (!(len > 1e-12f)) {  // on top of the parent: keep the bone's current direction
        const glm::vec3 ps = pos[s];
        dx = -(ps.x - pp.x), dy = -(ps.y - pp.y), dz = -(ps.z - pp.z);
        len = sqrtFloat(dx * dx + dy * dy + dz * dz);
      }
      if (len > 1e-12f) {
        const float k = bone[s] / len;
        rx = rx + dx * k, ry = ry + dy * k, rz = rz + dz * k;
      } else {
        rx = pp.x, ry = pp.y, rz = pp.z;
      }
      back[s - 1] = glm::vec3(rx, ry, rz);
    }
    // Forward: from the fixed root, each joint turns its bone onto its child's backward place.
    __m128 parentRot = fixedRot, parentPos = _mm_setzero_ps();
    for (int s = 0; s < m; ++s) {
      __m128 world, p;
      if (s > 0) {
        const Transform& t = local[joints[s]];
        world = simd::renormalize(simd::mul(parentRot, simd::load(t.rotation)));
        // t.translation is followed by t.rotation: a 4-float load stays inside t.
        p = _mm_add_ps(parentPos, simd::rotate(parentRot, _mm_loadu_ps(&t.translation.x)));
        simd::store3(pos[s], p);
      } else {
        world = simd::load(rot[0]);
        p = simd::load3(pos[0]);
      }
      if (s == m - 1) {
        simd::store(rot[s], world);
        break;
      }
      // Lane 3 masked to +0: the cross product's lane 3 is then +0 and w can be or-ed in.
      const __m128 a4 =
          _mm_and_ps(_mm_sub_ps(_mm_add_ps(p, simd::rotate(world, _mm_loadu_ps(&local[joints[s + 1]].translation.x))), p), xyz);
      const __m128 b4 = _mm_and_ps(_mm_sub_ps(simd::load3(back[s + 1]), p), xyz);
      const float aa = dot3(a4, a4), bb = dot3(b4, b4);
      parentPos = p;
      if (!(aa > 1e-24f && bb > 1e-24f)) {
        simd::store(rot[s], world);
        parentRot = world;
        continue;
      }
      // fastFromTo(a, b, aa, bb), written out.
      const float ll = sqrtFloat(aa * bb), d = dot3(a4, b4);
      const float n2 = 2.0f * ll * (ll + d);
      __m128 delta;
      if (!(ll > 0.0f) || d < -0.999999f * ll || !(n2 > 1e-30f && n2 < 1e30f)) {
        glm::vec3 from, to;
        simd::store3(from, a4);
        simd::store3(to, b4);
        delta = simd::load(ik_detail::fastFromTo(from, to, aa, bb));
      } else {
        const __m128 half = _mm_or_ps(simd::cross(a4, b4), _mm_set_ps(ll + d, 0.0f, 0.0f, 0.0f));
        delta = _mm_mul_ps(half, _mm_set1_ps(1.0f / sqrtFloat(n2)));
      }
      const __m128 turned = simd::renormalize(simd::mul(simd::mul(simd::conjugate(parentRot), delta), world));
      simd::store(local[joints[s]].rotation, turned);
      world = simd::renormalize(simd::mul(parentRot, turned));
      simd::store(rot[s], world);
      parentRot = world;
    }
    error = c.maxError();
    if (c.stalled(error, settings)) break;
  }
  return it;
}
#else
int plainPasses(IkChain& c, const IkSettings& settings, std::vector<float>& boneLength,
                std::vector<glm::vec3>& reached) {
  const int m = static_cast<int>(c.joints.size());
  const Goal& goal = c.goals[0];
  glm::vec3* pos = c.positions.data();
  glm::quat* rot = c.rotation.data();
  Transform* local = c.pose->local.data();
  const int* joints = c.joints.data();
  int it = 0;
  float error = c.maxError();
  while (!c.converged(error, settings) && it < settings.maxIterations) {
    ++it;
    // Backward: from the target, each joint's parent at bone length towards where it is.
    reached[m - 1] = goal.weight * goal.position / goal.weight;
    for (int s = m - 1; s > 0; --s) {
      const int p = s - 1;
      glm::vec3 dir = pos[p] - reached[s];
      float len = glm::length(dir);
      if (!(len > 1e-12f)) {  // on top of the parent: keep the bone's current direction
        dir = -(pos[s] - pos[p]);
        len = glm::length(dir);
      }
      reached[p] = len > 1e-12f ? reached[s] + dir * (boneLength[s] / len) : pos[p];
    }
    // Forward: from the fixed root, each joint turns its bone onto its child's backward place.
    for (int s = 0; s < m; ++s) {
      const glm::quat parentRot = s > 0 ? rot[s - 1] : c.fixedRotation[0];
      if (s > 0) {
        const Transform& t = local[joints[s]];
        rot[s] = ik_detail::renormalize(ik_detail::mul(parentRot, t.rotation));
        pos[s] = pos[s - 1] + ik_detail::rotate(parentRot, t.translation);
      }
      if (s == m - 1) break;
      const glm::vec3 p = pos[s];
      const glm::vec3 a = (p + ik_detail::rotate(rot[s], local[joints[s + 1]].translation)) - p, b = reached[s + 1] - p;
      const float aa = glm::dot(a, a), bb = glm::dot(b, b);
      if (!(aa > 1e-24f && bb > 1e-24f)) continue;
      const glm::quat turned =
          ik_detail::renormalize(ik_detail::mul(ik_detail::mul(glm::conjugate(parentRot), ik_detail::fastFromTo(a, b, aa, bb)), rot[s]));
      local[joints[s]].rotation = turned;
      rot[s] = ik_detail::renormalize(ik_detail::mul(parentRot, turned));
    }
    error = c.maxError();
    if (c.stalled(error, settings)) break;
  }
  return it;
}

#endif

}  // namespace

IkResult solveFabrik(const IkProblem& problem, const IkSettings& settings) {
  IkChain& c = ik_detail::workspace();
  if (IkResult bad; !(bad.message = c.begin(problem, settings)).empty()) return bad;
  IkTrace* trace = settings.trace;
  const int m = static_cast<int>(c.joints.size());
  thread_local FabrikScratch scratch;  // per-slot arrays, reused from call to call
  std::vector<float>& boneLength = scratch.boneLength;
  boneLength.assign(m, 0.0f);
  for (int s = 0; s < m; ++s)
    if (c.parentSlot[s] >= 0) boneLength[s] = glm::length(c.position(s) - c.position(c.parentSlot[s]));
  // The paper's first test: a single target out of reach straightens the chain at once
  // (its reach: the sum of these bone lengths).
  if (c.straightenIfUnreachable(boneLength.data())) {
    c.record(trace, 1, IkStep::Straighten);
    return c.result(1, settings);
  }
  if (!trace && c.rigid && c.goals.size() == 1 && !c.goals[0].hasOrientation && !c.hasLimits()) {
    scratch.reached.resize(m);
    return c.result(plainPasses(c, settings, boneLength, scratch.reached), settings);
  }
  std::vector<int>& goalOf = scratch.goalOf;
  goalOf.assign(m, -1);
  for (int g = 0; g < static_cast<int>(c.goals.size()); ++g) goalOf[c.goals[g].slot] = g;
  std::vector<glm::vec3>&reached = scratch.reached, &sum = scratch.sum;
  reached.assign(m, glm::vec3(0.0f));
  sum.assign(m, glm::vec3(0.0f));
  std::vector<float>& count = scratch.count;
  count.assign(m, 0.0f);
  std::vector<glm::quat>& backRot = scratch.backRot;  // world rotations the backward pass gives the joints
  backRot.assign(m, glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
  std::vector<int>& proposals = scratch.proposals;  // how many children (or targets) set backRot
  proposals.assign(m, 0);
  std::vector<char>& twisted = scratch.twisted;  // backRot was turned to meet a child's limit
  twisted.assign(m, 0);
  std::vector<glm::quat>& limitedParent = scratch.limitedParent;  // the parent frame a slot's limit asked for
  limitedParent.assign(m, glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
  std::vector<char>& hasLimitedParent = scratch.hasLimitedParent;
  hasLimitedParent.assign(m, 0);
  std::vector<glm::vec3>&from = scratch.from, &to = scratch.to;
  std::vector<float>& fitWeight = scratch.fitWeight;
  std::vector<float>&fromSq = scratch.fromSq, &toSq = scratch.toSq;
  std::vector<int>& children = scratch.children;
  children.assign(m, 0);
  for (int s = 0; s < m; ++s)
    if (c.parentSlot[s] >= 0) ++children[c.parentSlot[s]];
  const bool finishWithDls = settings.fabrikFinishAfter > 0 && (c.hasLimits() || c.goals.size() > 1);
  float previousError = c.maxError();
  int it = 0;
  while (!c.converged(settings) && it < settings.maxIterations) {
    ++it;
    // Backward: children before parents (reverse preorder); each proposes where its
    // parent should be, at bone length from itself towards the parent's current place.
    // Limits act here too (Aristidou & Lasenby's constraint handling, run in reverse):
    // once a joint's own world rotation is settled by its child, its limit decides the
    // directions its parent's bone may take, and the proposal is re-projected into them.
    std::fill(sum.begin(), sum.end(), glm::vec3(0.0f));
    std::fill(count.begin(), count.end(), 0.0f);
    std::fill(proposals.begin(), proposals.end(), 0);
    std::fill(twisted.begin(), twisted.end(), 0);
    std::fill(hasLimitedParent.begin(), hasLimitedParent.end(), 0);
    for (int s = m - 1; s >= 0; --s) {
      const Goal* goal = goalOf[s] >= 0 ? &c.goals[goalOf[s]] : nullptr;
      if (goal) {
        sum[s] += goal->weight * goal->position;
        count[s] += goal->weight;
        if (goal->hasOrientation) {
          backRot[s] = goal->orientation;
          proposals[s] = 1;
        }
      }
      if (children[s] >= 2 && !(goal && goal->hasOrientation)) {  // a rigid sub-base: fit it
        glm::quat turn;
        reached[s] = rigidFit(c, s, reached, goal, limitedParent, hasLimitedParent, from, to, fitWeight, turn);
        backRot[s] = safeNormalize(turn * c.rotation[s]);
        proposals[s] = 1;  // its frame is settled: its own limit can act on its parent below
      } else {
        reached[s] = count[s] > 0.0f ? sum[s] / count[s] : c.position(s);
      }
      const int p = c.parentSlot[s];
      if (p < 0) continue;
      const glm::vec3 oldBone = c.position(s) - c.position(p);  // parent -> s, before this pass
      glm::vec3 dir = c.position(p) - reached[s];
      float len = glm::length(dir);
      if (!(len > 1e-12f)) {  // on top of the parent: keep the bone's current direction
        dir = -oldBone;
        len = glm::length(dir);
      }
      glm::vec3 proposal = len > 1e-12f ? reached[s] + dir * (boneLength[s] / len) : c.position(p);
      // The parent's world rotation after this pass, needed only where a limit reads it.
      const bool needRotation = c.limit[s] || c.limit[p];
      glm::quat parentRot = c.rotation[p];
      if (needRotation) parentRot = safeNormalize(fromToRotation(oldBone, reached[s] - proposal) * c.rotation[p]);
      // s's world rotation is known when exactly one thing set it (its only child, or an
      // orientation target); then clamp s's local rotation by moving the parent instead.
      if (c.limit[s] && proposals[s] == 1 && boneLength[s] > 1e-12f) {
        const glm::quat local = safeNormalize(glm::conjugate(parentRot) * backRot[s]);
        const glm::quat limited = applyJointLimit(*c.limit[s], c.skeleton->rest[c.joints[s]].rotation, local);
        parentRot = safeNormalize(backRot[s] * glm::conjugate(limited));
        // The bone's direction in the parent's frame is fixed; turn it with the frame.
        const glm::vec3 boneInParent = glm::conjugate(c.rotation[p]) * (oldBone / boneLength[s]);
        proposal = reached[s] - (parentRot * boneInParent) * boneLength[s];
        twisted[p] = 1;
        limitedParent[s] = parentRot;
        hasLimitedParent[s] = 1;
      }
      sum[p] += proposal;
      count[p] += 1.0f;
      backRot[p] = parentRot;
      ++proposals[p];
    }
    if (trace) c.recordPositions(trace, it, IkStep::FabrikBackward, reached, c.maxError());
    // Forward: from the fixed roots outwards; each joint turns its bone(s) towards the
    // backward positions of its children, within its limit.
    for (int s = 0; s < m; ++s) {
      if (c.parentSlot[s] >= 0) c.forwardSlot(s);
      const glm::vec3 p = c.position(s);
      // Bone directions as they are (from) and as the backward pass wants them (to), not
      // normalised: each use below normalises what it needs.
      from.clear();
      to.clear();
      fromSq.clear();
      toSq.clear();
      for (int k = s + 1; k < s + c.subtreeSize[s]; k += c.subtreeSize[k]) {
        const glm::vec3 a = c.childPosition(k) - p, b = reached[k] - p;
        const float aa = glm::dot(a, a), bb = glm::dot(b, b);
        if (aa > 1e-24f && bb > 1e-24f) {  // both longer than 1e-12
          from.push_back(a);
          to.push_back(b);
          fromSq.push_back(aa);
          toSq.push_back(bb);
        }
      }
      glm::quat local = c.pose->local[c.joints[s]].rotation;
      const glm::quat parentRot = c.parentRotation(s);
      if (goalOf[s] >= 0 && c.goals[goalOf[s]].hasOrientation && from.empty()) {
        local = glm::conjugate(parentRot) * c.goals[goalOf[s]].orientation;
      } else if (from.size() == 1 && twisted[s]) {
        // Start from the frame the backward pass chose to satisfy the child's limit (it
        // may twist about the bone, which a minimal rotation never would), then aim it.
        const glm::quat base = backRot[s];
        const glm::vec3 a = base * (glm::conjugate(c.rotation[s]) * from[0]);
        local = glm::conjugate(parentRot) * fromToRotation(a, to[0]) * base;
      } else if (from.size() == 1) {
        // Renormalised below with the other branches.
        local = ik_detail::mul(ik_detail::mul(glm::conjugate(parentRot), ik_detail::fastFromTo(from[0], to[0], fromSq[0], toSq[0])),
                               c.rotation[s]);
      } else if (from.size() > 1) {
        for (size_t i = 0; i < from.size(); ++i) {
          from[i] /= std::sqrt(fromSq[i]);
          to[i] /= std::sqrt(toSq[i]);
        }
        local = glm::conjugate(parentRot) * bestRotation(from, to) * c.rotation[s];
      } else {
        continue;
      }
      // A product of unit quaternions: renormalize is exact enough and much cheaper.
      local = ik_detail::renormalize(local);
      // Only a hinge child's plane asks for a twist (checked here first: it is rare).
      if (from.size() == 1 && s + 1 < m && c.limit[s + 1]) local = twistForHingeChild(c, s, parentRot, local, reached);
      if (c.limit[s]) local = applyJointLimit(*c.limit[s], c.skeleton->rest[c.joints[s]].rotation, local);
      c.pose->local[c.joints[s]].rotation = local;
      c.forwardRotation(s);
    }
    c.record(trace, it, IkStep::FabrikForward);
    const float error = c.maxError();
    if (c.stalled(error, settings)) break;
    // Hand over once the passes stop paying: at the cap, or when a pass gains < 20 %.
    if (finishWithDls && (it >= settings.fabrikFinishAfter || error > kSlowPass * previousError)) break;
    previousError = error;
  }
  // Hybrid finish: with limits or several effectors FABRIK gets close in a few passes and
  // then crawls (a hinge waiting for twist from a cone above it; two arms leaving a rigid
  // chest only a residual pull). Damped least squares steps, which move every joint at
  // once and clamp each to its limit, converge from there in a few iterations.
  if (finishWithDls && !c.converged(settings) && it < settings.maxIterations) {
    ik_detail::JacobianStepper stepper(c, ik_detail::JacobianMethod::Dls);
    while (!c.converged(settings) && it < settings.maxIterations) {
      ++it;
      if (!stepper.step(c, settings)) break;
      c.record(trace, it, IkStep::JacobianStep);
      if (c.stalled(c.maxError(), settings)) break;
    }
  }
  return c.result(it, settings);
}

}  // namespace kinema
