#pragma once
#include "editor/model/editor_state.h"

namespace kinema {

// The clip list's steps behind its rows and its rename field (the Clip menu's commands are
// in the registry: clip.new, clip.duplicate, clip.rename, clip.delete, clip.previous,
// clip.next). Each edit is one undo step (model/clip_list.h); afterwards the views follow
// the active clip and the status line says what happened, or the error popup why not.

// A click on a clip's row: it becomes the active clip (an undo step, as in Blender).
void chooseClipInEditor(EditorState& state, int clip);
// Opens the inline name field on clip `clip`'s row, holding its name (clip.rename, a
// double click on the row).
void startClipRename(EditorState& state, int clip);
// Enter in that field: renames the clip. A refused name (empty, another clip's) keeps the
// field open with the reason under it and on the status line.
void finishClipRename(EditorState& state);

}  // namespace kinema
