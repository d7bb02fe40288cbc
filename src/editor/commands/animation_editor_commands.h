#pragma once
#include <string>

#include "editor/model/editor_state.h"

namespace kinema {

// The pose at the current frame again after a dope-sheet key edit (Blender re-evaluates
// the action): not an undo step; nothing while playing or without motion. The dope sheet's
// mouse gestures and its commands both end with it.
void showDopeSheetFrame(EditorState& state);
// "" -> `done` on the status bar and the frame shown again; else the error popup.
void reportDopeSheetEdit(EditorState& state, const std::string& error, const std::string& done);

}  // namespace kinema
