#include "cli/boids_demo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command_line.h"
#include "io/atomic_write.h"
#include "io/image.h"
#include "sim/boids.h"
#include "core/random.h"
#include "render/raster_draw.h"

namespace kinema::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kMembers = 60, kSteps = 450, kTrail = 60, kSnapshotStep = 165;
constexpr float kDt = 1.0f / 30.0f;
const glm::vec2 kWorldMin(-16.0f, -10.0f), kWorldMax(16.0f, 10.0f);  // x, z
constexpr float kGoalRadius = 4.0f;  // "reached the goal": this close at the end

const raster::Rgb kImpulseColour[kBoidImpulseCount] = {
    {210, 40, 40}, {230, 140, 20}, {40, 120, 210}, {40, 160, 80}, {140, 60, 180}};

BoidsSettings scene(AccelerationAllocation mode) {
  BoidsSettings s;
  s.planar = true;
  s.allocation = mode;
  s.hasGoal = true;
  s.goal = glm::vec3(11.0f, 0.0f, 0.0f);
  s.spheres.push_back({glm::vec3(0.0f, 0.0f, 0.5f), 3.0f});
  s.boxes.push_back({glm::vec3(5.0f, -1.0f, -7.0f), glm::vec3(7.0f, 1.0f, -2.5f)});
  return s;
}

bool insideObstacle(const BoidsSettings& s, const glm::vec3& p) {
  for (const BoidSphere& o : s.spheres)
    if (glm::distance(p, o.centre) < o.radius) return true;
  for (const BoidBox& b : s.boxes)
    if (p.x > b.min.x && p.x < b.max.x && p.z > b.min.z && p.z < b.max.z) return true;
  return false;
}

struct Run {
  std::vector<std::deque<glm::vec3>> trails, snapshotTrails;  // the last kTrail positions (now, at the snapshot)
  std::vector<glm::vec3> positions;           // at the snapshot
  BoidDebug debug;                            // of the member avoiding hardest at the snapshot
  int debugMember = 0;
  float closest = 1e30f;
  int intrusionSteps = 0;
  double meanSpeed = 0.0;
  int reached = 0;
};

Run simulate(const BoidsSettings& s) {
  SplitMix64 random(21);
  std::vector<glm::vec3> p, v;
  for (int i = 0; i < kMembers; ++i) {  // a loose block on the left, heading right
    p.emplace_back(-14.0f + 1.6f * (i % 6) + static_cast<float>(random.uniform(-0.3, 0.3)), 0.0f,
                   -6.0f + 1.4f * (i / 6) + static_cast<float>(random.uniform(-0.3, 0.3)));
    v.emplace_back(2.0f, 0.0f, static_cast<float>(random.uniform(-0.5, 0.5)));
  }
  Run run;
  run.trails.resize(kMembers);
  BoidsStepJob step;
  step.settings = &s;
  step.dt = kDt;
  double speedSum = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    step.positions = &p;
    step.velocities = &v;
    if (k == kSnapshotStep) {  // the member whose avoidance asks most (else the first)
      float most = -1.0f;
      for (int m = 0; m < kMembers; ++m) {
        BoidsStepJob probe = step;
        probe.debugBoid = m;
        probe.run();
        const float asked = glm::length(probe.debug.desired[0]) + 0.01f * glm::length(probe.debug.desired[1]);
        if (asked > most) most = asked, run.debugMember = m, run.debug = probe.debug;
      }
      run.positions = p;
      run.snapshotTrails = run.trails;
    }
    step.run();
    p = step.outPositions;
    v = step.outVelocities;
    bool intruded = false;
    for (int i = 0; i < kMembers; ++i) {
      run.trails[i].push_back(p[i]);
      if (run.trails[i].size() > kTrail) run.trails[i].pop_front();
      intruded |= insideObstacle(s, p[i]);
      speedSum += glm::length(v[i]);
      for (int j = i + 1; j < kMembers; ++j) run.closest = std::min(run.closest, glm::distance(p[i], p[j]));
    }
    run.intrusionSteps += intruded;
  }
  run.meanSpeed = speedSum / (double(kSteps) * kMembers);
  for (const glm::vec3& q : p) run.reached += glm::distance(q, s.goal) < kGoalRadius;
  return run;
}

Image draw(const BoidsSettings& s, const Run& run, const char* title, int width, int height) {
  Image img(width, height);
  std::fill(img.rgba.begin(), img.rgba.end(), uint8_t(255));
  const float scale = std::min(width / (kWorldMax.x - kWorldMin.x), (height - 40) / (kWorldMax.y - kWorldMin.y));
  auto px = [&](const glm::vec3& w) {
    return glm::vec2((w.x - kWorldMin.x) * scale, 40.0f + (w.z - kWorldMin.y) * scale);
  };
  const glm::ivec4 clip(0, 0, width, height);
  for (const BoidSphere& o : s.spheres) raster::dot(img, px(o.centre), o.radius * scale, {200, 200, 200});
  for (const BoidBox& b : s.boxes) {
    const glm::vec2 a = px(b.min), c = px(b.max);
    raster::rect(img, static_cast<int>(a.x), static_cast<int>(a.y), static_cast<int>(c.x), static_cast<int>(c.y), {200, 200, 200});
  }
  raster::ring(img, px(s.goal), kGoalRadius * scale, 1.5f, {140, 60, 180});
  for (const std::deque<glm::vec3>& trail : run.snapshotTrails)
    for (size_t k = 1; k < trail.size(); ++k) raster::line(img, px(trail[k - 1]), px(trail[k]), 1.0f, {150, 150, 150}, clip);
  for (const glm::vec3& q : run.positions) raster::dot(img, px(q), 3.0f, {30, 30, 30});
  // One member's impulses, 0.25 m per m/s^2: asked thin, granted thick.
  const glm::vec3 at = run.positions[run.debugMember];
  raster::ring(img, px(at), s.neighbourRadius * scale, 1.0f, {120, 120, 220});
  for (int k = 0; k < kBoidImpulseCount; ++k) {
    raster::line(img, px(at), px(at + 0.25f * run.debug.desired[k]), 1.0f, kImpulseColour[k], clip);
    raster::line(img, px(at), px(at + 0.25f * run.debug.granted[k]), 4.0f, kImpulseColour[k], clip);
  }
  raster::text(img, 8, 6, title, {30, 30, 30}, 2);
  int x = 8;
  for (int k = 0; k < kBoidImpulseCount; ++k) {
    const std::string name = toString(static_cast<BoidImpulse>(k));
    raster::text(img, x, 24, name, kImpulseColour[k], 1);
    x += raster::textWidth(name) + 16;
  }
  char line[160];
  std::snprintf(line, sizeof line, "t = %.1f s; whole run: closest %.2f m, %d steps with a member inside an obstacle",
                kSnapshotStep * kDt, run.closest, run.intrusionSteps);
  raster::text(img, x + 8, 24, line, {80, 80, 80}, 1);
  return img;
}

}  // namespace

int runBoidsDemo(const std::string& outDir, int width, int height) {
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) return badInput(outDir + ": cannot create the folder (" + ec.message() + ")");
  std::cerr << "kinema demo: boids: " << kMembers << " members, " << kSteps << " steps, priority and average allocation...\n";
  nlohmann::ordered_json j;
  j["members"] = kMembers;
  j["steps"] = kSteps;
  j["dt_s"] = kDt;
  j["separation_distance_m"] = BoidsSettings().separationDistance;
  for (AccelerationAllocation mode : {AccelerationAllocation::Priority, AccelerationAllocation::Average}) {
    const bool priority = mode == AccelerationAllocation::Priority;
    const BoidsSettings s = scene(mode);
    const Run run = simulate(s);
    const Image img = draw(s, run, priority ? "priority allocation" : "naive average", width, height);
    const std::string name = priority ? "priority" : "average";
    if (std::string bad = savePng((fs::path(outDir) / (name + ".png")).string(), img); !bad.empty()) return badInput(bad);
    nlohmann::ordered_json m;
    m["closest_m"] = run.closest;
    m["intrusion_steps"] = run.intrusionSteps;
    m["mean_speed_m_per_s"] = run.meanSpeed;
    m["reached_goal"] = run.reached;
    j[name] = std::move(m);
  }
  if (std::string bad = writeFileAtomically((fs::path(outDir) / "numbers.json").string(), j.dump(2) + "\n"); !bad.empty())
    return badInput(bad);
  std::printf("wrote %s: priority.png, average.png, numbers.json\n", outDir.c_str());
  return kExitOk;
}

}  // namespace kinema::cli
