#pragma once
// The "Compare solvers" mode's ImGui drawing (Teach > Compare Solvers, `kinema edit
// --compare PRESET`): the solver views, the convergence plot, the numbers, the toolbar and
// the chain panel over the area the 3D view and the side columns usually take.
#include <nlohmann/json.hpp>

#include "editor/commands/command_context.h"

namespace kinema {

// Draws the mode (call between NewFrame and Render while state.compare.active); opens the
// first preset when none is open and advances playback by the frame's time.
void drawComparePanel(CommandContext& ctx);
// The dump's "compare" object: compareModeJson plus each solver's colour.
nlohmann::json compareStateJson(const CompareMode& m);

}  // namespace kinema
