#pragma once
#include "editor/model/editor_state.h"

namespace kinema {

// The properties panel's "Mesh" section: the weight display of the active joint and, per
// mesh instance, its skinning (linear blend or dual quaternion, an undoable edit).
void drawMeshSection(EditorState& state);

}  // namespace kinema
