#include "cli/render_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "cli/finite_results.h"
#include "core/forward_kinematics.h"
#include "render/headless_renderer.h"
#include "render/loose_joints.h"
#include "render/particle_overlay.h"
#include "render/skeleton_view.h"
#include "evaluation/scene_deformation.h"
#include "evaluation/scene_evaluation_job.h"

namespace kinema::cli {

namespace {

// Splits "a,b,c" / "WxH" into numbers; false when the syntax is wrong.
bool parseNumbers(const std::string& text, char separator, std::vector<double>& out) {
  out.clear();
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, separator)) {
    if (item.empty()) return false;
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      return false;
    }
    if (used != item.size()) return false;
    out.push_back(v);
  }
  return !text.empty() && text.back() != separator;
}

// Sizes beyond this are refused before any OpenGL is opened; the real limit is smaller.
constexpr double kMaxSizeToAsk = 1 << 20;

// The last frame of the clip a sequence can show: the frame at its last key (sampling
// holds the last pose after it). A file without clips shows its one pose, frame 0.
long long lastFrameOf(const Scene& scene, int clip, double frameTime) {
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size())) return 0;
  const double frames = static_cast<double>(scene.clips[clip].duration()) / frameTime;
  if (!std::isfinite(frames) || frames > 1e15) return static_cast<long long>(1e15);
  return std::max(0LL, static_cast<long long>(std::llround(frames)));
}

struct Sample {
  long long frame = 0;  // frame number for sequences
  double time = 0.0;
};

// The evaluation pipeline's model-space pose; `context` carries the dynamic chains from one
// frame of a sequence to the next.
std::vector<glm::mat4> posedWorld(const Scene& scene, int clip, double time, EvaluationContext& context) {
  Pose pose;
  std::vector<glm::mat4> world;
  SceneEvaluationJob job;
  job.scene = &scene;
  job.clip = clip;
  job.time = contractTime(scene, clip, time);
  job.context = &context;
  job.pose = &pose;
  job.world = &world;
  job.run();
  return world;
}

// The CPU deformation, run only to name the mesh and joint when the GPU's vertices are
// not finite.
std::string deformedVerticesError(const Scene& scene, const std::vector<glm::mat4>& world,
                                  const std::vector<std::vector<float>>& morphWeights, double time) {
  std::vector<DeformedPrimitive> deformed;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.morphWeights = &morphWeights;
  job.out = &deformed;
  if (!job.run()) return {};
  return nonFiniteVerticesError(scene, deformed, time);
}

const Clip* clipOf(const Scene& scene, int clip) {
  return clip >= 0 && clip < static_cast<int>(scene.clips.size()) ? &scene.clips[clip] : nullptr;
}

bool ensureParentFolder(const std::string& path, std::string& error) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return true;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) error = parent.string() + ": cannot create the folder (" + ec.message() + ")";
  return !ec;
}

}  // namespace

std::string expandFramePattern(const std::string& pattern, long long frame) {
  std::string out;
  int numbers = 0;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out += pattern[i];
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out += '%';
      ++i;
      continue;
    }
    size_t j = i + 1;
    const bool zero = j < pattern.size() && pattern[j] == '0';
    if (zero) ++j;
    int width = 0;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
      width = width * 10 + (pattern[j++] - '0');
    if (j >= pattern.size() || pattern[j] != 'd' || width > 20) return {};
    std::string digits = std::to_string(frame < 0 ? -frame : frame);
    const int pad = width - static_cast<int>(digits.size()) - (frame < 0 ? 1 : 0);
    if (pad > 0) digits.insert(0, static_cast<size_t>(pad), zero ? '0' : ' ');
    out += (frame < 0 ? "-" : "") + digits;
    ++numbers;
    i = j;
  }
  return numbers == 1 ? out : std::string();
}

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a skeleton file (or the default character) to PNG, no display needed");
  cmd->add_option("file", o.file, "A .bvh or .kinema file (default: the default character)");
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  cmd->add_option("--clip", o.clip, "Clip index (default 0)");
  o.timeOption = cmd->add_option("--time", o.time, "Time in seconds (clamped to the clip)");
  o.frameOption = cmd->add_option("--frame", o.frame, "Frame number (time = N x frame time)");
  o.framesOption = cmd->add_option("--frames", o.frames, "Frame range A:B (inclusive): a numbered PNG sequence");
  o.timeOption->excludes(o.frameOption)->excludes(o.framesOption);
  o.frameOption->excludes(o.framesOption);
  cmd->add_option("--size", o.size, "Image size WxH in pixels (default 1280x720)");
  cmd->add_option("--camera", o.camera,
                  "AZ,EL[,DIST]: azimuth and elevation in degrees (0,0 = from the front), distance in file units "
                  "(default: 30,12 and the distance that frames the skeleton)");
  cmd->add_option("--backend", o.backend, "egl (default) or osmesa")->check(CLI::IsMember({"egl", "osmesa"}));
  cmd->add_option("--select", o.select, "Highlight this joint, as the editor shows a selection");
  cmd->add_option("--bones", o.bones,
                  "Bones over the meshes: none, on (default; hidden inside a body) or xray (on top, see-through)")
      ->check(CLI::IsMember({"none", "on", "xray"}));
  cmd->add_option("--weights", o.weights, "Show this joint's skin weights as heat colours (blue 0 -> red 1)");
  cmd->add_option("--mesh", o.mesh, "on (default) or off: draw the file's meshes, or its skeleton alone")
      ->check(CLI::IsMember({"on", "off"}));
  addUpOption(cmd, o.up);
  cmd->add_option("--out", o.out, "PNG path; with --frames a pattern such as dir/frame_%04d.png")->required();
  return cmd;
}

int runRender(const RenderOptions& o) { return runRenderOn(o, nullptr); }

int runRenderOn(const RenderOptions& o, const Scene* given) {
  // Options set by a caller rather than parsed have no handles: a range then means a sequence.
  const bool framesGiven = o.framesOption ? o.framesOption->count() > 0 : !o.frames.empty();
  const bool frameGiven = o.frameOption && o.frameOption->count() > 0;
  // Syntax first (exit 2), then values (exit 1).
  std::vector<double> size, cam;
  if (!parseNumbers(o.size, 'x', size) || size.size() != 2) {
    std::cerr << "kinema render: --size takes WxH, e.g. 1280x720; see --help\n";
    return kExitUsage;
  }
  if (!o.camera.empty() && (!parseNumbers(o.camera, ',', cam) || cam.size() < 2 || cam.size() > 3)) {
    std::cerr << "kinema render: --camera takes AZ,EL or AZ,EL,DIST; see --help\n";
    return kExitUsage;
  }
  long long first = 0, last = 0;
  if (framesGiven) {
    const size_t colon = o.frames.find(':');
    try {
      size_t a = 0, b = 0;
      first = std::stoll(o.frames.substr(0, colon), &a);
      last = std::stoll(o.frames.substr(colon + 1), &b);
      if (colon == std::string::npos || a != colon || b != o.frames.size() - colon - 1) throw std::invalid_argument("");
    } catch (const std::exception&) {
      std::cerr << "kinema render: --frames takes A:B, e.g. 0:29; see --help\n";
      return kExitUsage;
    }
  }

  // The upper bound is what the OpenGL implementation reports (checked once it is open);
  // this one only keeps the numbers in an int.
  const double w = size[0], h = size[1];
  if (!(w >= 1 && h >= 1 && w <= kMaxSizeToAsk && h <= kMaxSizeToAsk) || w != std::floor(w) || h != std::floor(h))
    return badInput("--size " + o.size + ": width and height must be whole numbers of at least 1");
  for (double v : cam)
    if (!std::isfinite(v)) return badInput("--camera " + o.camera + ": numbers must be finite");
  if (cam.size() == 3 && !(cam[2] > 0)) return badInput("--camera " + o.camera + ": the distance must be positive");
  if (!std::isfinite(o.time)) return badInput("--time must be a finite number");
  if (first > last) return badInput("--frames " + o.frames + ": the first frame comes after the last");
  const bool sequence = framesGiven;
  if (sequence && expandFramePattern(o.out, first).empty())
    return badInput("--out " + o.out + ": a sequence needs one frame number in the name, e.g. dir/frame_%04d.png");

  Result<Scene> loaded = given ? Result<Scene>(Scene{}) : loadSceneOrDefault(o.file, inputLimits(o.allowOutsidePaths), upAxisOf(o.up));
  if (!loaded) return badInput(loaded.error());
  const Scene& scene = given ? *given : loaded.value();
  if (const std::string bad = clipIndexError(scene, o.clip); !bad.empty()) return badInput(bad);
  int selected = -1;
  if (!o.select.empty()) {
    selected = scene.skeleton.find(o.select);
    if (selected < 0) return badInput(scene.source + ": no joint named '" + o.select + "' (--select)");
  }

  int weightJoint = -1;
  if (!o.weights.empty()) {
    weightJoint = scene.skeleton.find(o.weights);
    if (weightJoint < 0) return badInput(scene.source + ": no joint named '" + o.weights + "' (--weights)");
  }

  std::vector<Sample> samples;
  const double frameTime = scene.frameGrid(o.clip).secondsPerFrame;
  if (sequence) {
    const long long end = lastFrameOf(scene, o.clip, frameTime);
    // Particles go on after the clip's last key (which the pose holds): no end then.
    const bool particles = !scene.simulation.particles.empty();
    if (first > end && !particles)
      return badInput(scene.source + ": --frames " + o.frames + " starts after the clip's last frame, " + std::to_string(end));
    if (last > end && !particles) {
      std::fprintf(stderr, "kinema render: warning: %s: --frames %s runs past the clip's end; stopping at its last frame, %lld\n",
                   scene.source.c_str(), o.frames.c_str(), end);
      last = end;
    }
    for (long long f = first; f <= last; ++f) samples.push_back({f, static_cast<double>(f) * frameTime});
  } else {
    samples.push_back({o.frame, frameGiven ? static_cast<double>(o.frame) * frameTime : o.time});
  }

  // Particles: each system simulated from frame 0 on the clip's frame grid up to the frame
  // shown (--time T shows the frame nearest T), joint emitters following the posed joints.
  std::vector<std::vector<ParticleState>> particles(samples.size());
  if (!scene.simulation.particles.empty()) {
    ParticlePlayback playback;
    EvaluationContext context;
    const auto jointsAt = [&](long long f, std::vector<glm::mat4>& world) {
      world = posedWorld(scene, o.clip, static_cast<double>(f) * frameTime, context);
    };
    for (size_t k = 0; k < samples.size(); ++k) {
      const double shown = sequence ? static_cast<double>(samples[k].frame) : std::round(samples[k].time / frameTime);
      if (!(shown <= 1000000.0))
        return badInput(scene.source + ": particles are simulated up to frame 1,000,000 (asked for frame " +
                        std::to_string(static_cast<long long>(std::min(shown, 1e18))) + ")");
      particles[k] = playback.at(scene.simulation.particles, frameTime, static_cast<long long>(std::max(0.0, shown)), jointsAt);
    }
  }
  const HeadlessBackend backend = o.backend == "osmesa" ? HeadlessBackend::OsMesa : HeadlessBackend::Egl;
  // Poses first (a non-finite one is the file's fault, whatever the GL), then the GL.
  std::vector<std::vector<glm::mat4>> worlds;
  EvaluationContext context;
  for (const Sample& s : samples) {
    worlds.push_back(posedWorld(scene, o.clip, s.time, context));
    if (const std::string bad = nonFiniteWorldError(scene, worlds.back(), s.time); !bad.empty()) return badInput(bad);
  }
  RenderSizeLimit largest;
  Result<std::unique_ptr<HeadlessRenderer>> opened =
      HeadlessRenderer::open(backend, static_cast<int>(w), static_cast<int>(h), &largest);
  if (!opened && largest.known() && (w > largest.width || h > largest.height))
    return badInput("--size " + o.size + ": the largest image this OpenGL (" + o.backend + ", " + largest.renderer +
                    ") makes is " + std::to_string(largest.width) + "x" + std::to_string(largest.height) + " (" +
                    largest.limitedBy + ")");
  if (!opened) return badInput("cannot render: " + opened.error());
  HeadlessRenderer& renderer = *opened.value();
  const bool meshes = !scene.meshInstances.empty() && o.mesh == "on";
  if (meshes) {
    const std::string error = renderer.meshes().upload(scene);
    if (!error.empty()) return badInput("cannot render: " + error);
  }

  // One camera for the whole sequence, framing every pose in it (joints and deformed
  // vertices, read back from the GPU), so the view does not jump.
  std::vector<std::vector<std::vector<float>>> morphWeights;  // per sample, per mesh instance
  // Per sample: the instances with an active deformer stack, deformed on the CPU (morphs,
  // skin, deformers); the GPU draws those vertices as they are.
  std::vector<std::vector<DeformedPrimitive>> cpuDeformed(samples.size());
  Bounds bounds;
  for (size_t k = 0; k < samples.size(); ++k) {
    for (const glm::mat4& m : worlds[k]) bounds.add(glm::vec3(m[3]));
    for (const ParticleState& p : particles[k])
      for (const glm::vec3& q : p.positions) bounds.add(q);
    if (!meshes) continue;
    const int clip = scene.clips.empty() ? -1 : o.clip;
    morphWeights.push_back(sampleMorphWeights(scene, clip, samples[k].time));
    const std::vector<DeformerStack> stacks = sampleDeformerStacks(scene, clip, samples[k].time);
    if (anyDeformerActive(stacks)) {
      SceneDeformationJob job;
      job.scene = &scene;
      job.world = &worlds[k];
      job.morphWeights = &morphWeights.back();
      job.deformers = &stacks;
      job.withDeformersOnly = true;
      job.out = &cpuDeformed[k];
      if (std::string e = job.validate(); !e.empty()) return badInput(scene.source + ": " + e);
      if (!job.run()) return badInput(scene.source + ": the deformer stacks could not be evaluated");
      if (std::string e = nonFiniteVerticesError(scene, cpuDeformed[k], samples[k].time); !e.empty()) return badInput(e);
    }
    MeshFrame meshFrame;
    meshFrame.world = &worlds[k];
    meshFrame.morphWeights = &morphWeights.back();
    meshFrame.deformed = &cpuDeformed[k];
    const Bounds body = renderer.meshes().deformedBounds(meshFrame);
    if (!body.empty && !(isFinite(body.min) && isFinite(body.max))) {
      const std::string bad = deformedVerticesError(scene, worlds[k], morphWeights.back(), samples[k].time);
      return badInput(bad.empty() ? scene.source + ": the deformed meshes are not finite" : bad);
    }
    if (!body.empty) {
      bounds.add(body.min);
      bounds.add(body.max);
    }
  }
  const float aspect = static_cast<float>(w / h);
  OrbitCamera camera = defaultCamera(bounds, aspect);
  if (!cam.empty()) {
    camera.azimuthDeg = static_cast<float>(cam[0]);
    camera.elevationDeg = static_cast<float>(cam[1]);
    if (cam.size() == 3) camera.distance = static_cast<float>(cam[2]);
    camera.fitClipPlanes(bounds.radius());
  }
  const std::vector<char> skinJoints = skinJointMask(scene);

  for (size_t k = 0; k < samples.size(); ++k) {
    const std::string path = sequence ? expandFramePattern(o.out, samples[k].frame) : o.out;
    SkeletonDrawList list;
    SkeletonDrawJob job;
    job.parents = &scene.skeleton.parents;
    job.world = &worlds[k];
    job.selectedJoint = selected;
    job.shownJoints = &skinJoints;
    const std::vector<char> loose = looseJoints(scene.skeleton, clipOf(scene, o.clip), sampledPose(scene, o.clip, samples[k].time));
    job.looseJoints = &loose;
    if (o.bones == "xray") job.style = SkeletonStyle::xRay();  // see-through over meshes and grid alike
    job.run(list);
    MeshDraw meshDraw;
    meshDraw.renderer = &renderer.meshes();
    meshDraw.frame.world = &worlds[k];
    meshDraw.frame.morphWeights = meshes ? &morphWeights[k] : nullptr;
    meshDraw.frame.deformed = meshes ? &cpuDeformed[k] : nullptr;
    meshDraw.frame.weightJoint = weightJoint;
    FrameDescription frame;
    frame.skeleton = &list;
    frame.meshes = meshes ? &meshDraw : nullptr;
    frame.bones = o.bones == "none" ? BoneDisplay::None : o.bones == "xray" ? BoneDisplay::XRay : BoneDisplay::On;
    frame.camera = camera;
    frame.sceneRadius = bounds.radius();
    OverlayDrawList overlay;
    for (size_t i = 0; i < particles[k].size(); ++i)
      appendParticles(scene.simulation.particles[i], particles[k][i], camera, static_cast<float>(h), overlay);
    if (!overlay.empty()) frame.overlay = &overlay;
    const Image image = renderer.render(frame);
    std::string error;
    if (!ensureParentFolder(path, error)) return badInput(error);
    error = savePng(path, image);
    if (!error.empty()) return badInput(error);
    if (sequence)
      std::fprintf(stderr, "kinema render: frame %lld (%zu/%zu) -> %s\n", samples[k].frame, k + 1, samples.size(),
                   path.c_str());
  }
  if (!sequence) std::fprintf(stderr, "kinema render: wrote %s\n", o.out.c_str());
  return kExitOk;
}

int renderDefaultCharacterHeadless(const std::string& path) {
  RenderOptions o;
  CLI::App app;
  addRenderCommand(app, o);  // gives the options their defaults and the option handles
  o.out = path;
  const int code = runRender(o);
  if (code != kExitOk) return code;
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  std::printf("No display: rendered Kinema's default character to %s\n", (ec ? path : absolute.string()).c_str());
  std::printf("(open a window with `kinema edit` where there is a display; `kinema --help` lists every subcommand)\n");
  return kExitOk;
}

}  // namespace kinema::cli
