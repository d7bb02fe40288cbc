#pragma once
#include "editor/commands/command_context.h"

namespace kinema {

// The properties panel's "Deformers" section (issue 22): per mesh instance, buttons adding a
// lattice, bend, twist, taper or soft pull (deformer_edits.h), and each deformer of the stack
// with its enable box, reorder, "Apply as shape" and remove, and its keyable parameters (a
// drag field that keys where the parameter is animated or auto-key is on, and a Key button).
void drawDeformersSection(CommandContext& ctx);

}  // namespace kinema
