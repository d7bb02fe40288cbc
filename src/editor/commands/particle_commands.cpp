// The Simulate menu's particle commands (issue 24): add an emitter on the active joint (or
// at the origin), play the particles live, the Particles window, remove the shown system.
// particle_edits.h does the work; the Particles window's buttons run these commands.
#include "editor/commands/animation_editor_commands.h"
#include "editor/commands/command_sets.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

int systems(const CommandContext& c) { return static_cast<int>(c.state.doc.scene().simulation.particles.size()); }

}  // namespace

void addParticleCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("sim.add_particle_emitter", "Add Particle Emitter").menu("Simulate", true)
                    .hint("sparks from the active joint (or a fountain at the origin when none is active), played live")
                    .enabled(documentIdle)
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      int index = -1;
                      const std::string error = addParticleEmitterEdit(s.doc, s.doc.selection.active(), &index);
                      if (error.empty()) {
                        s.particleSystem = index;
                        s.particlesWindowOpen = true;
                        s.liveParticles.enabled = true;
                      }
                      reportDopeSheetEdit(s, error, error.empty() ? "Added particle emitter " + s.doc.scene().simulation.particles[index].name : "");
                    }));
  out.push_back(CommandDef("sim.live_particles", "Play Particles Live").menu("Simulate")
                    .hint("particle systems shown at every frame (simulated from frame 0)")
                    .checked([](const CommandContext& c) { return c.state.liveParticles.enabled; })
                    .run([](CommandContext& c) { c.state.liveParticles.enabled = !c.state.liveParticles.enabled; }));
  out.push_back(CommandDef("sim.remove_particle_system", "Remove Particle System").menu("Simulate")
                    .hint("the particle system the Particles window shows")
                    .enabled([](const CommandContext& c) { return documentIdle(c) && c.state.particleSystem < systems(c); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const std::string error = removeParticleSystemEdit(s.doc, s.particleSystem);
                      if (error.empty() && s.particleSystem > 0 && s.particleSystem >= systems(c)) --s.particleSystem;
                      reportDopeSheetEdit(s, error, "Removed the particle system");
                    }));
  out.push_back(CommandDef("sim.particle_settings", "Particle Settings...").menu("Simulate")
                    .hint("each particle system's emitters, forces and look")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.particlesWindowOpen; })
                    .run([](CommandContext& c) { c.state.particlesWindowOpen = !c.state.particlesWindowOpen; }));
}

}  // namespace kinema
