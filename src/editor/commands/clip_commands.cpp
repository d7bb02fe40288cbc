// The Clip menu's commands (Blender's action list): new, duplicate, rename, delete and the
// previous / next clip, each one undo step (model/clip_list.h); the clip list in the
// outliner runs the same commands and chooses a clip by a click on its row.
#include "editor/commands/clip_commands.h"

#include <cstdio>

#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/clip_list.h"
#include "editor/model/key_codes.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

// No drag, modal tool or dope-sheet gesture holds the active clip's keys.
bool clipsIdle(const CommandContext& c) {
  const EditorState& s = c.state;
  return documentShown(c) && !s.doc.dragging() && s.tool.mode == ModalTool::None &&
         s.dopeSheet.gesture == DopeSheetState::Gesture::None;
}
bool hasClip(const CommandContext& c) { return clipsIdle(c) && !c.state.doc.scene().clips.empty(); }
int clipCount(const CommandContext& c) { return static_cast<int>(c.state.doc.scene().clips.size()); }

// The views follow the document's active clip; the status line says what happened.
void finish(EditorState& s, const std::string& error, const std::string& done) {
  if (!error.empty()) return showEditorError(s, error);
  followDocumentClip(s);
  s.statusMessage = done;
}

std::string activeName(const EditorState& s) {
  const int a = s.doc.activeClip();
  return a >= 0 && a < static_cast<int>(s.doc.scene().clips.size()) ? s.doc.scene().clips[a].name : "";
}

void step(EditorState& s, int delta) {
  const int target = s.doc.activeClip() + delta;
  finish(s, chooseClip(s.doc, target), "Clip " + (target >= 0 && target < static_cast<int>(s.doc.scene().clips.size())
                                                      ? s.doc.scene().clips[target].name
                                                      : std::string()));
}

}  // namespace

void chooseClipInEditor(EditorState& state, int clip) {
  const std::string error = chooseClip(state.doc, clip);
  finish(state, error, error.empty() ? "Clip " + activeName(state) : "");
}

void addClipCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("clip.new", "New Clip").menu("Clip").hint("an empty clip (\"Action\"), made active")
                    .enabled(clipsIdle)
                    .run([](CommandContext& c) {
                      finish(c.state, newClip(c.state.doc), "New clip " + activeName(c.state));
                    }));
  out.push_back(CommandDef("clip.duplicate", "Duplicate Clip").menu("Clip").hint("a copy of the active clip, made active")
                    .enabled(hasClip)
                    .run([](CommandContext& c) {
                      const std::string from = activeName(c.state);
                      finish(c.state, duplicateClip(c.state.doc), "Duplicated " + from + " as " + activeName(c.state));
                    }));
  out.push_back(CommandDef("clip.rename", "Rename Clip...").menu("Clip").hint("type the active clip's new name in the clip list")
                    .enabled(hasClip)
                    .run([](CommandContext& c) { startClipRename(c.state, c.state.doc.activeClip()); }));
  out.push_back(CommandDef("clip.delete", "Delete Clip").menu("Clip")
                    .hint("the active clip (the last one gone: the rest pose)")
                    .enabled(hasClip)
                    .run([](CommandContext& c) {
                      const std::string gone = activeName(c.state);
                      finish(c.state, deleteClip(c.state.doc), "Deleted clip " + gone);
                    }));
  out.push_back(CommandDef("clip.previous", "Previous Clip").menu("Clip", true).key(keys::PAGE_DOWN)
                    .hint("the clip above in the list becomes active")
                    .enabled([](const CommandContext& c) { return clipsIdle(c) && c.state.doc.activeClip() > 0; })
                    .run([](CommandContext& c) { step(c.state, -1); }));
  out.push_back(CommandDef("clip.next", "Next Clip").menu("Clip").key(keys::PAGE_UP)
                    .hint("the clip below in the list becomes active")
                    .enabled([](const CommandContext& c) { return clipsIdle(c) && c.state.doc.activeClip() + 1 < clipCount(c); })
                    .run([](CommandContext& c) { step(c.state, 1); }));
}

void startClipRename(EditorState& state, int clip) {
  const std::vector<Clip>& clips = state.doc.scene().clips;
  if (clip < 0 || clip >= static_cast<int>(clips.size())) return;
  PanelState& p = state.panels;
  p.renamingClip = clip;
  p.clipRenameFocus = true;
  p.clipRenameError.clear();
  std::snprintf(p.clipRenameBuffer, sizeof(p.clipRenameBuffer), "%s", clips[clip].name.c_str());
}

void finishClipRename(EditorState& state) {
  PanelState& p = state.panels;
  const int clip = p.renamingClip;
  const std::string old = clip >= 0 && clip < static_cast<int>(state.doc.scene().clips.size())
                              ? state.doc.scene().clips[clip].name
                              : std::string();
  p.clipRenameError = renameClip(state.doc, clip, p.clipRenameBuffer);
  if (!p.clipRenameError.empty()) {
    state.statusMessage = "Rename clip: " + p.clipRenameError;
    return;  // the field stays open with the reason
  }
  p.renamingClip = -1;
  if (old != p.clipRenameBuffer) state.statusMessage = "Renamed clip " + old + " to " + p.clipRenameBuffer;
}

}  // namespace kinema
