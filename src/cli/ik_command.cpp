#include "cli/ik_command.h"

#include "cli/ik_trace_json.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "cli/finite_results.h"
#include "core/forward_kinematics.h"
#include "ik/ik_solver.h"
#include "io/json_number.h"
#include "io/kinema_file.h"
#include "io/text_file.h"

namespace kinema::cli {

namespace {

enum class Parsed { Ok, Malformed, NotFinite, TooFar };

// IK runs in float; a coordinate beyond this is refused as bad input (exit 1) so that
// squared distances and the reported error stay finite (1.85e19 squared overflows float).
constexpr double kMaxTargetCoordinate = 1e18;

// "X,Y,Z": three numbers separated by commas. Denormals (1e-310) are numbers like any other;
// a number that overflows double (1e400) is not finite.
Parsed parseVec3(const std::string& text, glm::vec3& out) {
  std::stringstream ss(text);
  std::string part;
  int n = 0;
  bool finite = true, near = true;
  while (std::getline(ss, part, ',')) {
    if (n == 3) return Parsed::Malformed;
    const size_t start = part.find_first_not_of(" \t");
    if (start == std::string::npos) return Parsed::Malformed;
    const char* begin = part.c_str() + start;
    char* end = nullptr;
    const double v = std::strtod(begin, &end);  // unlike std::stod, no throw on underflow
    if (end == begin || std::string(end).find_first_not_of(" \t") != std::string::npos) return Parsed::Malformed;
    if (!std::isfinite(v) || std::abs(v) > 3.0e38) finite = false;
    else if (std::abs(v) > kMaxTargetCoordinate) near = false;
    out[n++] = static_cast<float>(v);
  }
  if (n != 3 || (!text.empty() && text.back() == ',')) return Parsed::Malformed;
  return !finite ? Parsed::NotFinite : !near ? Parsed::TooFar : Parsed::Ok;
}

bool withinReach(const glm::vec3& p) {
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(static_cast<double>(p[k])) <= kMaxTargetCoordinate)) return false;
  return true;
}

}  // namespace

CLI::App* addIkCommand(CLI::App& app, IkOptions& o) {
  CLI::App* cmd = app.add_subcommand("ik", "Move joints so effectors reach targets (inverse kinematics)");
  cmd->add_option("file", o.file, "A .bvh or .kinema file")->required();
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  cmd->add_option("--effector", o.effectors, "Effector joint name (repeat for several targets)");
  cmd->add_option("--target", o.targets, "Target position X,Y,Z (one per --effector)");
  cmd->add_option("--root", o.roots,
                  "IK root joint per effector (default: its topmost ancestor; for two-bone its grandparent)");
  cmd->add_option("--rig", o.rig, "JSON rig file: {\"limits\": [...], \"targets\": [...]} as in .kinema files");
  cmd->add_option("--solver", o.solver, "ccd, fabrik, jacobian-transpose, jacobian-pinv, jacobian-dls, jacobian-sdls or two-bone");
  cmd->add_option("--tolerance", o.tolerance, "Converged when every effector is this close (file units; default 0.001)");
  cmd->add_option("--max-iterations", o.maxIterations, "Iteration cap (default 100; 2000 for jacobian-transpose)");
  cmd->add_option("--lambda", o.lambda, "jacobian-dls damping, as a fraction of the chain's reach (default 0.1)");
  cmd->add_option("--pole", o.pole, "two-bone: X,Y,Z point the middle joint bends towards");
  cmd->add_option("--soften", o.soften, "two-bone: soften distance near full extension (default 0)");
  cmd->add_option("--fabrik-finish-after", o.fabrikFinishAfter,
                  "fabrik with limits or several targets: DLS finishes after at most N passes (default 10; 0 = passes only)");
  cmd->add_option("--clip", o.clip, "Clip index (default 0)");
  o.timeOption = cmd->add_option("--time", o.time, "Start from the pose at this time (seconds)");
  o.frameOption = cmd->add_option("--frame", o.frame, "Start from the pose at this frame");
  o.timeOption->excludes(o.frameOption);
  cmd->add_flag("--trace", o.trace, "Include every solver step (joint positions and error) in the JSON");
  cmd->add_flag("--json", o.json, "Print JSON (the stable contract) instead of a summary");
  addUpOption(cmd, o.up);
  return cmd;
}

int runIk(const IkOptions& o) {
  const std::optional<IkSolver> solver = ikSolverFromString(o.solver);
  if (!solver) return usageError("ik", "--solver '" + o.solver + "' is not one of ccd, fabrik, jacobian-transpose, jacobian-pinv, jacobian-dls, jacobian-sdls, two-bone");
  if (o.effectors.size() != o.targets.size())
    return usageError("ik", "give one --target per --effector (" + std::to_string(o.effectors.size()) + " effectors, " +
                 std::to_string(o.targets.size()) + " targets)");
  if (!o.roots.empty() && o.roots.size() != o.effectors.size())
    return usageError("ik", "give --root once per --effector, or not at all");
  std::vector<glm::vec3> positions(o.targets.size());
  for (size_t i = 0; i < o.targets.size(); ++i) {
    const Parsed p = parseVec3(o.targets[i], positions[i]);
    if (p == Parsed::Malformed) return usageError("ik", "--target '" + o.targets[i] + "' is not X,Y,Z");
    if (p == Parsed::NotFinite) return badInput("--target '" + o.targets[i] + "' is not a finite position");
    if (p == Parsed::TooFar) return badInput("--target '" + o.targets[i] + "' is too far: coordinates must be within 1e18");
  }
  glm::vec3 pole(0.0f);
  if (!o.pole.empty()) {
    const Parsed p = parseVec3(o.pole, pole);
    if (p == Parsed::Malformed) return usageError("ik", "--pole '" + o.pole + "' is not X,Y,Z");
    if (p == Parsed::NotFinite) return badInput("--pole '" + o.pole + "' is not a finite position");
    if (p == Parsed::TooFar) return badInput("--pole '" + o.pole + "' is too far: coordinates must be within 1e18");
  }
  if (!std::isfinite(o.time)) return badInput("--time must be a finite number");
  if (!std::isfinite(o.tolerance) || o.tolerance < 0) return badInput("--tolerance must be a finite number >= 0");
  if (!std::isfinite(o.lambda) || o.lambda < 0) return badInput("--lambda must be a finite number >= 0");
  if (!std::isfinite(o.soften) || o.soften < 0) return badInput("--soften must be a finite number >= 0");
  if (o.maxIterations == 0 || o.maxIterations < -1) return badInput("--max-iterations must be at least 1");
  if (o.fabrikFinishAfter < 0) return badInput("--fabrik-finish-after must be >= 0");

  Result<Scene> loaded = loadSceneOrDefault(o.file, inputLimits(o.allowOutsidePaths), upAxisOf(o.up));
  if (!loaded) return badInput(loaded.error());
  const Scene& scene = loaded.value();
  const Skeleton& skeleton = scene.skeleton;
  if (const std::string bad = clipIndexError(scene, o.clip); !bad.empty()) return badInput(bad);
  const double time = o.frameOption->count() ? static_cast<double>(o.frame) * scene.frameGrid(o.clip).secondsPerFrame : o.time;
  Pose pose = sampledPose(scene, o.clip, time);
  if (const std::string bad = nonFiniteWorldError(scene, computeWorld(skeleton, pose), time); !bad.empty())
    return badInput(bad);

  IkRig rig = scene.ik;
  std::vector<IkTarget> targets;
  if (!o.rig.empty()) {
    std::string text;
    const std::string err = readTextFile(o.rig, text);
    if (!err.empty()) return badInput(err);
    Result<IkRig> extra = parseIkRigJson(text, o.rig, skeleton);
    if (!extra) return badInput(extra.error());
    for (int j = 0; j < static_cast<int>(extra->limits.size()); ++j)
      if (extra->limits[j].active()) rig.setLimit(skeleton.size(), j, extra->limits[j]);
    targets = extra->targets;
  }
  for (size_t i = 0; i < o.effectors.size(); ++i) {
    IkTarget t;
    t.effector = skeleton.find(o.effectors[i]);
    if (t.effector < 0) return badInput(scene.source + ": --effector: no joint named '" + o.effectors[i] + "'");
    if (!o.roots.empty()) {
      t.root = skeleton.find(o.roots[i]);
      if (t.root < 0) return badInput(scene.source + ": --root: no joint named '" + o.roots[i] + "'");
    }
    t.position = positions[i];
    t.hasPole = !o.pole.empty();
    t.pole = pole;
    targets.push_back(t);
  }
  if (targets.empty()) targets = scene.ik.targets;  // the file's saved targets
  if (targets.empty()) return usageError("ik", "give --effector NAME --target X,Y,Z (or --rig FILE)");
  for (const IkTarget& t : targets)  // the file's and the rig's targets as well as --target
    if (!withinReach(t.position) || (t.hasPole && !withinReach(t.pole)))
      return badInput(scene.source + ": the target of " + jointLabel(scene, t.effector) +
                      " is too far: coordinates must be within 1e18");

  IkProblem problem;
  problem.skeleton = &skeleton;
  problem.pose = &pose;
  problem.rig = rig.empty() ? nullptr : &rig;
  problem.targets = targets;
  IkSettings settings;
  settings.tolerance = static_cast<float>(o.tolerance);
  settings.maxIterations = o.maxIterations > 0 ? o.maxIterations : (*solver == IkSolver::JacobianTranspose ? 2000 : 100);
  settings.dlsLambda = static_cast<float>(o.lambda);
  settings.twoBoneSoften = static_cast<float>(o.soften);
  settings.fabrikFinishAfter = o.fabrikFinishAfter;
  IkTrace trace;
  if (o.trace) settings.trace = &trace;
  const IkResult r = solveIk(*solver, problem, settings);
  if (!r.message.empty()) return badInput(scene.source + ": " + r.message);
  const std::vector<glm::mat4> world = computeWorld(skeleton, pose);
  if (const std::string bad = nonFiniteWorldError(scene, world, time); !bad.empty())
    return badInput(bad + " after " + toString(*solver));
  // The solvers measure distances in double (core/math.h distanceInDouble); with targets
  // within 1e18 the error is finite, and if it is not, no JSON null goes out.
  if (!std::isfinite(r.error)) return badInput(scene.source + ": the IK error after " + toString(*solver) + " is not finite");

  if (o.json) {
    nlohmann::ordered_json out;
    out["solver"] = toString(*solver);
    out["converged"] = r.converged;
    out["iterations"] = r.iterations;
    out["error"] = jsonFloat(r.error);
    if (o.trace) {
      nlohmann::ordered_json names = nlohmann::ordered_json::array();
      for (int j : trace.joints) names.push_back(scene.fileIndexOf(j));  // glTF: node indices
      out["trace_joints"] = std::move(names);  // indices into "joints" of each trace position
      out["trace"] = ikTraceJson(trace);
    }
    out["joints"] = jointsJson(scene, world);
    std::cout << out.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    return kExitOk;
  }
  std::printf("%s: %s %s after %d iteration%s, error %g\n", scene.source.c_str(), toString(*solver),
              r.converged ? "converged" : "did not converge", r.iterations, r.iterations == 1 ? "" : "s", r.error);
  for (const IkTarget& t : targets) {
    const glm::vec3 p(world[t.effector][3]);
    std::printf("  %-20s at %12.6g %12.6g %12.6g  (target %g %g %g)\n", skeleton.names[t.effector].c_str(), p.x, p.y,
                p.z, t.position.x, t.position.y, t.position.z);
  }
  return kExitOk;
}

}  // namespace kinema::cli
