// Teaching mode's model: one case solved by several solvers, each run recorded as an
// IkTrace and replayed through a cursor (see solver_comparison.h).
#include "ik/solver_comparison.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace kinema {

namespace {

std::string number(float v) {
  // The shortest text that reads back as the same float (the CLI parses it as a double
  // and rounds to float), so the printed command reproduces the case exactly.
  char buf[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, static_cast<double>(v));
    if (static_cast<float>(std::strtod(buf, nullptr)) == v) break;
  }
  return buf;
}

IkProblem problemFor(const TeachingSkeleton& chain, const glm::vec3& target, Pose& pose) {
  IkProblem p;
  p.skeleton = &chain.skeleton;
  p.pose = &pose;
  p.rig = chain.rig.empty() ? nullptr : &chain.rig;
  IkTarget t;
  t.effector = chain.skeleton.size() - 1;
  t.position = target;
  p.targets.push_back(t);
  return p;
}

// A planar chain is drawn and solved in its own plane: the target goes there too.
glm::vec3 placedTarget(const TeachingCase& setup) {
  glm::vec3 t = setup.target;
  if (setup.chain.planar) t.z = setup.chain.base.z;
  return t;
}

}  // namespace

std::string TeachingChain::validate() const {
  if (boneLengths.empty()) return "the chain has no bones";
  for (size_t i = 0; i < boneLengths.size(); ++i)
    if (!std::isfinite(boneLengths[i]) || !(boneLengths[i] > 0.0f))
      return "bone " + std::to_string(i) + " length must be a finite number > 0";
  if (startAngles.size() != boneLengths.size())
    return "give one start angle per bone (" + std::to_string(boneLengths.size()) + " bones, " +
           std::to_string(startAngles.size()) + " angles)";
  for (float a : startAngles)
    if (!std::isfinite(a)) return "a start angle is not finite";
  if (!isFinite(base)) return "the chain's base is not finite";
  if (!limits.empty() && limits.size() != boneLengths.size() + 1)
    return "give no limits or one per joint (" + std::to_string(boneLengths.size() + 1) + ")";
  for (const JointLimit& l : limits)
    if (const std::string bad = l.validate(); !bad.empty()) return bad;
  return {};
}

float TeachingChain::reach() const {
  float r = 0.0f;
  for (float l : boneLengths) r += l;
  return r;
}

TeachingSkeleton makeTeachingSkeleton(const TeachingChain& chain) {
  TeachingSkeleton out;
  const int bones = static_cast<int>(chain.boneLengths.size());
  for (int j = 0; j <= bones; ++j) {
    Transform rest;
    rest.translation = j == 0 ? chain.base : glm::vec3(chain.boneLengths[j - 1], 0.0f, 0.0f);
    if (j < bones && j < static_cast<int>(chain.startAngles.size()))
      rest.rotation = glm::angleAxis(chain.startAngles[j], glm::vec3(0.0f, 0.0f, 1.0f));
    out.skeleton.addJoint("j" + std::to_string(j), j - 1, rest);
  }
  out.start = Pose::rest(out.skeleton);
  if (!chain.limits.empty()) {
    out.rig.limits = chain.limits;
    // Hinges about Z are given as angles relative to the parent bone; the solvers clamp
    // relative to the rest pose, which starts at startAngles[j].
    for (int j = 0; j < bones && j < static_cast<int>(out.rig.limits.size()); ++j) {
      JointLimit& l = out.rig.limits[j];
      if (l.type != JointLimitType::Hinge) continue;
      const float sign = glm::dot(l.axis, glm::vec3(0.0f, 0.0f, 1.0f));
      if (std::abs(std::abs(sign) - 1.0f) > 1e-4f) continue;
      const float start = j < static_cast<int>(chain.startAngles.size()) ? chain.startAngles[j] : 0.0f;
      l.minAngle -= sign * start;
      l.maxAngle -= sign * start;
    }
  }
  return out;
}

std::string TeachingCase::validate() const {
  if (name.empty()) return "the case has no name";
  if (const std::string bad = chain.validate(); !bad.empty()) return name + ": " + bad;
  if (!isFinite(target)) return name + ": the target is not finite";
  if (solvers.empty() || solvers.size() > 3) return name + ": give one to three solvers";
  for (IkSolver s : solvers)
    if (s == IkSolver::TwoBone && chain.boneLengths.size() != 2)
      return name + ": the two-bone solver needs a chain of exactly two bones";
  if (!std::isfinite(settings.tolerance) || settings.tolerance < 0.0f) return name + ": tolerance must be >= 0";
  if (settings.maxIterations < 1) return name + ": the iteration cap must be at least 1";
  return {};
}

IkSettings settingsFor(const TeachingCase& setup, IkSolver solver) {
  IkSettings s = setup.settings;
  s.trace = nullptr;
  // Buss's transpose step needs many small steps; `kinema ik` allows it 2000 as well.
  if (solver == IkSolver::JacobianTranspose) s.maxIterations = std::max(s.maxIterations, 2000);
  return s;
}

std::vector<std::string> ikCommandArguments(const TeachingCase& setup, IkSolver solver) {
  const IkSettings s = settingsFor(setup, solver);
  const glm::vec3 t = placedTarget(setup);
  std::vector<std::string> args{"--solver", toString(solver),
                                "--effector", "j" + std::to_string(setup.chain.boneLengths.size()),
                                "--target", number(t.x) + "," + number(t.y) + "," + number(t.z),
                                "--tolerance", number(s.tolerance),
                                "--max-iterations", std::to_string(s.maxIterations)};
  if (solver == IkSolver::JacobianDls) {
    args.push_back("--lambda");
    args.push_back(number(s.dlsLambda));
  }
  if (solver == IkSolver::Fabrik) {
    args.push_back("--fabrik-finish-after");
    args.push_back(std::to_string(s.fabrikFinishAfter));
  }
  return args;
}

namespace {
// Largest error per iteration over entries [0, end).
std::vector<float> convergenceOf(const std::vector<IkTraceEntry>& entries, size_t end) {
  std::vector<float> out;
  for (size_t k = 0; k < end && k < entries.size(); ++k) {
    const IkTraceEntry& e = entries[k];
    if (e.iteration < 0) continue;
    if (static_cast<int>(out.size()) <= e.iteration) out.resize(e.iteration + 1, -1.0f);
    out[e.iteration] = e.error;  // the last entry of each iteration wins
  }
  // An iteration with no entry (none should be missing) keeps the error before it.
  for (size_t i = 1; i < out.size(); ++i)
    if (out[i] < 0.0f) out[i] = out[i - 1];
  return out;
}
}  // namespace

std::vector<float> SolverRun::convergence() const { return convergenceOf(trace.entries, trace.entries.size()); }

std::vector<float> SolverRun::convergenceSoFar() const {
  return convergenceOf(trace.entries, static_cast<size_t>(std::max(cursor, 0)) + 1);
}

std::string startComparison(const TeachingCase& setup, SolverComparison& out, int timingRepeats) {
  if (const std::string bad = setup.validate(); !bad.empty()) return bad;
  out.setup = setup;
  out.setup.target = placedTarget(setup);
  out.chain = makeTeachingSkeleton(setup.chain);
  out.runs.clear();
  for (IkSolver solver : setup.solvers) {
    SolverRun run;
    run.solver = solver;
    IkSettings settings = settingsFor(out.setup, solver);
    Pose pose = out.chain.start;
    IkProblem problem = problemFor(out.chain, out.setup.target, pose);
    settings.trace = &run.trace;
    run.result = solveIk(solver, problem, settings);
    if (!run.result.message.empty()) return setup.name + ": " + toString(solver) + ": " + run.result.message;
    settings.trace = nullptr;
    std::vector<double> times;
    for (int r = 0; r < std::max(1, timingRepeats); ++r) {
      Pose p = out.chain.start;
      IkProblem timed = problemFor(out.chain, out.setup.target, p);
      const auto t0 = std::chrono::steady_clock::now();
      solveIk(solver, timed, settings);
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    run.totalMilliseconds = times[times.size() / 2];
    run.millisecondsPerIteration = run.totalMilliseconds / std::max(1, run.result.iterations);
    out.runs.push_back(std::move(run));
  }
  return {};
}

void stepSubStep(SolverComparison& c) {
  for (SolverRun& r : c.runs)
    if (!r.finished()) ++r.cursor;
}

void stepIteration(SolverComparison& c) {
  for (SolverRun& r : c.runs) {
    if (r.finished()) continue;
    // Inside an iteration (a CCD sweep half done, a FABRIK backward pass shown): finish it,
    // as a lecturer's "next iteration" means; at an iteration's end: the whole next one.
    const int last = static_cast<int>(r.trace.entries.size()) - 1;
    const int current = r.current().iteration;
    const bool inside = current > 0 && r.trace.entries[r.cursor + 1].iteration == current;
    const int goal = inside ? current : current + 1;
    while (r.cursor < last && r.trace.entries[r.cursor + 1].iteration <= goal) ++r.cursor;
  }
}

void runToEnd(SolverComparison& c) {
  for (SolverRun& r : c.runs) r.cursor = std::max(0, static_cast<int>(r.trace.entries.size()) - 1);
}

void resetCursors(SolverComparison& c) {
  for (SolverRun& r : c.runs) r.cursor = 0;
}

std::string setTarget(SolverComparison& c, const glm::vec3& target) {
  TeachingCase setup = c.setup;
  setup.target = target;
  return startComparison(setup, c);
}

std::string setChain(SolverComparison& c, const TeachingChain& chain) {
  TeachingCase setup = c.setup;
  setup.chain = chain;
  return startComparison(setup, c);
}

}  // namespace kinema
