#pragma once
#include <string>

#include "editor/model/editor_state.h"

namespace kinema {

// The editor's state as JSON for `kinema edit --dump-state` (tests read it): selection,
// the pose (local rotation [x,y,z,w] and translation, world position per joint), IK targets
// with their last solve, undo depth, dirty flag, path, camera, the running tool.
std::string editorStateJson(const EditorState& state, int windowWidth, int windowHeight, long long frames);

}  // namespace kinema
