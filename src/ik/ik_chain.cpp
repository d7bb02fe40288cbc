#include "ik/ik_chain.h"

#include <algorithm>

#include "core/forward_kinematics.h"
#include "core/rotation.h"

namespace kinema::ik_detail {

std::string IkChain::begin(const IkProblem& problem, const IkSettings& settings) {
  std::string error = problem.validate();
  if (error.empty()) error = build(problem);
  if (error.empty()) record(settings.trace, 0, IkStep::Start);
  return error;
}

std::string IkChain::build(const IkProblem& problem, bool twoBone) {
  skeleton = problem.skeleton;
  pose = problem.pose;
  rig = problem.rig;
  const Skeleton& s = *skeleton;
  const int n = s.size();
  std::vector<int>& order = orderScratch;
  order.clear();
  const bool single = problem.targets.size() == 1;
  if (single) {
    // One target: the slots are its root..effector path, root first (the preorder of a
    // path), found by walking up from the effector (once to count, once to fill from the
    // end); no marking, no child search.
    const IkTarget& t = problem.targets[0];
    const int root = ikRootOf(s, t, twoBone);
    const int* parents = s.parents.data();
    int depth = 0;
    for (int j = t.effector; j >= 0; j = parents[j]) {
      ++depth;
      if (j == root) break;
    }
    joints.resize(depth);
    int* out = joints.data();
    for (int j = t.effector, i = depth - 1; i >= 0; j = parents[j]) out[i--] = j;
  } else {
    // Mark the union of root..effector paths.
    std::vector<char>& in = inScratch;
    in.assign(n, 0);
    for (const IkTarget& t : problem.targets) {
      const int root = ikRootOf(s, t, twoBone);
      for (int j = t.effector; j >= 0; j = s.parents[j]) {
        in[j] = 1;
        if (j == root) break;
      }
    }
    // Depth-first preorder over the marked joints: each marked joint's marked children,
    // in ascending order, listed once (parents come before children in the skeleton).
    std::vector<int>& childStart = stackScratch;  // per joint: start of its children in childList
    std::vector<int>& childList = slotOfScratch;
    childStart.assign(n + 1, 0);
    for (int c = 0; c < n; ++c)
      if (in[c] && s.parents[c] >= 0 && in[s.parents[c]]) ++childStart[s.parents[c] + 1];
    for (int j = 0; j < n; ++j) childStart[j + 1] += childStart[j];
    childList.assign(childStart[n], 0);
    std::vector<int>& fill = fillScratch;
    fill.assign(childStart.begin(), childStart.end() - 1);
    for (int c = 0; c < n; ++c)
      if (in[c] && s.parents[c] >= 0 && in[s.parents[c]]) childList[fill[s.parents[c]]++] = c;
    std::vector<int>& stack = dfsScratch;
    stack.clear();
    for (int j = n - 1; j >= 0; --j)
      if (in[j] && (s.parents[j] < 0 || !in[s.parents[j]])) stack.push_back(j);
    while (!stack.empty()) {
      const int j = stack.back();
      stack.pop_back();
      order.push_back(j);
      for (int k = childStart[j + 1] - 1; k >= childStart[j]; --k) stack.push_back(childList[k]);
    }
  }
  if (!single) joints = order;
  const int m = static_cast<int>(joints.size());
  // Every slot's entry is written below; fixedParent, fixedRotation and fixedPosition are
  // read only for slots whose parent lies outside (parentSlot -1).
  parentSlot.resize(m);
  subtreeSize.resize(m);
  fixedParent.resize(m);
  fixedRotation.resize(m);
  fixedPosition.resize(m);
  positions.resize(m);
  rotation.resize(m);
  limit.resize(m);
  // One target: slot i's parent is slot i - 1, and m - i slots hang from slot i. Several:
  // through the joint -> slot map.
  std::vector<int>& slotOf = slotOfScratch;
  if (single) {
    int* ps = parentSlot.data();
    int* sub = subtreeSize.data();
    for (int i = 0; i < m; ++i) {
      ps[i] = i - 1;
      sub[i] = m - i;
    }
  } else {
    std::fill(subtreeSize.begin(), subtreeSize.end(), 1);
    slotOf.assign(n, -1);
    for (int i = 0; i < m; ++i) slotOf[joints[i]] = i;
    for (int i = 0; i < m; ++i) {
      const int p = s.parents[joints[i]];
      parentSlot[i] = p >= 0 ? slotOf[p] : -1;
    }
    for (int i = m - 1; i >= 0; --i)
      if (parentSlot[i] >= 0) subtreeSize[parentSlot[i]] += subtreeSize[i];
  }
  // Unit rotations, and whether any slot has scale (then the chain is not rigid).
  bool unscaled = true;
  {
    Transform* local = pose->local.data();
    const int* js = joints.data();
#if defined(__SSE2__)
    // makeUnit's test (glm's quaternion dot, (w w + x x) + (y y + z z)) and the scale test
    // in SSE registers; makeUnit itself only where the test says so.
    const __m128 ones = _mm_set1_ps(1.0f);
    int scaled = 0;
    for (int i = 0; i < m; ++i) {
      Transform& t = local[js[i]];
      const __m128 q = simd::load(t.rotation), sq = _mm_mul_ps(q, q);
      const __m128 pairs = _mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 1, 2, 3)));
      const float d = _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(1, 1, 1, 1))));
      if (std::abs(d - 1.0f) > 1e-6f) t.rotation = safeNormalize(t.rotation);
      // Floats 6-9 of the transform: rotation.w, then the scale.
      scaled |= _mm_movemask_ps(_mm_cmpneq_ps(_mm_loadu_ps(&t.translation.x + 6), ones)) & 0xe;
    }
    unscaled = scaled == 0;
#else
    for (int i = 0; i < m; ++i) {
      Transform& t = local[js[i]];
      makeUnit(t.rotation);
      unscaled = unscaled && t.scale == glm::vec3(1.0f);
    }
#endif
  }
  anyLimit = false;
  if (rig) {
    for (int i = 0; i < m; ++i) anyLimit = (limit[i] = rig->limitOf(joints[i])) != nullptr || anyLimit;
  } else {
    std::fill(limit.begin(), limit.end(), nullptr);
  }
  // The fixed parents: the placement times the world of the joint above the slot (FK of
  // that joint's ancestors only). One target: only slot 0 has one.
  const bool identityPlacement = isIdentity(problem.rootTransform);
  bool fixedRigid = true;
  for (int i = 0; i < (single ? std::min(m, 1) : m); ++i) {
    if (parentSlot[i] >= 0) continue;
    const int p = s.parents[joints[i]];
    glm::mat4 parentWorld(1.0f);
    if (p >= 0) {
      std::vector<int>& up = stackScratch;
      up.clear();
      for (int j = p; j >= 0; j = s.parents[j]) up.push_back(j);
      parentWorld = pose->local[up.back()].toMatrix();  // as computeWorld: a root's world is its local
      for (auto it = up.rbegin() + 1; it != up.rend(); ++it)
        parentWorld = multiplyAffine(parentWorld, pose->local[*it].toMatrix());
    }
    if (identityPlacement && p < 0) {
      // No placement and no parent: the identity, exactly what the general branch gives.
      fixedParent[i] = glm::mat4(1.0f);
      fixedRotation[i] = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
      fixedPosition[i] = glm::vec3(0.0f);
      continue;
    }
    fixedParent[i] = p >= 0 ? problem.rootTransform * parentWorld : problem.rootTransform;
    fixedRotation[i] = rotationOf(fixedParent[i]);
    fixedPosition[i] = glm::vec3(fixedParent[i][3]);
    // The fixed parent must be a rotation (orthonormal columns) for the rigid shortcut.
    const glm::mat3 l(fixedParent[i]);
    const glm::mat3 ltl = glm::transpose(l) * l;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) fixedRigid = fixedRigid && std::abs(ltl[a][b] - (a == b ? 1.0f : 0.0f)) < 1e-6f;
  }
  rigid = fixedRigid && unscaled;
  chain = single;
  world.assign(rigid ? 0 : m, glm::mat4(1.0f));
  goals.clear();
  anyOrientation = false;
  for (const IkTarget& t : problem.targets) {
    Goal g;
    if (problem.targets.size() == 1) {
      g.slot = m - 1;
      g.rootSlot = 0;
    } else {
      g.slot = slotOf[t.effector];
      g.rootSlot = slotOf[ikRootOf(s, t, twoBone)];
    }
    g.position = t.position;
    g.hasOrientation = t.hasOrientation;
    // Read only where hasOrientation is set.
    if (t.hasOrientation) g.orientation = safeNormalize(t.orientation);
    g.weight = t.weight;
    anyOrientation = anyOrientation || g.hasOrientation;
    goals.push_back(g);
  }
  history.clear();
  forwardKinematics();
  return {};
}

void IkChain::forwardSlot(int s) {
  const Transform& t = pose->local[joints[s]];
  const int ps = parentSlot[s];
  const glm::quat parentRot = ps >= 0 ? rotation[ps] : fixedRotation[s];
  rotation[s] = renormalize(mul(parentRot, t.rotation));
  if (rigid) {
    // A quaternion product and a rotated vector: no matrix at all.
    positions[s] = (ps >= 0 ? positions[ps] : fixedPosition[s]) + rotate(parentRot, t.translation);
    return;
  }
  world[s] = multiplyAffine(ps >= 0 ? world[ps] : fixedParent[s], t.toMatrix());
  positions[s] = glm::vec3(world[s][3]);
}

glm::vec3 IkChain::childPosition(int child) const {
  const int s = parentSlot[child];
  const glm::vec3& t = pose->local[joints[child]].translation;
  if (rigid) return positions[s] + rotate(rotation[s], t);
  return glm::vec3(world[s] * glm::vec4(t, 1.0f));
}

void IkChain::forwardKinematics() {
  const int m = static_cast<int>(joints.size());
  if (!rigid) {
    for (int s = 0; s < m; ++s) forwardSlot(s);
    return;
  }
  // forwardSlot's rigid branch, inlined: every iterative solver runs this once a step.
  const Transform* local = pose->local.data();
#if defined(__SSE2__)
  if (chain) {
    // One target's path: each slot's parent is the previous one, slot 0's is fixed.
    const int* js = joints.data();
    glm::quat* rotOut = rotation.data();
    glm::vec3* posOut = positions.data();
    __m128 rot = simd::load(fixedRotation[0]), pos = simd::load3(fixedPosition[0]);
    for (int s = 0; s < m; ++s) {
      const Transform& t = local[js[s]];
      pos = _mm_add_ps(pos, simd::rotate(rot, _mm_loadu_ps(&t.translation.x)));
      rot = simd::renormalize(simd::mul(rot, simd::load(t.rotation)));
      simd::store(rotOut[s], rot);
      simd::store3(posOut[s], pos);
    }
    return;
  }
  // The previous slot's rotation and position stay in registers: along a chain (parent =
  // previous slot) nothing is read back from memory.
  __m128 rot = _mm_setzero_ps(), pos = _mm_setzero_ps();
  for (int s = 0; s < m; ++s) {
    const int ps = parentSlot[s];
    const Transform& t = local[joints[s]];
    __m128 parentRot = rot, parentPos = pos;
    if (ps != s - 1 || ps < 0) {
      parentRot = simd::load(ps >= 0 ? rotation[ps] : fixedRotation[s]);
      parentPos = simd::load3(ps >= 0 ? positions[ps] : fixedPosition[s]);
    }
    // t.translation is followed by t.rotation in memory: a 4-float load stays inside t.
    pos = _mm_add_ps(parentPos, simd::rotate(parentRot, _mm_loadu_ps(&t.translation.x)));
    rot = simd::renormalize(simd::mul(parentRot, simd::load(t.rotation)));
    simd::store(rotation[s], rot);
    simd::store3(positions[s], pos);
  }
#else
  for (int s = 0; s < m; ++s) {
    const int ps = parentSlot[s];
    const Transform& t = local[joints[s]];
    // References, not copies: GCC copies a selected quaternion through integer registers.
    const glm::quat& parentRot = ps >= 0 ? rotation[ps] : fixedRotation[s];
    const glm::vec3& parentPos = ps >= 0 ? positions[ps] : fixedPosition[s];
    const glm::vec3 p = parentPos + rotate(parentRot, t.translation);
    rotation[s] = renormalize(mul(parentRot, t.rotation));
    positions[s] = p;
  }
#endif
}

glm::quat IkChain::rotateJoint(int s, const glm::quat& delta) {
  Transform& t = pose->local[joints[s]];
  const glm::quat parentRot = parentRotation(s);
  glm::quat local = safeNormalize(glm::conjugate(parentRot) * delta * rotation[s]);
  if (limit[s]) local = applyJointLimit(*limit[s], skeleton->rest[joints[s]].rotation, local);
  t.rotation = local;
  const glm::quat newWorld = safeNormalize(parentRot * local);
  const glm::quat applied = safeNormalize(newWorld * glm::conjugate(rotation[s]));
  // Carry the slot and its sub-tree along rigidly about the slot's position.
  const glm::mat3 r = glm::mat3_cast(applied);
  const glm::vec3 pivot = position(s);
  for (int k = s; k < s + subtreeSize[s]; ++k) {
    positions[k] = pivot + r * (positions[k] - pivot);
    rotation[k] = safeNormalize(applied * rotation[k]);
    if (rigid) continue;
    glm::mat4& w = world[k];
    for (int c = 0; c < 3; ++c) w[c] = glm::vec4(r * glm::vec3(w[c]), 0.0f);
    w[3] = glm::vec4(positions[k], 1.0f);
  }
  rotation[s] = newWorld;
  return applied;
}

void IkChain::setLocalRotation(int s, const glm::quat& localIn) {
  glm::quat local = safeNormalize(localIn);
  if (limit[s]) local = applyJointLimit(*limit[s], skeleton->rest[joints[s]].rotation, local);
  pose->local[joints[s]].rotation = local;
  for (int k = s; k < s + subtreeSize[s]; ++k) forwardSlot(k);
}

float IkChain::maxErrorOfAll() const {
  float e = 0.0f;
  for (const Goal& g : goals) e = std::max(e, goalError(g));
  return e;
}

float IkChain::orientationError() const {
  float e = 0.0f;
  for (const Goal& g : goals) {
    if (!g.hasOrientation) continue;
    const glm::quat d = g.orientation * glm::conjugate(rotation[g.slot]);
    e = std::max(e, 2.0f * std::atan2(glm::length(glm::vec3(d.x, d.y, d.z)), std::abs(d.w)));
  }
  return e;
}


bool IkChain::stalled(float error, const IkSettings& settings) {
  history.push_back(error);
  const int w = settings.stallWindow;
  if (settings.stallFraction <= 0.0f || w <= 0 || static_cast<int>(history.size()) <= w) return false;
  const float before = history[history.size() - 1 - w];
  return before - error <= settings.stallFraction * before;
}


float IkChain::reach(const Goal& g, const float* boneLength) const {
  float r = 0.0f;
  for (int s = g.slot; s != g.rootSlot && parentSlot[s] >= 0; s = parentSlot[s])
    r += boneLength ? boneLength[s] : glm::length(position(s) - position(parentSlot[s]));
  return r;
}

bool IkChain::straightenIfUnreachable(const float* boneLength) {
  if (goals.size() != 1 || hasLimits()) return false;
  const Goal& g = goals[0];
  const glm::vec3 toTarget = g.position - position(g.rootSlot);
  const float d = glm::length(toTarget);
  if (!(d > reach(g, boneLength)) || !(d > 0.0f)) return false;
  const glm::vec3 u = toTarget / d;
  // One target: the slots are its chain, root first, each the parent of the next. Root
  // down, each joint turns its bone (as its ancestors' turns `turned` left it) onto u;
  // one FK at the end places the chain. O(chain), where turning each joint's sub-tree
  // along would be O(chain^2).
  glm::quat turned(1.0f, 0.0f, 0.0f, 0.0f);
  glm::quat parentWorld = parentRotation(g.rootSlot);
  for (int s = g.rootSlot; s < g.slot; ++s) {
    const glm::vec3 bone = rotate(turned, position(s + 1) - position(s));
    glm::quat world = renormalize(mul(turned, rotation[s]));
    if (glm::dot(bone, bone) > 0.0f) {
      const glm::quat delta = fromToRotation(bone, u);
      world = renormalize(mul(delta, world));
      turned = renormalize(mul(delta, turned));
    }
    pose->local[joints[s]].rotation = renormalize(mul(glm::conjugate(parentWorld), world));
    parentWorld = world;
  }
  forwardKinematics();
  return true;
}

void IkChain::record(IkTrace* trace, int iteration, IkStep step, int joint) const {
  if (!trace) return;
  if (trace->joints.empty()) trace->joints = joints;
  IkTraceEntry e;
  e.iteration = iteration;
  e.step = step;
  e.joint = joint;
  e.error = maxError();
  e.positions.reserve(joints.size());
  for (int s = 0; s < static_cast<int>(joints.size()); ++s) e.positions.push_back(position(s));
  trace->entries.push_back(std::move(e));
}

void IkChain::recordPositions(IkTrace* trace, int iteration, IkStep step, const std::vector<glm::vec3>& positions,
                              float error) const {
  if (!trace) return;
  if (trace->joints.empty()) trace->joints = joints;
  IkTraceEntry e;
  e.iteration = iteration;
  e.step = step;
  e.error = error;
  e.positions = positions;
  trace->entries.push_back(std::move(e));
}

IkChain& workspace() {
  thread_local IkChain chain;
  return chain;
}

IkResult IkChain::result(int iterations, const IkSettings& settings) const {
  IkResult r;
  r.iterations = iterations;
  r.error = maxError();
  r.converged = converged(settings);
  return r;
}

}  // namespace kinema::ik_detail
