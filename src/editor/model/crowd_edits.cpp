// Crowds in the editor (crowd_edits.h).
#include "editor/model/crowd_edits.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "bake/crowd_scene.h"
#include "core/forward_kinematics.h"
#include "editor/model/document.h"
#include "evaluation/scene_poses.h"

namespace kinema {

namespace {

// The crowd's character as it plays (the one pipeline), as bake/crowd_scene.cpp bakes it:
// each member at its own clip time, so the live chains are left out.
std::unique_ptr<ScenePoses> crowdPoses(const CrowdPreview& p, const CrowdSettings& crowd) {
  EvaluationStages stages;
  stages.dynamics = false;
  return std::make_unique<ScenePoses>(*p.character, crowd.clip, stages);
}

// How big a crowd of the character should be: its rest height (file units), 1 when flat.
float restHeightOrOne(const Skeleton& s) {
  const float h = restJointHeight(s);
  return h > 0.0f ? h : 1.0f;
}

std::string checkIndex(const Document& doc, int index, const char* what) {
  if (index < 0 || index >= static_cast<int>(doc.scene().simulation.crowds.size()))
    return std::string(what) + ": the document has no such crowd";
  return "";
}

}  // namespace

CrowdSettings defaultCrowd(const Document& doc) {
  CrowdSettings c;
  const auto& crowds = doc.scene().simulation.crowds;
  c.name = crowds.empty() ? "crowd" : "crowd" + std::to_string(crowds.size() + 1);
  c.clip = doc.activeClip();
  c.members = 50;
  // A character over 20 units tall is in centimetres: the crowd's metres become its units.
  const float k = restHeightOrOne(doc.skeleton()) > 20.0f ? 100.0f : 1.0f;
  BoidsSettings& b = c.boids;
  b.separationDistance *= k;
  b.neighbourRadius *= k;
  b.avoidanceDistance *= k;
  b.maxSpeed *= k;
  b.cruiseSpeed *= k;
  b.maxAcceleration *= k;
  b.cohesionWeight *= 1.0f;  // per second squared: unit-free
  c.spawnCentre = glm::vec3(-10.0f * k, 0.0f, 0.0f);
  b.hasGoal = true;
  b.goal = glm::vec3(14.0f * k, 0.0f, 0.0f);
  b.spheres.push_back({glm::vec3(0.0f), 2.5f * k});
  return c;
}

std::string addCrowdEdit(Document& doc, const CrowdSettings& crowd) {
  if (std::string e = crowd.validate(); !e.empty()) return "Add crowd: " + e;
  return doc.edit("Add crowd", [&](DocumentEdit& e) {
    e.simulation.crowds.push_back(crowd);
    return std::string();
  });
}

std::string setCrowdEdit(Document& doc, int index, const CrowdSettings& crowd) {
  if (std::string e = checkIndex(doc, index, "Crowd settings"); !e.empty()) return e;
  if (std::string e = crowd.validate(); !e.empty()) return "Crowd settings: " + e;
  return doc.edit("Crowd settings", [&](DocumentEdit& e) {
    e.simulation.crowds[index] = crowd;
    return std::string();
  });
}

std::string removeCrowdEdit(Document& doc, int index) {
  if (std::string e = checkIndex(doc, index, "Remove crowd"); !e.empty()) return e;
  return doc.edit("Remove crowd", [&](DocumentEdit& e) {
    e.simulation.crowds.erase(e.simulation.crowds.begin() + index);
    return std::string();
  });
}

std::string toggleNaiveAverageEdit(Document& doc, int index) {
  if (std::string e = checkIndex(doc, index, "Naive average allocation"); !e.empty()) return e;
  CrowdSettings c = doc.scene().simulation.crowds[index];
  c.boids.allocation = c.boids.allocation == AccelerationAllocation::Priority ? AccelerationAllocation::Average
                                                                              : AccelerationAllocation::Priority;
  return doc.edit(c.boids.allocation == AccelerationAllocation::Average ? "Naive average allocation"
                                                                        : "Priority allocation",
                  [&](DocumentEdit& e) {
                    e.simulation.crowds[index] = c;
                    return std::string();
                  });
}

std::string bakeCrowdEdit(Document& doc, int index, long long first, long long last, int* clips) {
  if (std::string e = checkIndex(doc, index, "Bake crowd"); !e.empty()) return e;
  const CrowdSettings& crowd = doc.scene().simulation.crowds[index];
  if (!crowd.character.empty())
    return "Bake crowd: its character is another file; bake it with kinema simulate --out FILE.glb";
  if (crowd.clip >= static_cast<int>(doc.scene().clips.size())) return "Bake crowd: the document has no clip to play";
  first = std::max(0LL, first);
  last = std::max(first, last);
  Result<CrowdBake> bake = bakeCrowd(crowd, doc.scene(), first, last);
  if (!bake) return "Bake crowd: " + bake.error();
  const int count = static_cast<int>(bake->clips.size());
  const std::string error = doc.edit("Bake crowd", [&](DocumentEdit& e) {
    for (Clip& c : bake->clips) {
      auto same = std::find_if(e.clips.begin(), e.clips.end(), [&](const Clip& o) { return o.name == c.name; });
      if (same != e.clips.end()) *same = std::move(c);
      else e.clips.push_back(std::move(c));
    }
    return std::string();
  });
  if (error.empty() && clips) *clips = count;
  return error;
}

const glm::vec4& crowdImpulseColor(int impulse) {
  // Avoidance red, separation orange, alignment blue, cohesion green, goal violet (the
  // boids demo's figure), the resulting acceleration white.
  static const glm::vec4 colors[kBoidImpulseCount + 1] = {
      {0.95f, 0.2f, 0.2f, 1.0f}, {1.0f, 0.6f, 0.1f, 1.0f}, {0.25f, 0.55f, 1.0f, 1.0f},
      {0.2f, 0.85f, 0.35f, 1.0f}, {0.75f, 0.35f, 0.95f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f}};
  return colors[std::clamp(impulse, 0, kBoidImpulseCount)];
}

bool updateCrowdPreview(CrowdPreview& p, const Document& doc, int index, double time, float height, float seconds) {
  const auto& crowds = doc.scene().simulation.crowds;
  if (index < 0 || index >= static_cast<int>(crowds.size())) {
    p = CrowdPreview{};
    p.error = "no crowd";
    return false;
  }
  const CrowdSettings& crowd = crowds[index];
  const bool stale = p.changeCount != doc.changeCount() || p.crowd != index || p.documentPath != doc.path();
  if (stale) {
    const long long runs = p.runs;
    p = CrowdPreview{};
    p.runs = runs;
    p.changeCount = doc.changeCount();
    p.crowd = index;
    p.documentPath = doc.path();
    Result<Scene> character = loadCrowdCharacter(crowd, doc.scene(), doc.path());
    if (!character) {
      p.error = character.error();
      return false;
    }
    p.character = std::make_shared<const Scene>(std::move(character.value()));
    p.motion = analyseCrowdClip(p.character->skeleton, p.character->clips[crowd.clip], crowd, &*crowdPoses(p, crowd));
  }
  if (!p.character) return false;
  const Clip& clip = p.character->clips[crowd.clip];
  const FrameGrid grid = p.character->frameGrid(crowd.clip);
  const long long frame = std::clamp(grid.nearestFrame(time), 0LL, 100000LL);
  if (p.run.frames <= frame) {  // run on past the frame asked for (at least the clip, or twice as far as before)
    const long long frames = std::max({frame + 1, 2 * p.run.frames, grid.nearestFrame(clip.duration()) + 1, 120LL});
    Result<CrowdRun> run = runCrowd(crowd, p.motion, grid.secondsPerFrame, frames);
    ++p.runs;
    if (!run) {
      p.error = run.error();
      return false;
    }
    p.run = std::move(run.value());
    p.frame = -1;
  }
  if (p.frame == frame) return true;
  p.frame = frame;
  const Skeleton& s = p.character->skeleton;
  p.world.resize(static_cast<size_t>(crowd.members));
  Pose pose;
  std::unique_ptr<ScenePoses> poses = crowdPoses(p, crowd);
  for (int m = 0; m < crowd.members; ++m) {
    crowdMemberPose(s, clip, p.motion, p.run.at(frame, m), pose, poses.get());
    computeWorld(s, pose, p.world[static_cast<size_t>(m)]);
  }
  p.vectors.clear();
  const BoidDebug& d = p.run.debug[static_cast<size_t>(frame)];
  if (height < 0.0f) {  // the member's middle: the mean height of its joints
    height = 0.0f;
    for (const glm::mat4& m : p.world[static_cast<size_t>(crowd.debugMember)]) height += m[3].y;
    height /= static_cast<float>(std::max(1, s.size()));
  }
  const glm::vec3 from = p.run.at(frame, crowd.debugMember).position + glm::vec3(0.0f, height, 0.0f);
  for (int k = 0; k < kBoidImpulseCount; ++k)
    if (glm::length(d.desired[k]) > 0.0f)
      p.vectors.push_back({from, from + d.desired[k] * seconds, crowdImpulseColor(k), toString(static_cast<BoidImpulse>(k))});
  p.vectors.push_back({from, from + d.acceleration * seconds, crowdImpulseColor(kBoidImpulseCount), "acceleration"});
  return true;
}

}  // namespace kinema
