// Fuzzes the IK solvers with arbitrary numbers (NaN, Inf, denormals, huge values) as bone
// offsets, start rotations, limits and targets. A solver must never crash; when validate()
// accepts the problem, the pose it leaves must be finite with unit rotations, and bone
// lengths must be unchanged (only local rotations may change).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/forward_kinematics.h"
#include "ik/ik_solver.h"
#include "ik/joint_limits.h"

namespace {
struct Bytes {
  const std::uint8_t* p;
  const std::uint8_t* end;
  float f() {
    float v = 0.0f;
    if (end - p >= 4) {
      std::memcpy(&v, p, 4);
      p += 4;
    }
    return v;
  }
  std::uint8_t b() { return p < end ? *p++ : 0; }
  glm::vec3 v3() {
    const float x = f(), y = f();
    return glm::vec3(x, y, f());
  }
};
// Says which invariant broke before aborting, so a crash file explains itself.
[[noreturn]] void fail(const char* what, int joint = -1) {
  std::fprintf(stderr, "fuzz_ik: %s (joint %d)\n", what, joint);
  std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  if (size < 4) return 0;
  Bytes in{data, data + size};
  const int solverCount = 7;  // two-bone, CCD, FABRIK, transpose, pseudo-inverse, DLS, SDLS
  const auto solver = static_cast<kinema::IkSolver>(in.b() % solverCount);
  const int joints = 2 + in.b() % 7;
  const std::uint8_t flags = in.b();

  kinema::Skeleton skeleton;
  for (int i = 0; i < joints; ++i) {
    // Branch once (joint 3 hangs off joint 1) when asked, so sub-bases are fuzzed too.
    const int parent = i == 0 ? -1 : ((flags & 1) && i == 3 ? 1 : i - 1);
    kinema::Transform t = kinema::Transform::fromTranslation(in.v3());
    skeleton.addJoint("j" + std::to_string(i), parent, t);
  }
  kinema::Pose pose = kinema::Pose::rest(skeleton);
  for (int i = 0; i < joints; ++i) {
    const float x = in.f(), y = in.f(), z = in.f();
    const float w = in.f();
    pose.local[i].rotation = glm::quat(w, x, y, z);  // possibly not unit, zero or NaN
  }
  kinema::IkRig rig;
  if (flags & 2) {
    for (int i = 0; i < joints; ++i) {
      const std::uint8_t kind = in.b() % 4;
      kinema::JointLimit l;
      if (kind == 1) l = kinema::JointLimit::hinge(in.v3(), in.f(), in.f());
      if (kind == 2) l = kinema::JointLimit::cone(in.v3(), in.f(), in.f(), in.f());
      if (kind == 3) l = kinema::JointLimit::euler(kinema::EulerOrder::XYZ, in.v3(), in.v3());
      rig.setLimit(joints, i, l);
    }
  }
  kinema::IkProblem problem;
  problem.skeleton = &skeleton;
  problem.pose = &pose;
  problem.rig = &rig;
  const int targets = 1 + ((flags >> 2) & 1);
  for (int k = 0; k < targets; ++k) {
    kinema::IkTarget t;
    t.effector = joints - 1 - k;
    t.position = in.v3();
    t.weight = (flags & 8) ? in.f() : 1.0f;
    if (flags & 16) {
      t.hasOrientation = true;
      const float x = in.f(), y = in.f(), z = in.f();
      t.orientation = glm::quat(in.f(), x, y, z);
    }
    if (flags & 32) {
      t.hasPole = true;
      t.pole = in.v3();
    }
    problem.targets.push_back(t);
  }
  kinema::IkSettings settings;
  settings.maxIterations = 1 + in.b() % 32;
  if (flags & 64) settings.tolerance = in.f();
  if (flags & 128) settings.maxStepAngle = in.f();
  settings.transposeLineSearch = in.b() & 1;  // read last: older corpus files keep their meaning

  const bool twoBone = solver == kinema::IkSolver::TwoBone;
  const bool valid = problem.validate(twoBone).empty();
  const std::vector<kinema::Transform> start = pose.local;
  const kinema::IkResult result = kinema::solveIk(solver, problem, settings);  // must not crash
  if (!valid) {
    // Refused input is reported and leaves the pose untouched.
    if (result.message.empty()) fail("invalid input not reported");
    for (int i = 0; i < joints; ++i)
      if (std::memcmp(&start[i], &pose.local[i], sizeof(kinema::Transform)) != 0) fail("refused input changed the pose", i);
    return 0;
  }
  // The joints the solver may move: each target's chain, effector up to its IK root.
  std::vector<bool> inChain(joints, false);
  for (const kinema::IkTarget& t : problem.targets) {
    const int root = kinema::ikRootOf(skeleton, t, twoBone);
    for (int j = t.effector; j >= 0; j = skeleton.parents[j]) {
      inChain[j] = true;
      if (j == root) break;
    }
  }
  for (int i = 0; i < joints; ++i) {
    const kinema::Transform& t = pose.local[i];
    // Only local rotations change: translations (so bone lengths) stay bit for bit.
    if (std::memcmp(&t.translation, &start[i].translation, sizeof t.translation) != 0) fail("translation changed", i);
    if (!inChain[i]) continue;
    if (!kinema::isFinite(t.rotation)) fail("rotation not finite", i);
    if (std::abs(glm::length(t.rotation) - 1.0f) > 1e-3f) fail("rotation not unit", i);
  }
  if (std::isnan(result.error)) fail("error is NaN");
  return 0;
}
