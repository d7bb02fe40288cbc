// The Help menu: Help > Controls lists every command with its keys (controls_help.h).
#include "editor/commands/command_sets.h"
#include "editor/model/key_codes.h"

namespace kinema {

void addHelpCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("help.controls", "Controls").menu("Help").key(keys::F1).hint("this list of keys and mouse controls")
                    .checked([](const CommandContext& c) { return c.state.panels.showHelp; })
                    .run([](CommandContext& c) { c.state.panels.showHelp = !c.state.panels.showHelp; }));
}

}  // namespace kinema
