#include "editor/commands/command_registry.h"

#include <cstdio>
#include <cstdlib>

#include "editor/commands/command_sets.h"

namespace kinema {

const char* toString(CommandScope scope) {
  switch (scope) {
    case CommandScope::Global: return "global";
    case CommandScope::Viewport: return "viewport";
    case CommandScope::DopeSheet: return "dope-sheet";
    case CommandScope::CurveEditor: return "curve-editor";
    case CommandScope::Compare: return "compare";
    case CommandScope::LatticeEdit: return "lattice-edit";
    case CommandScope::Property: return "property";
  }
  return "global";
}

const char* scopeTitle(CommandScope scope) {
  switch (scope) {
    case CommandScope::Global: return "Everywhere";
    case CommandScope::Viewport: return "3D view";
    case CommandScope::DopeSheet: return "Dope sheet (mouse over it)";
    case CommandScope::CurveEditor: return "Curve editor (mouse over it)";
    case CommandScope::Compare: return "Teach > Compare Solvers";
    case CommandScope::LatticeEdit: return "Lattice edit mode (3D view, Tab)";
    case CommandScope::Property: return "Over a keyable field of the Properties panel";
  }
  return "Everywhere";
}

std::string CommandRegistry::add(Command command) {
  if (command.id.empty()) return "a command without an id";
  if (command.label.empty()) return command.id + ": no label";
  if (!command.run) return command.id + ": nothing to run";
  if (find(command.id)) return command.id + ": the id is taken";
  commands_.push_back(std::move(command));
  return "";
}

const Command* CommandRegistry::find(const std::string& id) const {
  for (const Command& c : commands_)
    if (c.id == id) return &c;
  return nullptr;
}

const CommandRegistry& editorCommands() {
  static const CommandRegistry registry = [] {
    CommandRegistry r;
    std::vector<Command> all;
    // Menu order: File, Edit, View, Pose, Clip, Animation, Simulate, Teach, Help; commands without a menu anywhere.
    addFileCommands(all);
    addEditCommands(all);
    addViewCommands(all);
    addPoseCommands(all);
    addLatticeCommands(all);
    addClipCommands(all);
    addMotionCommands(all);
    addTimelineCommands(all);
    addAnimationEditorCommands(all);
    addSimulateCommands(all);
    addParticleCommands(all);     // issue 24's Simulate commands after the physics ones
    addCrowdCommands(all);
    addStiffSpringsCommand(all);  // the Teach menu starts after the last Simulate command
    addCompareCommands(all);
    addHelpCommands(all);
    for (Command& c : all) {
      // A broken definition is a programming error the unit tests catch; never ship one.
      if (const std::string error = r.add(std::move(c)); !error.empty()) {
        std::fprintf(stderr, "kinema: bad editor command: %s\n", error.c_str());
        std::abort();
      }
    }
    return r;
  }();
  return registry;
}

std::string runCommand(const CommandRegistry& registry, const std::string& id, CommandContext& ctx) {
  const Command* c = registry.find(id);
  if (!c) return "no command '" + id + "'";
  if (!c->isEnabled(ctx)) return c->label + " is not available now";
  c->run(ctx);
  return "";
}

}  // namespace kinema
