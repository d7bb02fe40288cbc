#include "cli/simulate_particles.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "cli/command_line.h"
#include "cli/render_command.h"
#include "core/forward_kinematics.h"
#include "io/bvh_writer.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"

namespace kinema::cli {

namespace {

// "a<sep>b<sep>..." as n numbers (n in [lo, hi]); false on any other text.
bool numbers(const std::string& text, char separator, size_t lo, size_t hi) {
  size_t count = 0, start = 0;
  while (true) {
    const size_t end = text.find(separator, start);
    const std::string item = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    char* stop = nullptr;
    if (item.empty()) return false;
    std::strtod(item.c_str(), &stop);
    if (stop != item.c_str() + item.size()) return false;
    ++count;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return count >= lo && count <= hi;
}

}  // namespace

void addSimulateRenderOptions(CLI::App* cmd, SimulateOptions& o) {
  cmd->add_option("--render", o.render,
                  "DIR: also draw every frame of --frames as DIR/frame_NNNN.png, as kinema render draws (particles included)");
  cmd->add_option("--size", o.size, "With --render: image size WxH in pixels (default 1280x720)");
  cmd->add_option("--camera", o.camera,
                  "With --render: AZ,EL[,DIST] in degrees and file units (default: 30,12 and the distance that frames "
                  "every frame)");
  cmd->add_option("--backend", o.backend, "With --render: egl (default) or osmesa")->check(CLI::IsMember({"egl", "osmesa"}));
}

bool simulateRenderSyntaxOk(const SimulateOptions& o) {
  if (!numbers(o.size, 'x', 2, 2)) {
    std::cerr << "kinema simulate: --size takes WxH, e.g. 1280x720; see --help\n";
    return false;
  }
  if (!o.camera.empty() && !numbers(o.camera, ',', 2, 3)) {
    std::cerr << "kinema simulate: --camera takes AZ,EL or AZ,EL,DIST; see --help\n";
    return false;
  }
  return true;
}

void defaultParticleFrames(const Scene& scene, int clip, long long& first, long long& last) {
  first = 0;
  last = 0;
  if (clip >= 0 && clip < static_cast<int>(scene.clips.size()))
    last = std::max(0LL, scene.frameGrid(clip).nearestFrame(scene.clips[clip].duration()));
  if (last == 0) last = 119;
}

nlohmann::ordered_json particleReport(const Scene& scene, int clip, long long first, long long last) {
  ParticlePlayback playback;
  const double frameTime = scene.frameGrid(clip).secondsPerFrame;
  const std::vector<ParticleState>& states =
      playback.at(scene.simulation.particles, frameTime, last, [&](long long f, std::vector<glm::mat4>& world) {
        world = computeWorld(scene.skeleton, sampledPose(scene, clip, static_cast<double>(f) * frameTime));
      });
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (size_t i = 0; i < states.size(); ++i)
    list.push_back(nlohmann::ordered_json{{"kind", "particles"},
                    {"name", scene.simulation.particles[i].name},
                    {"frames", {first, last}},
                    {"steps", last},
                    {"alive", states[i].size()},
                    {"emitted", states[i].emitted}});
  return list;
}

int renderSimulatedFrames(const SimulateOptions& o, const Scene& scene, long long first, long long last) {
  if (o.render.empty()) return kExitOk;
  RenderOptions r;
  r.file = o.file;
  r.clip = o.clip;
  r.frames = std::to_string(first) + ":" + std::to_string(last);
  r.size = o.size;
  r.camera = o.camera;
  r.backend = o.backend;
  r.out = o.render + "/frame_%04d.png";
  return runRenderOn(r, &scene);
}

int runParticlesOnly(const SimulateOptions& o, const Scene& scene, long long first, long long last) {
  if (!o.out.empty()) {
    std::vector<std::string> report;
    const std::string error = saveSimulatedScene(o.out, scene, o.clip, report);
    for (const std::string& line : report) std::cerr << "kinema simulate: warning: " << line << "\n";
    if (!error.empty()) return badInput(error);
  }
  if (const int code = renderSimulatedFrames(o, scene, first, last); code != kExitOk) return code;
  if (o.json) {
    nlohmann::ordered_json j;
    j["file"] = o.file;
    if (!o.out.empty()) j["out"] = o.out;
    j["clip"] = o.clip;
    j["frames"] = {first, last};
    j["parts"] = particleReport(scene, o.clip, first, last);
    j["steps"] = last * static_cast<long long>(scene.simulation.particles.size());
    j["largestLimitExcessDegrees"] = 0;
    if (!o.render.empty()) j["render"] = o.render;
    std::cout << j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
  }
  return kExitOk;
}

}  // namespace kinema::cli
