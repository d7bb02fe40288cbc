#pragma once
// The editor's particle systems (issue 24), window-free: adding an emitter on the active
// joint (or at the origin), editing and removing a system, each one undo step; and the
// particles played live at the playhead for the viewport. The simulation is sim/'s (the one
// `kinema render` and `kinema simulate` play), saved in the document's "simulation.particles".
#include <cstdint>
#include <string>
#include <vector>

#include "sim/particle_system.h"

namespace kinema {

class Document;
struct Clip;

// Simulate > Add Particle Emitter: a default system (defaultParticleSystem, scaled to the
// character) emitting from `joint`, or from the origin with -1; named after the joint, made
// unique. One undo step "Add particle emitter". `index` gets the new system's index.
std::string addParticleEmitterEdit(Document& doc, int joint, int* index = nullptr);
// Replaces system `index` (one undo step "Set particle system NAME"); refused with the
// settings' own message when they do not fit the skeleton.
std::string setParticleSystemEdit(Document& doc, int index, const ParticleSystemSettings& settings);
std::string removeParticleSystemEdit(Document& doc, int index);

// The particles played live: simulated from frame 0 on the clip's frame grid (the document's rate without
// one), joint emitters following the clip sampled at each frame (the working pose without a
// clip). Owned by the editor state; any document change starts again from frame 0.
struct LiveParticles {
  bool enabled = true;
  ParticlePlayback playback;
  long long frame = -1;  // the frame last shown, -1 before any
  std::vector<int> alive;          // per system at `frame`
  std::vector<uint64_t> emitted;   // per system: born by `frame`
};

// The states at `frame` of clip `clipIndex` (each system's, in order), or null when live
// particles are off or the document has none.
const std::vector<ParticleState>* liveParticlesAt(LiveParticles& live, const Document& doc, int clipIndex, long long frame);

}  // namespace kinema
