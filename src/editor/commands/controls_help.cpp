#include "editor/commands/controls_help.h"

namespace kinema {

namespace {

struct Gesture {
  CommandScope scope;
  const char* keys;
  const char* action;
};

// The mouse, per scope (viewport_tools.cpp, dope_sheet_panel.cpp, curve_editor_panel.cpp,
// compare_mode.h). Panels' own gestures are listed under Global.
const Gesture kGestures[] = {
    {CommandScope::Global, "Double-click a joint in the outliner", "rename it"},
    {CommandScope::Global, "Click / double-click a clip in the clip list", "make it the active clip / rename it"},
    {CommandScope::Global, "Drag in the timeline's ruler", "scrub"},
    {CommandScope::Global, "Click / drag a foot contact bar over the timeline",
     "select it / move it; drag its start or end to change its frames (Esc or right click cancels)"},
    {CommandScope::Global, "Drag on an empty foot contact lane", "add a contact over the frames dragged"},
    {CommandScope::Global, "Esc with a menu, combo or popup open", "closes it (and does nothing else)"},
    {CommandScope::Global, "Esc with Help > Controls open", "closes it (a running tool's Esc cancels the tool first)"},
    {CommandScope::Viewport, "Left click", "select a joint (Shift: add / toggle)"},
    {CommandScope::Viewport, "Left drag on empty space", "box select (Shift adds, Ctrl removes)"},
    {CommandScope::Viewport, "Middle drag / Alt+left drag", "orbit"},
    {CommandScope::Viewport, "Shift+middle drag", "pan"},
    {CommandScope::Viewport, "Wheel", "zoom"},
    {CommandScope::Viewport, "Drag a ring of the gizmo", "rotate about that axis"},
    {CommandScope::Viewport, "Drag an IK target handle", "move the target, the chain follows"},
    {CommandScope::LatticeEdit, "Left click", "select a lattice point (Shift: toggle)"},
    {CommandScope::LatticeEdit, "Left drag on empty space", "box select points (Shift adds, Ctrl removes)"},
    {CommandScope::DopeSheet, "Click / drag keys", "select (Shift: toggle) / move, snapped to frames"},
    {CommandScope::DopeSheet, "Drag on empty space", "box select"},
    {CommandScope::DopeSheet, "Click in the ruler / a joint's name", "set the current frame / select the joint"},
    {CommandScope::CurveEditor, "Click / drag keys and handles", "select (Shift: add) / move (both handles of a Bezier key)"},
    {CommandScope::CurveEditor, "Drag on empty space", "box select keys (Shift: add); a click deselects"},
    {CommandScope::CurveEditor, "Wheel / middle drag", "zoom (Ctrl: time, Shift: values) / pan"},
    {CommandScope::Compare, "Drag the target or a joint", "the solvers start again from there"},
};

// The keys a running modal tool takes (ViewportTools::modalKey; the dope sheet's G move
// takes the same Enter and Esc).
struct ModalKey {
  const char* keys;
  const char* action;  // in Help > Controls
  const char* brief;   // in the status bar
  bool rotateOnly;
};
const ModalKey kModalKeys[] = {
    {"X / Y / Z", "constrain to the axis (R: twice for the joint's own axes, three times frees it)", "constrain", false},
    {"0-9 . - Backspace", "type the angle in degrees (R)", "type degrees", true},
    {"Enter / left click", "confirm (an IK drag: release the button)", "confirm", false},
    {"Esc / right click", "cancel", "cancel", false},
};

// "X / Y / Z constrain, Enter / left click confirm, ...": what a running tool takes.
std::string modalKeyLine(bool rotate) {
  std::string out;
  for (const ModalKey& k : kModalKeys)
    if (rotate || !k.rotateOnly) out += (out.empty() ? "" : ", ") + std::string(k.keys) + " " + k.brief;
  return out;
}

const CommandScope kScopes[] = {CommandScope::Global,      CommandScope::Viewport,    CommandScope::LatticeEdit,
                                CommandScope::Property,    CommandScope::DopeSheet,   CommandScope::CurveEditor,
                                CommandScope::Compare};

std::string menuPath(const Command& c) {
  if (c.menu.empty()) return "";
  std::string path = c.menu;
  for (size_t at = path.find('/'); at != std::string::npos; at = path.find('/', at + 3)) path.replace(at, 1, " > ");
  return path + " > " + c.label;
}

// "R Rotate, G Move Root": each bound command's first chord and label.
std::string keyList(const Keymap& keymap, const std::vector<const char*>& ids) {
  std::string out;
  for (const char* id : ids) {
    const Command* c = keymap.registry().find(id);
    const std::string chord = keymap.shortcut(id);
    if (!c || chord.empty()) continue;
    out += (out.empty() ? "" : ", ") + chord + " " + c->label;
  }
  return out;
}

std::string cell(const std::string& s) {  // a markdown table cell: '|' escaped
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::vector<ControlGroup> controlsTable(const Keymap& keymap) {
  std::vector<ControlGroup> groups;
  for (CommandScope scope : kScopes) {
    ControlGroup g;
    g.title = scopeTitle(scope);
    for (const Gesture& gesture : kGestures)
      if (gesture.scope == scope) g.rows.push_back(ControlRow{gesture.keys, gesture.action, "", "", ""});
    for (const Command& c : keymap.registry().all())
      if (c.scope == scope) g.rows.push_back(ControlRow{keymap.shortcuts(c.id, " / "), c.label, c.hint, menuPath(c), c.id});
    groups.push_back(std::move(g));
    if (scope == CommandScope::Viewport) {
      ControlGroup modal;
      modal.title = "While R, G or an IK drag runs";
      for (const ModalKey& k : kModalKeys) modal.rows.push_back(ControlRow{k.keys, k.action, "", "", ""});
      groups.push_back(std::move(modal));
    }
  }
  return groups;
}

std::string controlsMarkdown(const Keymap& keymap) {
  std::string out;
  for (const ControlGroup& g : controlsTable(keymap)) {
    out += (out.empty() ? "" : "\n") + std::string("### ") + g.title + "\n\n| Keys | Action | Menu | Command |\n|---|---|---|---|\n";
    for (const ControlRow& r : g.rows) {
      const std::string action = r.hint.empty() ? r.action : r.action + ": " + r.hint;
      out += "| " + cell(r.keys.empty() ? "-" : r.keys) + " | " + cell(action) + " | " + cell(r.menu) + " | " +
             (r.id.empty() ? std::string() : "`" + r.id + "`") + " |\n";
    }
  }
  return out;
}

std::string statusHint(const EditorState& state, const Keymap& keymap) {
  if (state.compare.active)
    return "Compare: " +
           keyList(keymap, {"compare.step", "compare.iteration", "compare.play", "compare.run_to_end", "compare.reset",
                            "compare.exit"}) +
           "; drag the target";
  switch (state.tool.mode) {
    case ModalTool::Rotate: return "Rotate: move the mouse; " + modalKeyLine(true);
    case ModalTool::Grab: return "Move: move the mouse; " + modalKeyLine(false);
    case ModalTool::BoxSelect: return "Box select: release to select (Shift adds, Ctrl removes)";
    case ModalTool::IkDrag: return "IK drag: the chain follows; " + modalKeyLine(false);
    case ModalTool::GizmoDrag: return "Gizmo: drag a ring to rotate about its axis, Esc cancels";
    case ModalTool::Navigate: return "View: orbit / pan";
    case ModalTool::LatticeGrab: return "Move lattice points: move the mouse; " + modalKeyLine(false);
    case ModalTool::None: break;
  }
  if (state.lattice.active)
    return "Lattice edit: click / box-select points, " +
           keyList(keymap, {"lattice.grab", "lattice.insert_keyframe", "lattice.select_all", "lattice.edit"});
  if (state.doc.selection.active() >= 0)
    return keyList(keymap, {"tool.rotate", "tool.grab", "edit.clear_rotation", "pose.add_ik_target", "anim.insert_keyframe"}) +
           ", Shift+click add";
  const std::string all = keyList(keymap, {"select.all"});
  return "Click a joint to select it" + (all.empty() ? std::string() : ", " + all);
}

}  // namespace kinema
