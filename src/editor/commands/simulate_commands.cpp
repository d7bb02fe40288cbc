// The Simulate menu (issue 23): make the selected chain dynamic (spring bones), play the
// chains live, ragdoll from the current frame, bake every dynamic part into the clip (one
// undo step each; simulation_edits.h does the work), the Simulation window; and Teach >
// Stiff Springs, the time-step window. The Simulation window's buttons run these commands.
#include <algorithm>

#include "editor/commands/animation_editor_commands.h"
#include "editor/commands/command_sets.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {


std::string partsText(const SimulationBake& bake) {
  std::string text;
  for (const SimulatedPart& p : bake.parts) text += (text.empty() ? "" : ", ") + p.kind + " " + p.name;
  return text + " (" + std::to_string(bake.keysBefore) + " -> " + std::to_string(bake.keysAfter) + " keys)";
}

}  // namespace

void addSimulateCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("sim.make_chain_dynamic", "Make Chain Dynamic").menu("Simulate")
                    .hint("spring bones: the selected joints (or one joint and the chain below it) swing behind the animation")
                    .enabled([](const CommandContext& c) { return documentIdleNoTool(c) && !c.state.doc.selection.empty(); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const Skeleton& sk = s.doc.skeleton();
                      const std::vector<int> joints = dynamicChainFrom(sk, s.doc.selection.joints(), s.doc.selection.active());
                      const SpringBoneChain chain = defaultSpringChain(sk, joints);
                      const std::string error = addSpringChainEdit(s.doc, chain);
                      if (error.empty()) s.simulationWindowOpen = true;
                      reportDopeSheetEdit(s, error, "Made chain " + chain.name + " dynamic (" + std::to_string(joints.size()) + " joints)");
                    }));
  out.push_back(CommandDef("sim.remove_chain", "Remove Dynamic Chain").menu("Simulate")
                    .hint("the dynamic chain holding the active joint goes back to its keys alone")
                    .enabled([](const CommandContext& c) {
                      return documentIdleNoTool(c) && springChainOf(c.state.doc, c.state.doc.selection.active()) >= 0;
                    })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const std::string error = removeSpringChainEdit(s.doc, springChainOf(s.doc, s.doc.selection.active()));
                      reportDopeSheetEdit(s, error, "Removed the dynamic chain");
                    }));
  out.push_back(CommandDef("sim.add_collider", "Add Collision Capsule").menu("Simulate")
                    .hint("a capsule along the active joint's bone that the dynamic chains' tails stay out of (sized in Simulation Settings)")
                    .enabled([](const CommandContext& c) {
                      const int active = c.state.doc.selection.active();
                      if (!documentIdleNoTool(c) || active < 0) return false;
                      for (const SpringBoneChain& chain : c.state.doc.scene().simulation.springChains)
                        if (std::find(chain.joints.begin(), chain.joints.end(), active) == chain.joints.end()) return true;
                      return false;
                    })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const int active = s.doc.selection.active();
                      const std::string error = addColliderEdit(s.doc, defaultCollider(s.doc.skeleton(), active));
                      if (error.empty()) s.simulationWindowOpen = true;
                      reportDopeSheetEdit(s, error, "Added a collision capsule on " + s.doc.skeleton().names[active]);
                    }));
  out.push_back(CommandDef("sim.live_springs", "Play Spring Bones Live").menu("Simulate")
                    .hint("dynamic chains swing during playback and scrubbing (simulated from the range's start)")
                    .checked([](const CommandContext& c) { return c.state.liveSprings.enabled; })
                    .run([](CommandContext& c) {
                      c.state.liveSprings.enabled = !c.state.liveSprings.enabled;
                      poseAtPlayhead(c.state);
                    }));
  out.push_back(CommandDef("sim.ragdoll_from_frame", "Ragdoll from Current Frame").menu("Simulate", true)
                    .hint("the character (or the active joint and what hangs below it) falls from this frame, baked to keys "
                          "(without a clip, from the pose on screen into a new Action)")
                    .enabled([](const CommandContext& c) { return documentIdleNoTool(c) && c.state.doc.skeleton().size() > 1; })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const Skeleton& sk = s.doc.skeleton();
                      const int active = s.doc.selection.active();
                      bool hasChild = false;
                      for (int j = active + 1; active >= 0 && j < sk.size() && !hasChild; ++j) hasChild = sk.parents[j] == active;
                      const int root = hasChild ? active : characterRoot(sk);
                      const long long frame = std::max(0LL, currentFrame(s));
                      // At least three seconds of fall, past the range's end if need be.
                      const long long last = std::max(rangeEndFrame(s), frame + static_cast<long long>(3.0 * timelineFps(s)));
                      SimulationBake bake;
                      const std::string error = ragdollFromFrameEdit(s.doc, s.clip, root, frame, last, &bake);
                      if (error.empty()) s.lastBake = bake;
                      reportDopeSheetEdit(s, error, "Ragdoll from frame " + std::to_string(frame) + " to " + std::to_string(last) +
                                                        ": " + partsText(bake));
                    }));
  out.push_back(CommandDef("sim.bake", "Bake Simulation").menu("Simulate")
                    .hint("every dynamic chain and ragdoll into keys over the playback range (one undo step)")
                    .enabled([](const CommandContext& c) { return idleOnClip(c) && c.state.doc.scene().simulation.hasBakedParts(); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      SimulationBake bake;
                      const std::string error = bakeSimulationEdit(s.doc, s.clip, rangeStartFrame(s), rangeEndFrame(s), &bake);
                      if (error.empty()) {
                        s.lastBake = bake;
                        // Live springs on top of the baked keys would lag them a second time:
                        // the view shows the keys (the menu item turns live springs back on).
                        s.liveSprings.enabled = false;
                      }
                      reportDopeSheetEdit(s, error, "Baked " + partsText(bake) +
                                                        (error.empty() ? "; live spring bones off, the keys play" : ""));
                    }));
  out.push_back(CommandDef("sim.settings", "Simulation Settings...").menu("Simulate", true)
                    .hint("the dynamic chains' and ragdolls' settings")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.simulationWindowOpen; })
                    .run([](CommandContext& c) { c.state.simulationWindowOpen = !c.state.simulationWindowOpen; }));
}

void addStiffSpringsCommand(std::vector<Command>& out) {
  out.push_back(CommandDef("teach.stiff_springs", "Stiff Springs (Time Steps)").menu("Teach")
                    .hint("why a time step blows up: four integrators on a damped spring chain (kinema demo stiff-springs)")
                    .checked([](const CommandContext& c) { return c.state.stiffSpringsWindowOpen; })
                    .run([](CommandContext& c) { c.state.stiffSpringsWindowOpen = !c.state.stiffSpringsWindowOpen; }));
}

}  // namespace kinema
