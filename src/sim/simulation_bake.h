#pragma once
// Everything a file says to simulate (SimulationSettings: spring chains, then ragdolls),
// baked into one of its clips: what `kinema simulate` and the editor's Bake run. Library
// kinema_ragdoll (ragdolls need Bullet). New kinds of part add a step and a `kind` here.
#include <functional>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/pose_source.h"
#include "core/mesh.h"
#include "ik/ik_rig.h"
#include "retarget/key_reduction.h"
#include "sim/simulation_settings.h"

namespace kinema {

// One simulated part as the report names it.
struct SimulatedPart {
  std::string kind;                 // "spring-chain", "ragdoll"
  std::string name;
  std::vector<int> joints;          // the joints it keyed
  long long firstFrame = 0, lastFrame = -1;  // the frames it moved
  long long steps = 0;              // integration steps taken (substeps or physics steps)
  int bodies = 0;                   // ragdolls: rigid bodies
  float largestLimitExcess = 0.0f;  // radians: the furthest a keyed joint went past its limit
  int worstJoint = -1;              // the joint that went furthest past its limit (-1: none did)
};

struct SimulationBakeInput {
  const Skeleton* skeleton = nullptr;
  const Clip* clip = nullptr;
  // Optional: the clip's poses, what the simulated parts move on (the CLI and the editor pass
  // the pipeline's, dynamics off: evaluation/scene_poses.h); null: the clip's keys alone.
  PoseSource* poses = nullptr;
  // The document's frame rate (Scene::frameRate): the clip's when it has none of its own.
  double documentFrameRate = kDefaultFrameRate;
  const SimulationSettings* settings = nullptr;
  const IkRig* rig = nullptr;  // joint limits (optional)
  // Optional, to size ragdoll bodies by the skin (all three or none).
  const std::vector<Mesh>* meshes = nullptr;
  const std::vector<Skin>* skins = nullptr;
  const std::vector<MeshInstance>* instances = nullptr;
  long long firstFrame = 0, lastFrame = 0;  // on the clip's frame grid, inclusive
  int springSubsteps = 4;
  bool reduceKeys = true;            // thin the baked keys (sim/baked_keys.h)
  KeyReductionSettings reduction;    // used when reduceKeys
  // Called as the work goes: the part, then the frame reached out of first..last.
  std::function<void(const SimulatedPart& part, long long frame)> progress;
};

struct SimulationBake {
  Clip clip;
  std::vector<SimulatedPart> parts;
  int keysBefore = 0, keysAfter = 0;  // over the baked channels (before and after reduction)
};

Result<SimulationBake> bakeSimulation(const SimulationBakeInput& input);

}  // namespace kinema
