#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"

namespace kinema {

class Document;

// The clip list (Blender's action list in the Action editor): the scene's clips in file
// order, one of them active (Document::activeClip: what the timeline, dope sheet, curve
// editor and onion skin play and edit). Each operation is one undo step that also records
// the active clip, so undo brings back the clip and which one was active; each returns ""
// or a one-line reason it changed nothing. The editor's views follow the active clip
// afterwards (timeline.h followDocumentClip).
//
// Choosing a clip is an undo step too, as changing the active action is in Blender: it is
// part of what a save writes (.kinema "playhead.clip"), so it also makes the file dirty.

// Makes clip `clip` active ("Choose clip NAME"); choosing the active one changes nothing.
std::string chooseClip(Document& doc, int clip);
// Appends an empty clip (newActionClip: "Action", 24 fps, frames 1..250; "Action.001" when
// that name is taken) and makes it active. The pose stays (the new clip animates nothing).
std::string newClip(Document& doc);
// Inserts a copy of the active clip right after it, named "NAME.001" (the next free
// number), and makes the copy active.
std::string duplicateClip(Document& doc);
// Renames clip `clip`. Refused: an empty (or blank) name, one another clip has, a name
// that is not UTF-8. The same name changes nothing.
std::string renameClip(Document& doc, int clip, const std::string& name);
// Deletes the active clip; the next one (or the one before, when it was the last) becomes
// active. Deleting the only clip is allowed: the character goes back to its rest pose in
// the same undo step and the timeline shows its no-clip defaults.
std::string deleteClip(Document& doc);

// Blender's naming of copies: `base` when no clip has it, else base.001, base.002...
// (a ".NNN" already on `base` is replaced, so a copy of "Run.001" is "Run.002").
std::string uniqueClipName(const std::vector<Clip>& clips, const std::string& base);

}  // namespace kinema
