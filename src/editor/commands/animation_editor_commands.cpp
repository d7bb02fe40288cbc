// The keys of the animation editors under the 3D view (CommandScope::DopeSheet and
// CurveEditor: they apply while the mouse is over that editor). The editors' modal keys
// (Esc / Enter during a move) stay in the panels.
#include "editor/commands/animation_editor_commands.h"

#include <algorithm>
#include <cmath>

#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/channel_modifier_edits.h"
#include "editor/model/edit_labels.h"
#include "editor/model/key_codes.h"
#include "editor/model/timeline.h"

namespace kinema {

void showDopeSheetFrame(EditorState& state) {
  if (!state.playing) poseAtPlayhead(state);  // the one re-pose at the current frame (timeline.h)
}

void reportDopeSheetEdit(EditorState& state, const std::string& error, const std::string& done) {
  if (!error.empty()) return showEditorError(state, error);
  state.statusMessage = done;
  showDopeSheetFrame(state);
}

namespace {

// The dope sheet is shown on a clip and no mouse gesture of its own is running.
bool dopeSheetIdle(const CommandContext& c) {
  const EditorState& s = c.state;
  return documentShown(c) && s.animationEditor == AnimationEditorKind::DopeSheet && s.hasMotion() &&
         s.dopeSheet.gesture == DopeSheetState::Gesture::None && !s.doc.dragging();
}

void pasteKeys(EditorState& s, bool ontoSelectedJoints) {
  DopeSheetState& ds = s.dopeSheet;
  const long long frame = currentFrame(s);
  const std::vector<int> onto = ontoSelectedJoints ? s.doc.selection.joints() : std::vector<int>{};
  if (ontoSelectedJoints && onto.empty())
    return showEditorError(s, "Paste keys onto the selected joints: select joints first");
  reportDopeSheetEdit(s, pasteKeysEdit(s.doc, s.clip, ds.selection, ds.clipboard, frame, onto), "Pasted keys");
}

CommandDef dopeSheet(const char* id, const char* label, int key, int mods, const char* hint) {
  return CommandDef(id, label).key(key, mods).scope(CommandScope::DopeSheet).hint(hint).enabled(dopeSheetIdle);
}

// The curve editor is shown on a clip and no mouse drag of its own is running.
bool curveEditorIdle(const CommandContext& c) {
  const EditorState& s = c.state;
  return documentShown(c) && s.animationEditor == AnimationEditorKind::CurveEditor && s.hasMotion() &&
         s.curveEditor.drag == CurveEditorState::Drag::None && !s.doc.dragging();
}

CommandDef curveEditor(const char* id, const char* label, int key, int mods, const char* hint) {
  return CommandDef(id, label).key(key, mods).scope(CommandScope::CurveEditor).hint(hint).enabled(curveEditorIdle);
}

// Curve editor > Add Modifier: on the channels of the selected keys, else on every shown
// channel (modifierTargetChannels), one undo step.
CommandDef addModifier(const char* id, const char* label, ChannelModifierKind kind, const char* hint) {
  return CommandDef(id, label).menu("Animation/Add Modifier").scope(CommandScope::CurveEditor).hint(hint)
      .enabled(curveEditorIdle).run([kind](CommandContext& c) {
    EditorState& s = c.state;
    const std::vector<int> channels = modifierTargetChannels(editedClip(s), s.doc.selection, s.curveEditor);
    reportDopeSheetEdit(s, addChannelModifierEdit(s.doc, s.clip, channels, kind),
                        "Added a " + std::string(toString(kind)) + " modifier to " +
                            countPhrase(channels.size(), "channel"));
  });
}

}  // namespace

void addAnimationEditorCommands(std::vector<Command>& out) {
  out.push_back(dopeSheet("dopesheet.select_all", "Select All Keys", keys::A, 0, "")
                    .run([](CommandContext& c) { c.state.dopeSheet.selection.set(allKeyColumns(editedClip(c.state))); }));
  out.push_back(dopeSheet("dopesheet.select_none", "Deselect All Keys", keys::A, kModAlt, "")
                    .run([](CommandContext& c) { c.state.dopeSheet.selection.clear(); }));
  out.push_back(dopeSheet("dopesheet.delete_keys", "Delete Keys", keys::X, 0, "the selected key columns")
                    .key(keys::DELETE)
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      reportDopeSheetEdit(s, deleteKeysEdit(s.doc, s.clip, s.dopeSheet.selection), "Deleted keys");
                    }));
  out.push_back(dopeSheet("dopesheet.move_keys", "Move Keys", keys::G, 0,
                                     "move the selected keys with the mouse (click / Enter drops, Esc cancels)")
                    .enabled([](const CommandContext& c) { return dopeSheetIdle(c) && !c.state.dopeSheet.selection.empty(); })
                    .run([](CommandContext& c) {
                      EditorState& s = c.state;
                      DopeSheetState& ds = s.dopeSheet;
                      if (const std::string error = ds.move.begin(s.doc, s.clip, ds.selection); !error.empty())
                        return showEditorError(s, error);
                      ds.gesture = DopeSheetState::Gesture::GrabKeys;
                      ds.pressMouse = c.mouse;
                    }));
  out.push_back(dopeSheet("dopesheet.copy_keys", "Copy Keys", keys::C, kModCtrl, "the selected key columns")
                    .run([](CommandContext& c) {
                      DopeSheetState& ds = c.state.dopeSheet;
                      ds.clipboard = copyKeyColumns(editedClip(c.state), timelineGrid(c.state), ds.selection.columns());
                      c.state.statusMessage = ds.clipboard.empty()
                                                  ? "Copy keys: select keys first"
                                                  : "Copied " + std::to_string(ds.clipboard.keys.size()) + " key(s)";
                    }));
  out.push_back(dopeSheet("dopesheet.paste_keys", "Paste Keys", keys::V, kModCtrl, "at the current frame")
                    .run([](CommandContext& c) { pasteKeys(c.state, false); }));
  out.push_back(dopeSheet("dopesheet.paste_keys_onto_selected", "Paste Keys onto Selected Joints", keys::V,
                                     kModCtrl | kModShift, "at the current frame, onto the selected joints")
                    .run([](CommandContext& c) { pasteKeys(c.state, true); }));
  out.push_back(dopeSheet("dopesheet.frame_all", "Frame All Keys", keys::HOME, 0, "the whole clip fills the dope sheet")
                    .run([](CommandContext& c) {
                      const Clip& clip = editedClip(c.state);
                      c.state.dopeSheet.view.frameRange(0.0, std::max(timelineGrid(c.state).timeToFrame(clip.duration()), 1.0));
                    }));
  out.push_back(CommandDef("curves.frame_all", "Fit Curves").key(keys::HOME).scope(CommandScope::CurveEditor)
                    .hint("the shown curves fill the curve editor")
                    .enabled([](const CommandContext& c) {
                      return documentShown(c) && c.state.animationEditor == AnimationEditorKind::CurveEditor;
                    })
                    .run([](CommandContext& c) { c.state.curveEditor.fitPending = true; }));
  out.push_back(curveEditor("curves.select_all", "Select All Curve Keys", keys::A, 0, "every key of the shown curves")
                    .run([](CommandContext& c) {
                      CurveEditorState& ce = c.state.curveEditor;
                      ce.selected = allVisibleKeys(shownCurves(editedClip(c.state), c.state.doc.selection, ce), ce);
                    }));
  out.push_back(curveEditor("curves.select_none", "Deselect All Curve Keys", keys::A, kModAlt, "")
                    .run([](CommandContext& c) { c.state.curveEditor.selected.clear(); }));
  out.push_back(curveEditor("curves.box_select", "Box Select Curve Keys", keys::B, 0,
                            "then drag a box over keys (Shift: add); a drag from empty space does it too")
                    .run([](CommandContext& c) {
                      c.state.curveEditor.boxArmed = true;
                      c.state.statusMessage = "Box select: drag over the keys (Esc cancels)";
                    }));
  out.push_back(addModifier("curves.add_noise_modifier", "Add Noise Modifier", ChannelModifierKind::Noise,
                            "fractal noise on the selected keys' channels (or every shown channel)"));
  out.push_back(addModifier("curves.add_cycles_modifier", "Add Cycles Modifier", ChannelModifierKind::Cycles,
                            "repeat the keyed range before and after (selected keys' channels, or every shown one)"));
  out.push_back(addModifier("curves.add_wave_modifier", "Add Wave Modifier", ChannelModifierKind::Wave,
                            "A cos(wt - k.x + phi) on the selected keys' channels (or every shown channel)"));
}

}  // namespace kinema
