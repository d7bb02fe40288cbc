#pragma once
#include "editor/commands/command_context.h"
#include "editor/model/editor_state.h"

namespace kinema {

// The properties panel's "Mesh" section: the weight display of the active joint and, per
// mesh instance, its skinning (linear blend or dual quaternion, an undoable edit) and a
// slider per morph target (shape_keys.h: moveShapeSlider) with "Insert Shape Keys".
void drawMeshSection(CommandContext& ctx);

}  // namespace kinema
