// The Animation menu: foot contacts of the edited clip (detect, add, delete: the timeline's
// contact strip and the Clean Up window run the same commands) and Clean Up Motion… (foot
// locking and key reduction, motion_cleanup_edit.h); Edit Bone Map of Clip… opens the Import
// Motion dialog again on the map the clip keeps.
#include <algorithm>

#include "editor/commands/animation_editor_commands.h"
#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

void reportContactEdit(EditorState& s, const std::string& error, const std::string& done) {
  reportDopeSheetEdit(s, error, done);  // error popup, or the status line and the frame shown again
}

}  // namespace

void openCleanUpWindow(EditorState& s) {
  s.cleanUpWindowOpen = true;
  // Add Foot Contact's range starts at the playhead, ten frames long, unless set already.
  if (s.newContactFirst == 0 && s.newContactLast == 10) {
    s.newContactFirst = static_cast<int>(std::max(currentFrame(s), 0LL));
    s.newContactLast = s.newContactFirst + 10;
  }
}

void addMotionCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("anim.clean_up_motion", "Clean Up Motion...").menu("Animation")
                    .hint("foot locking and key reduction on the clip, with the figures before and after")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.cleanUpWindowOpen; })
                    .run([](CommandContext& c) {
                      if (c.state.cleanUpWindowOpen) c.state.cleanUpWindowOpen = false;
                      else openCleanUpWindow(c.state);
                    }));
  out.push_back(CommandDef("anim.apply_clean_up", "Apply Clean Up").menu("Animation")
                    .hint("lock the feet over the clip's contacts and thin its keys (one undo step)")
                    .enabled(idleOnClip)
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      CleanUpResult result;
                      const std::string error = cleanUpMotionEdit(s.doc, s.clip, s.cleanUp, &result);
                      if (error.empty()) s.lastCleanUp = result;
                      reportContactEdit(s, error,
                                        "Cleaned up " + result.clipName + ": " + std::to_string(result.report.keys.keysBefore) +
                                            " -> " + std::to_string(result.report.keys.keysAfter) + " keys");
                    }));
  out.push_back(CommandDef("anim.edit_bone_map", "Edit Bone Map of Clip...").menu("Animation")
                    .hint("the Import Motion dialog again, on the map this clip was retargeted through")
                    .enabled([](const CommandContext& c) { return idleOnClip(c) && !editedClip(c.state).sourceMap.empty(); })
                    .run([](CommandContext& c) { reopenMotionImport(c.state, c.state.clip); }));
  out.push_back(CommandDef("contacts.detect", "Detect Foot Contacts").menu("Animation/Foot Contacts")
                    .hint("find when each foot is planted (ankle and toe height and speed); replaces the clip's contacts")
                    .enabled(idleOnClip)
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const std::string error = detectFootContactsEdit(s.doc, s.clip);
                      const FootContacts& fc = editedClip(s).contacts;
                      s.contactSelection.index = -1;
                      reportContactEdit(s, error, "Detected " + std::to_string(fc.feet[0].size()) + " left and " +
                                                      std::to_string(fc.feet[1].size()) + " right foot contacts");
                    }));
  out.push_back(CommandDef("contacts.add", "Add Foot Contact").menu("Animation/Foot Contacts")
                    .hint("a contact on the chosen foot over the Clean Up window's frame range (overlapped ones join it)")
                    .enabled(idleOnClip)
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      int added = -1;
                      const std::string error =
                          addFootContactEdit(s.doc, s.clip, s.newContactFoot, s.newContactFirst, s.newContactLast, &added);
                      if (error.empty()) s.contactSelection = FootContactSelection{s.newContactFoot, added};
                      reportContactEdit(s, error, std::string("Added a ") + toString(s.newContactFoot) + " foot contact");
                    }));
  out.push_back(CommandDef("contacts.delete", "Delete Foot Contact").menu("Animation/Foot Contacts")
                    .hint("the contact selected on the timeline's contact strip")
                    .enabled([](const CommandContext& c) { return idleOnClip(c) && c.state.contactSelection.valid(editedClip(c.state)); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      const FootContactSelection sel = s.contactSelection;
                      const std::string error = deleteFootContactEdit(s.doc, s.clip, sel.foot, sel.index);
                      if (error.empty()) s.contactSelection.index = -1;
                      reportContactEdit(s, error, std::string("Deleted a ") + toString(sel.foot) + " foot contact");
                    }));
}

}  // namespace kinema
