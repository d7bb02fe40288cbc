#include "ik/ik_posing_job.h"

#include <algorithm>
#include <chrono>

#include "core/forward_kinematics.h"
#include "core/rotation.h"

namespace kinema {

namespace {

glm::vec3 positionOf(const glm::mat4& m) { return glm::vec3(m[3]); }


struct Job {
  int index;  // into targets, -1 = temporary
  const PoseIkTarget* target;
};

}  // namespace

std::vector<IkTargetReport> solveIkPosing(const IkPosingInput& in, Pose& pose) {
  std::vector<IkTargetReport> reports;
  if (!in.skeleton || !in.targets) return reports;
  const Skeleton& skeleton = *in.skeleton;
  std::vector<PoseIkTarget>& targets = *in.targets;
  const int count = static_cast<int>(targets.size());

  // Stable order: the temporary (auto-IK) target, the driven one, then pinned ones.
  std::vector<Job> jobs;
  if (in.temporary && in.temporary->active) jobs.push_back({-1, in.temporary});
  if (in.driven >= 0 && in.driven < count && targets[in.driven].active) jobs.push_back({in.driven, &targets[in.driven]});
  for (int i = 0; i < count; ++i)
    if (i != in.driven && targets[i].active && targets[i].pinned) jobs.push_back({i, &targets[i]});

  IkRig rig;
  if (in.limits) rig.limits = *in.limits;
  std::vector<glm::mat4> world;
  if (!jobs.empty()) {
    reports.resize(jobs.size());
    std::vector<bool> usable(jobs.size(), true);
    auto measure = [&] {
      computeWorld(skeleton, pose, world);
      bool all = true;
      for (size_t k = 0; k < jobs.size(); ++k) {
        const IkTarget& t = jobs[k].target->target;
        reports[k].error = glm::distance(positionOf(world[t.effector]), t.position);
        reports[k].converged = usable[k] && reports[k].error <= in.settings.tolerance;
        if (usable[k] && !reports[k].converged) all = false;
      }
      return all;
    };
    // First each target with its own solver, in order.
    for (size_t k = 0; k < jobs.size(); ++k) {
      IkTargetReport& report = reports[k];
      report.target = jobs[k].index;
      IkProblem problem;
      problem.skeleton = &skeleton;
      problem.pose = &pose;
      problem.rig = &rig;
      problem.targets = {jobs[k].target->resolved(skeleton)};
      const auto start = std::chrono::steady_clock::now();
      const IkResult result = solveIk(jobs[k].target->solver, problem, in.settings);
      report.milliseconds += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (!result.message.empty()) {
        usable[k] = false;  // an unusable target (two-bone on a longer chain...) is skipped
        continue;
      }
      report.iterations += result.iterations;
    }
    if (!measure() && jobs.size() > 1) {
      // Overlapping chains (a pinned elbow inside the dragged hand's chain) fight when
      // solved one after the other: solve the usable targets together with damped least
      // squares, which takes several effectors and the limits.
      IkProblem problem;
      problem.skeleton = &skeleton;
      problem.pose = &pose;
      problem.rig = &rig;
      std::vector<size_t> together;
      for (size_t k = 0; k < jobs.size(); ++k) {
        if (!usable[k]) continue;
        IkTarget t = jobs[k].target->resolved(skeleton);
        if (t.root < 0) t.root = ikRootOf(skeleton, t, jobs[k].target->solver == IkSolver::TwoBone);
        problem.targets.push_back(t);
        together.push_back(k);
      }
      // A chain inside another one (a pinned elbow under a dragged hand's chain) is moved
      // by the outer chain's upper joints too, so in the joint solve it may use them.
      for (IkTarget& t : problem.targets)
        for (const IkTarget& o : problem.targets)
          if (o.root < t.root && skeleton.isInSubtree(t.root, o.root)) t.root = o.root;
      IkSettings settings = in.settings;
      settings.maxIterations = std::max(settings.maxIterations, kIkJointIterations);
      const auto start = std::chrono::steady_clock::now();
      const IkResult result = solveIk(IkSolver::JacobianDls, problem, settings);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      for (size_t k : together) {
        reports[k].iterations += result.iterations;
        reports[k].milliseconds += ms / static_cast<double>(together.size());
      }
      measure();
    }
  }

  // Every other active target follows its effector.
  bool followers = false;
  for (int i = 0; i < count; ++i)
    if (i != in.driven && targets[i].active && !targets[i].pinned) followers = true;
  if (followers) {
    if (world.size() != static_cast<size_t>(skeleton.size())) computeWorld(skeleton, pose, world);
    for (int i = 0; i < count; ++i) {
      if (i == in.driven || !targets[i].active || targets[i].pinned) continue;
      IkTarget& t = targets[i].target;
      if (t.effector < 0 || t.effector >= skeleton.size()) continue;
      t.position = positionOf(world[t.effector]);
      if (t.hasOrientation) t.orientation = rotationOf(world[t.effector]);
    }
  }
  return reports;
}

}  // namespace kinema
