// Teach > Compare Solvers and the keys of the mode (model/compare_mode.h); the mode's
// toolbar buttons run the same commands.
#include "editor/commands/command_sets.h"
#include "editor/model/key_codes.h"

namespace kinema {

namespace {

bool comparing(const CommandContext& c) { return c.state.compare.active && c.state.compare.ready(); }

Command compareKey(const char* id, const char* label, int key, int mods, const char* hint, bool (*action)(CompareMode&)) {
  return CommandDef(id, label).key(key, mods).scope(CommandScope::Compare).hint(hint).enabled(comparing)
      .run([action](CommandContext& c) { action(c.state.compare); });
}

}  // namespace

void addCompareCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("teach.compare_solvers", "Compare Solvers").menu("Teach")
                    .hint("the IK solvers side by side on a teaching case, step by step")
                    .checked([](const CommandContext& c) { return c.state.compare.active; })
                    .run([](CommandContext& c) { c.state.compare.active = !c.state.compare.active; }));
  out.push_back(compareKey("compare.step", "Step", keys::RIGHT, 0, "one sub-step of every solver", compareStepSubStep));
  out.push_back(compareKey("compare.iteration", "Step Iteration", keys::RIGHT, kModShift, "to the end of the next iteration",
                           compareStepIteration));
  out.push_back(CommandDef("compare.play", "Play").key(keys::SPACE).scope(CommandScope::Compare)
                    .hint("play / pause the steps").enabled(comparing)
                    .checked([](const CommandContext& c) { return c.state.compare.playing; })
                    .run([](CommandContext& c) { toggleComparePlay(c.state.compare); }));
  out.push_back(compareKey("compare.run_to_end", "Run to End", keys::END, 0, "every solver to its last step", compareRunToEnd));
  out.push_back(compareKey("compare.reset", "Reset", keys::R, 0, "every solver back to the start", compareReset));
  out.push_back(CommandDef("compare.exit", "Leave Compare Mode").key(keys::ESCAPE).scope(CommandScope::Compare)
                    .enabled([](const CommandContext& c) { return c.state.compare.active; })
                    .run([](CommandContext& c) { leaveCompareMode(c.state.compare); }));
}

}  // namespace kinema
