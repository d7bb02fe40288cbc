// The Simulate menu's crowd commands (issue 24): add a crowd of the document's character,
// show the Crowd panel, toggle the naive average allocation (to compare with the seed's
// priority allocation), bake the crowd to a clip per member, remove it. Each edit is one undo
// step (model/crowd_edits.h does the work); the Crowd panel's buttons run these commands.
#include <algorithm>

#include "editor/commands/animation_editor_commands.h"
#include "editor/commands/command_sets.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

int crowdCount(const CommandContext& c) { return static_cast<int>(c.state.doc.scene().simulation.crowds.size()); }
// The crowd the panel shows, kept inside the list.
int activeCrowd(const CommandContext& c) { return std::clamp(c.state.crowds.active, 0, std::max(crowdCount(c) - 1, 0)); }
bool hasCrowd(const CommandContext& c) { return documentIdleNoTool(c) && crowdCount(c) > 0; }

}  // namespace

void addCrowdCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("sim.add_crowd", "Add Crowd...").menu("Simulate", true)
                    .hint("a flock of boids that are instances of this character, playing its clip (edit it in the Crowd panel)")
                    .enabled([](const CommandContext& c) { return documentIdleNoTool(c) && !c.state.doc.skeleton().empty() && c.state.hasMotion(); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const CrowdSettings crowd = defaultCrowd(s.doc);
                      const std::string error = addCrowdEdit(s.doc, crowd);
                      if (error.empty()) {
                        s.crowds.active = crowdCount(c) - 1;
                        s.crowds.windowOpen = true;
                      }
                      reportDopeSheetEdit(s, error, "Added crowd " + crowd.name + " (" + std::to_string(crowd.members) + " members)");
                    }));
  out.push_back(CommandDef("sim.crowd_panel", "Show Crowd Panel").menu("Simulate")
                    .hint("the crowd's members, weights, neighbourhood, obstacles and goal; the impulses of one member")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.crowds.windowOpen; })
                    .run([](CommandContext& c) { c.state.crowds.windowOpen = !c.state.crowds.windowOpen; }));
  out.push_back(CommandDef("sim.crowd_naive_average", "Naive Average Allocation").menu("Simulate")
                    .hint("the crowd averages its impulses instead of the seed's priority allocation (compare: members bump into the obstacle)")
                    .enabled(hasCrowd)
                    .checked([](const CommandContext& c) {
                      return crowdCount(c) > 0 && c.state.doc.scene().simulation.crowds[activeCrowd(c)].boids.allocation ==
                                                      AccelerationAllocation::Average;
                    })
                    .run([](CommandContext& c) {
                      const std::string error = toggleNaiveAverageEdit(c.state.doc, activeCrowd(c));
                      const bool average =
                          error.empty() && c.state.doc.scene().simulation.crowds[activeCrowd(c)].boids.allocation ==
                                               AccelerationAllocation::Average;
                      reportDopeSheetEdit(c.state, error, average ? "Crowd: naive average allocation" : "Crowd: priority allocation");
                    }));
  out.push_back(CommandDef("sim.bake_crowd", "Bake Crowd").menu("Simulate")
                    .hint("a clip per member (crowd_0000, ...) over the playback range, added to the clip list (one undo step)")
                    .enabled([](const CommandContext& c) { return hasCrowd(c) && c.state.hasMotion(); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      int clips = 0;
                      const long long first = rangeStartFrame(s), last = rangeEndFrame(s);
                      const std::string error = bakeCrowdEdit(s.doc, activeCrowd(c), first, last, &clips);
                      reportDopeSheetEdit(s, error, "Baked the crowd: " + std::to_string(clips) + " clips, frames " +
                                                        std::to_string(first) + " to " + std::to_string(last));
                    }));
  out.push_back(CommandDef("sim.frame_crowd_member", "Frame Crowd Debug Member").menu("Simulate")
                    .hint("the view centres on the member whose impulse vectors are drawn, close up")
                    .enabled([](const CommandContext& c) { return hasCrowd(c) && !c.state.crowds.preview.world.empty(); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const CrowdSettings& crowd = s.doc.scene().simulation.crowds[activeCrowd(c)];
                      const CrowdPreview& p = s.crowds.preview;
                      const std::vector<glm::mat4>& w = p.world[std::min(static_cast<size_t>(crowd.debugMember), p.world.size() - 1)];
                      glm::vec3 lo(1e30f), hi(-1e30f);
                      for (const glm::mat4& m : w) lo = glm::min(lo, glm::vec3(m[3])), hi = glm::max(hi, glm::vec3(m[3]));
                      // The member and its impulse vectors in view, in the middle.
                      for (const CrowdDebugVector& v : p.vectors) lo = glm::min(lo, v.to), hi = glm::max(hi, v.to);
                      s.camera.target = 0.5f * (lo + hi);
                      s.camera.distance = std::max(2.5f * glm::length(hi - lo), 1e-3f);
                      s.camera.elevationDeg = 35.0f;
                      s.statusMessage = "Framed crowd member " + std::to_string(crowd.debugMember);
                    }));
  out.push_back(CommandDef("sim.remove_crowd", "Remove Crowd").menu("Simulate")
                    .hint("the crowd the Crowd panel shows goes (its baked clips stay)")
                    .enabled(hasCrowd)
                    .run([](CommandContext& c) {
                      const std::string error = removeCrowdEdit(c.state.doc, activeCrowd(c));
                      if (error.empty()) c.state.crowds.active = activeCrowd(c);
                      reportDopeSheetEdit(c.state, error, "Removed the crowd");
                    }));
}

}  // namespace kinema
