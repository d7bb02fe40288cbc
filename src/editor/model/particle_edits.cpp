// Particle systems in the editor (particle_edits.h).
#include "editor/model/particle_edits.h"

#include <algorithm>

#include "core/forward_kinematics.h"
#include "editor/model/document.h"
#include "editor/model/unique_name.h"
#include "evaluation/scene_evaluation_job.h"

namespace kinema {

namespace {

// What the default system scales to: the character's rest height, 1.8 (a person) when flat.
float restHeightOrHumanHeight(const Skeleton& s) {
  const float h = restJointHeight(s);
  return h > 0.0f ? h : 1.8f;
}

}  // namespace

std::string addParticleEmitterEdit(Document& doc, int joint, int* index) {
  const Skeleton& s = doc.skeleton();
  if (joint >= s.size()) joint = -1;
  ParticleSystemSettings settings = defaultParticleSystem(joint, restHeightOrHumanHeight(s));
  const std::vector<ParticleSystemSettings>& systems = doc.scene().simulation.particles;
  settings.name = uniqueName(joint >= 0 ? s.names[joint] + " sparks" : "fountain", [&](const std::string& name) {
    return std::any_of(systems.begin(), systems.end(), [&](const ParticleSystemSettings& p) { return p.name == name; });
  });
  const std::string error = doc.edit("Add particle emitter", [&](DocumentEdit& e) {
    e.simulation.particles.push_back(settings);
    return std::string();
  });
  if (error.empty() && index) *index = static_cast<int>(doc.scene().simulation.particles.size()) - 1;
  return error;
}

std::string setParticleSystemEdit(Document& doc, int index, const ParticleSystemSettings& settings) {
  if (index < 0 || index >= static_cast<int>(doc.scene().simulation.particles.size())) return "no such particle system";
  if (std::string bad = settings.validate(doc.skeleton()); !bad.empty()) return bad;
  return doc.edit("Set particle system " + settings.name, [&](DocumentEdit& e) {
    e.simulation.particles[index] = settings;
    return std::string();
  });
}

std::string removeParticleSystemEdit(Document& doc, int index) {
  if (index < 0 || index >= static_cast<int>(doc.scene().simulation.particles.size())) return "no such particle system";
  return doc.edit("Remove particle system " + doc.scene().simulation.particles[index].name, [&](DocumentEdit& e) {
    e.simulation.particles.erase(e.simulation.particles.begin() + index);
    return std::string();
  });
}

const std::vector<ParticleState>* liveParticlesAt(LiveParticles& live, const Document& doc, int clipIndex, long long frame) {
  const Scene& scene = doc.scene();
  if (!live.enabled || scene.simulation.particles.empty()) {
    live.frame = -1;
    live.alive.clear();
    live.emitted.clear();
    return nullptr;
  }
  const Clip* clip = clipIndex >= 0 && clipIndex < static_cast<int>(scene.clips.size()) ? &scene.clips[clipIndex] : nullptr;
  const FrameGrid grid = scene.frameGrid(clip ? clipIndex : -1);
  const double frameTime = grid.secondsPerFrame;
  // Without a clip the joints stand in the working pose, whose revision then is an input.
  const long long key = clip ? doc.changeCount() * 1024 + clipIndex : doc.changeCount() ^ (doc.poseRevision() << 20);
  // Joint emitters follow the evaluation pipeline's pose at each frame (the frames come in
  // order, so one context steps the dynamic chains forward once).
  EvaluationContext context;
  const IkRig rig = doc.savedRig();
  Pose pose;
  const auto jointsAt = [&](long long f, std::vector<glm::mat4>& world) {
    if (!clip) {
      world = doc.worldTransforms();
      return;
    }
    SceneEvaluationJob job;
    job.scene = &scene;
    job.clip = clipIndex;
    job.time = grid.frameToTime(f);
    job.rig = &rig;
    job.revision = doc.changeCount();
    job.context = &context;
    job.pose = &pose;
    job.world = &world;
    job.run();
  };
  live.frame = std::max(0LL, frame);
  const std::vector<ParticleState>& states = live.playback.at(scene.simulation.particles, frameTime, live.frame, jointsAt, key);
  live.alive.clear();
  live.emitted.clear();
  for (const ParticleState& p : states) live.alive.push_back(p.size()), live.emitted.push_back(p.emitted);
  return &states;
}

}  // namespace kinema
