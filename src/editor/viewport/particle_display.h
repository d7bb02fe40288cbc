#pragma once
#include "editor/model/editor_state.h"
#include "render/overlay_draw_list.h"

namespace kinema {

// The live particles at the playhead (particle_edits.h), as the viewport's overlay draws
// them: camera-facing squares or dots (render/particle_overlay.h), depth-tested.
void buildParticleDisplay(EditorState& state, float viewportHeightPixels, OverlayDrawList& out);

}  // namespace kinema
