// The command registry and its dispatch without a window (commands/): every command named
// and labelled once, default keys bound once per scope, keys routed by where the mouse is,
// script command events, the generated controls, and the one active IK target that the
// Pose menu, Shift+I and the IK panel all act on (issue 17's Pin IK Target bug).
#include <set>

#include "core/default_character.h"
#include "editor/commands/controls_help.h"
#include "editor/commands/editor_input.h"
#include "editor/model/active_ik_target.h"
#include "editor/model/key_codes.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(CommandRegistry, EveryCommandHasALabelAUniqueIdAndSomethingToRun) {
  std::set<std::string> ids;
  ASSERT_GE(editorCommands().all().size(), 60u);
  for (const Command& c : editorCommands().all()) {
    EXPECT_FALSE(c.label.empty()) << c.id;
    EXPECT_NE(c.id.find('.'), std::string::npos) << c.id << ": ids are area.action";
    EXPECT_TRUE(ids.insert(c.id).second) << c.id << " twice";
    EXPECT_TRUE(static_cast<bool>(c.run)) << c.id;
    EXPECT_EQ(editorCommands().find(c.id), &c);
  }
  EXPECT_EQ(editorCommands().find("no.such_command"), nullptr);
  CommandRegistry r;
  EXPECT_EQ(r.add(Command{}), "a command without an id");
  Command c;
  c.id = "x.y";
  c.label = "X";
  c.run = [](CommandContext&) {};
  EXPECT_EQ(r.add(c), "");
  EXPECT_EQ(r.add(c), "x.y: the id is taken");
}

TEST(CommandRegistry, EveryDefaultChordIsBoundAtMostOncePerScopeAndHasAName) {
  std::map<std::pair<CommandScope, KeyChord>, std::string> seen;
  for (const Command& c : editorCommands().all())
    for (const KeyChord& k : c.keys) {
      EXPECT_FALSE(formatChord(k).empty()) << c.id;
      const auto [it, fresh] = seen.emplace(std::make_pair(c.scope, k), c.id);
      EXPECT_TRUE(fresh) << formatChord(k) << " is bound to both " << it->second << " and " << c.id << " in "
                         << toString(c.scope);
    }
}

TEST(CommandRegistry, TheDefaultKeysAreTodaysKeys) {
  // The keys the editor had before the registry (viewport_tools.cpp, main_menu.cpp, the
  // dope sheet, the curve editor, the compare mode), each still on its command.
  const Keymap k;
  const std::pair<const char*, const char*> expected[] = {
      {"file.new", "Ctrl+N"}, {"file.open", "Ctrl+O"}, {"file.save", "Ctrl+S"}, {"file.save_as", "Ctrl+Shift+S"},
      {"file.quit", "Ctrl+Q"}, {"edit.undo", "Ctrl+Z"}, {"edit.redo", "Ctrl+Shift+Z, Ctrl+Y"},
      {"edit.copy_pose", "Ctrl+C"}, {"edit.paste_pose", "Ctrl+V"}, {"edit.paste_flipped", "Ctrl+Shift+V"},
      {"edit.clear_rotation", "Alt+R"}, {"edit.auto_ik", "Ctrl+I"}, {"view.front", "Numpad 1"},
      {"view.back", "Ctrl+Numpad 1"}, {"view.right", "Numpad 3"}, {"view.left", "Ctrl+Numpad 3"},
      {"view.top", "Numpad 7"}, {"view.bottom", "Ctrl+Numpad 7"}, {"view.orthographic", "Numpad 5"},
      {"view.frame_selected", "F"}, {"view.frame_all", "Home"}, {"view.cycle_bones", "Alt+Z"},
      {"view.weights", "Alt+W"}, {"view.curve_editor", "Shift+F6"}, {"view.onion_skin", "Alt+O"},
      {"view.motion_path", "Alt+P"}, {"view.motion_control", "Alt+M"}, {"pose.add_ik_target", "Shift+I"},
      {"pose.bind_automatic_weights", "Ctrl+P"}, {"anim.insert_keyframe", "I"}, {"anim.delete_keyframe", "Alt+I"},
      {"select.all", "A"}, {"select.none", "Alt+A"}, {"tool.rotate", "R"}, {"tool.grab", "G"},
      {"timeline.play", "Space"}, {"timeline.step_back", "Left"}, {"timeline.step_forward", "Right"},
      {"timeline.jump_start", "Shift+Left"}, {"timeline.jump_end", "Shift+Right"}, {"help.controls", "F1"},
      {"dopesheet.select_all", "A"}, {"dopesheet.select_none", "Alt+A"}, {"dopesheet.delete_keys", "X, Delete"},
      {"dopesheet.move_keys", "G"}, {"dopesheet.copy_keys", "Ctrl+C"}, {"dopesheet.paste_keys", "Ctrl+V"},
      {"dopesheet.paste_keys_onto_selected", "Ctrl+Shift+V"}, {"dopesheet.frame_all", "Home"},
      {"curves.frame_all", "Home"}, {"compare.step", "Right"}, {"compare.iteration", "Shift+Right"},
      {"compare.play", "Space"}, {"compare.run_to_end", "End"}, {"compare.reset", "R"}, {"compare.exit", "Esc"},
  };
  for (const auto& [id, keys] : expected) {
    ASSERT_NE(editorCommands().find(id), nullptr) << id;
    EXPECT_EQ(k.shortcuts(id), keys) << id;
  }
}

TEST(CommandRegistry, TheMainMenusComeInBlendersOrder) {
  std::vector<std::string> titles;
  for (const Command& c : editorCommands().all()) {
    if (c.menu.empty()) continue;
    const std::string title = c.menu.substr(0, c.menu.find('/'));
    if (titles.empty() || titles.back() != title) titles.push_back(title);
  }
  EXPECT_EQ(titles, (std::vector<std::string>{"File", "Edit", "View", "Pose", "Clip", "Animation", "Simulate", "Teach", "Help"}))
      << "each menu's commands are together, in this order";
}

// The default character, nothing selected; commands run as the window runs them, without
// the viewport's tools (a model-level test).
struct Editor {
  EditorState state;
  Keymap keymap;
  EditorInput input;
  SkeletonDrawList list;
  Editor() {
    Scene scene;
    scene.skeleton = makeDefaultCharacter();
    state.doc = Document(scene);
    evaluateEditorPose(state);
  }
  CommandContext context() {
    CommandContext ctx(state);
    ctx.keymap = &keymap;
    ctx.view.size = glm::vec2(800, 600);
    return ctx;
  }
  int joint(const char* name) const { return state.doc.skeleton().find(name); }
  void select(const char* name) { state.doc.selection.click(joint(name)); }
  std::string run(const std::string& id) {
    CommandContext ctx = context();
    const std::string error = runCommand(editorCommands(), id, ctx);
    evaluateEditorPose(state);
    return error;
  }
  void send(InputEventType type, int key = -1, const std::string& text = "") {
    InputEvent e;
    e.type = type;
    e.key = key;
    e.text = text;
    CommandContext ctx = context();
    input.handle(ctx, e, list, false, false);
    evaluateEditorPose(state);
  }
  void key(int k) {
    send(InputEventType::KeyDown, k);
    send(InputEventType::KeyUp, k);
  }
  void shiftKey(int k) {
    send(InputEventType::KeyDown, keys::LEFT_SHIFT);
    key(k);
    send(InputEventType::KeyUp, keys::LEFT_SHIFT);
  }
  void mouse(glm::vec2 p) {
    InputEvent e;
    e.type = InputEventType::MouseMove;
    e.x = p.x;
    e.y = p.y;
    CommandContext ctx = context();
    input.handle(ctx, e, list, false, false);
  }
  const std::vector<PoseIkTarget>& targets() const { return state.doc.ikTargets(); }
};

TEST(ActiveIkTarget, PinIkTargetPinsTheActiveJointsTargetNotTheFirstOne) {
  // Issue 17: Hand.R's target added first, then Foot.L selected and its target added with
  // Shift+I; Pose > Pin IK Target pinned Hand.R's (the row the IK panel had highlighted).
  Editor e;
  e.select("Hand.R");
  ASSERT_EQ(e.run("pose.add_ik_target"), "");  // the IK panel's Add and the menu item run this
  e.select("Foot.L");
  e.shiftKey(keys::I);
  ASSERT_EQ(e.targets().size(), 2u);
  EXPECT_EQ(e.targets()[0].target.effector, e.joint("Hand.R"));
  EXPECT_EQ(e.targets()[1].target.effector, e.joint("Foot.L"));
  EXPECT_EQ(activeIkTarget(e.state.doc), 1);
  ASSERT_EQ(e.run("pose.pin_ik_target"), "");
  EXPECT_TRUE(e.targets()[1].pinned) << "Foot.L's target, the active joint's";
  EXPECT_FALSE(e.targets()[0].pinned) << "Hand.R's target stays free";
  // The same command again unpins it; on Hand.R (a click on its row selects it) it pins that one.
  ASSERT_EQ(e.run("pose.pin_ik_target"), "");
  EXPECT_FALSE(e.targets()[1].pinned);
  e.select("Hand.R");
  ASSERT_EQ(e.run("pose.pin_ik_target"), "");
  EXPECT_TRUE(e.targets()[0].pinned);
  EXPECT_FALSE(e.targets()[1].pinned);
  // Nothing active: nothing to pin, and the command says so instead of guessing.
  e.state.doc.selection.clear();
  EXPECT_EQ(e.run("pose.pin_ik_target"), "Pin IK Target is not available now");
}

TEST(ActiveIkTarget, AddIkTargetFromEveryEntryPointLeavesTheNewTargetActive) {
  Editor e;
  e.state.panels.ikChainLength = 3;
  // The menu item and the IK panel's button run the command by id.
  e.select("Hand.L");
  ASSERT_EQ(e.run("pose.add_ik_target"), "");
  EXPECT_EQ(activeIkTarget(e.state.doc), 0);
  EXPECT_EQ(e.targets()[0].chainLength, 3);
  // Shift+I over the 3D view.
  e.select("Foot.R");
  e.shiftKey(keys::I);
  ASSERT_EQ(e.targets().size(), 2u);
  EXPECT_EQ(activeIkTarget(e.state.doc), 1);
  EXPECT_EQ(e.targets()[1].target.effector, e.joint("Foot.R"));
  // A script's command event.
  e.select("Head");
  e.send(InputEventType::Command, -1, "pose.add_ik_target");
  ASSERT_EQ(e.targets().size(), 3u);
  EXPECT_EQ(activeIkTarget(e.state.doc), 2);
  EXPECT_EQ(e.targets()[2].target.effector, e.joint("Head"));
  // A second target on the same joint would not be the active one: refused, with a reason.
  e.run("pose.add_ik_target");
  EXPECT_EQ(e.targets().size(), 3u);
  ASSERT_FALSE(e.state.panels.errors.empty());
  EXPECT_NE(e.state.panels.errors.back().find("Head has one already"), std::string::npos);
  // Remove acts on the active one too.
  e.select("Foot.R");
  ASSERT_EQ(e.run("pose.remove_ik_target"), "");
  ASSERT_EQ(e.targets().size(), 2u);
  EXPECT_EQ(e.targets()[1].target.effector, e.joint("Head"));
}

TEST(KeyDispatch, KeysGoToTheScopeUnderTheMouseThenToGlobal) {
  Editor e;
  e.state.viewportRect = glm::vec4(250, 19, 720, 400);
  e.state.animationEditor = AnimationEditorKind::DopeSheet;
  const glm::vec2 overView(500, 200), overDopeSheet(500, 19 + 400 + 10);
  EXPECT_EQ(keyScopes(e.state, overView), (std::vector<CommandScope>{CommandScope::Viewport, CommandScope::Global}));
  EXPECT_EQ(keyScopes(e.state, overDopeSheet), (std::vector<CommandScope>{CommandScope::DopeSheet, CommandScope::Global}));
  e.state.animationEditor = AnimationEditorKind::CurveEditor;
  EXPECT_EQ(keyScopes(e.state, overDopeSheet), (std::vector<CommandScope>{CommandScope::CurveEditor, CommandScope::Global}));
  e.state.curveEditor.drag = CurveEditorState::Drag::Pan;
  EXPECT_TRUE(keyScopes(e.state, overDopeSheet).empty()) << "the editor's own drag keeps Esc";
  e.state.curveEditor.drag = CurveEditorState::Drag::None;
  e.state.compare.active = true;
  EXPECT_EQ(keyScopes(e.state, overView), (std::vector<CommandScope>{CommandScope::Compare, CommandScope::Global}));
  e.state.compare.active = false;

  // A over the 3D view selects every joint; over the dope sheet (no clip: its commands are
  // disabled) it falls through to Global, which has no A.
  e.state.animationEditor = AnimationEditorKind::DopeSheet;
  e.mouse(overDopeSheet);
  e.key(keys::A);
  EXPECT_TRUE(e.state.doc.selection.empty());
  e.mouse(overView);
  e.key(keys::A);
  EXPECT_EQ(static_cast<int>(e.state.doc.selection.joints().size()), e.state.doc.skeleton().size());
  // Modifiers held as keys count (scripts); a chord matches exactly.
  e.send(InputEventType::KeyDown, keys::LEFT_ALT);
  e.key(keys::A);
  e.send(InputEventType::KeyUp, keys::LEFT_ALT);
  EXPECT_TRUE(e.state.doc.selection.empty()) << "Alt+A";
  e.send(InputEventType::KeyDown, keys::LEFT_CONTROL);
  e.key(keys::A);
  e.send(InputEventType::KeyUp, keys::LEFT_CONTROL);
  EXPECT_TRUE(e.state.doc.selection.empty()) << "Ctrl+A is bound to nothing";
  // Global keys work over both: F1 opens Help > Controls.
  e.key(keys::F1);
  EXPECT_TRUE(e.state.panels.showHelp);
}

TEST(KeyDispatch, AKeyImGuiWantsRunsNothingAndARebindingTakesEffect) {
  Editor e;
  InputEvent down;
  down.type = InputEventType::KeyDown;
  down.key = keys::A;
  CommandContext ctx = e.context();
  e.input.handle(ctx, down, e.list, false, /*keyboardCaptured=*/true);
  EXPECT_TRUE(e.state.doc.selection.empty()) << "typing 'a' into a text field";
  ASSERT_TRUE(e.keymap.apply("select.all = none\nselect.all = Shift+A\n", "k").empty());
  e.key(keys::A);
  EXPECT_TRUE(e.state.doc.selection.empty());
  e.shiftKey(keys::A);
  EXPECT_FALSE(e.state.doc.selection.empty());
}

TEST(KeyDispatch, TheCompareModeTakesItsKeysFirstAndHidesTheDocumentsCommands) {
  Editor e;
  e.state.compare.active = true;
  ASSERT_EQ(openComparePreset(e.state.compare, "ccd-steps"), "");
  e.key(keys::SPACE);
  EXPECT_TRUE(e.state.compare.playing);
  EXPECT_FALSE(e.state.playing) << "the timeline's Space is shadowed";
  e.key(keys::RIGHT);
  EXPECT_FALSE(e.state.compare.playing) << "a step pauses";
  EXPECT_EQ(e.state.compare.comparison.runs[0].cursor, 1);
  e.key(keys::A);
  EXPECT_TRUE(e.state.doc.selection.empty()) << "no document commands while the mode covers the 3D view";
  e.key(keys::ESCAPE);
  EXPECT_FALSE(e.state.compare.active);
}

TEST(ScriptCommands, ACommandEventRunsItsCommandAndAnUnknownIdIsAParseError) {
  const CommandIdCheck known = [](const std::string& id) { return editorCommands().find(id) != nullptr; };
  Result<std::vector<InputEvent>> r = parseInputScript(
      "{\"frame\":1,\"type\":\"key\",\"key\":\"A\"}\n{\"frame\":2,\"type\":\"command\",\"id\":\"pose.pin_ik_target\"}\n",
      "s.jsonl", known);
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.value().size(), 3u);
  EXPECT_EQ(r.value()[2].type, InputEventType::Command);
  EXPECT_EQ(r.value()[2].text, "pose.pin_ik_target");
  r = parseInputScript("{\"frame\":1,\"type\":\"key\",\"key\":\"A\"}\n{\"frame\":2,\"type\":\"command\",\"id\":\"pose.pin\"}\n",
                       "s.jsonl", known);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "s.jsonl: line 2: 'id' \"pose.pin\" is not a command (kinema edit --list-commands lists them)");
  r = parseInputScript("[{\"frame\":1,\"type\":\"command\"}]", "a.json", known);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("event 0: missing 'id'"), std::string::npos) << r.error();

  Editor e;
  e.send(InputEventType::Command, -1, "view.grid");
  EXPECT_FALSE(e.state.view.showGrid);
  e.send(InputEventType::Command, -1, "pose.pin_ik_target");
  EXPECT_EQ(e.state.statusMessage, "Pin IK Target is not available now");
}

TEST(ControlsHelp, TheTableListsEveryCommandWithTheActiveKeys) {
  Keymap keymap;
  ASSERT_TRUE(keymap.apply("tool.rotate = Shift+R\n", "k").empty());
  const std::string md = controlsMarkdown(keymap);
  for (const Command& c : editorCommands().all()) EXPECT_NE(md.find("`" + c.id + "`"), std::string::npos) << c.id;
  EXPECT_NE(md.find("| Ctrl+Shift+Z / Ctrl+Y | Redo | Edit > Redo | `edit.redo` |"), std::string::npos);
  EXPECT_NE(md.find("| Shift+R | Rotate: "), std::string::npos) << "the keymap's chord, not the default";
  EXPECT_NE(md.find("### 3D view"), std::string::npos);
  EXPECT_NE(md.find("| Wheel | zoom |"), std::string::npos) << "the mouse gestures are listed too";
  EXPECT_NE(md.find("### While R, G or an IK drag runs"), std::string::npos);
  EXPECT_NE(md.find("File > Export > GLB (.glb)..."), std::string::npos);
}

TEST(ControlsHelp, TheStatusHintShowsTheActiveKeys) {
  Editor e;
  EXPECT_EQ(statusHint(e.state, e.keymap), "Click a joint to select it, A Select All");
  e.select("Hand.L");
  EXPECT_EQ(statusHint(e.state, e.keymap).rfind("R Rotate, G Move Root, Alt+R Clear Rotation, Shift+I Add IK Target", 0),
            0u)
      << statusHint(e.state, e.keymap);
  ASSERT_TRUE(e.keymap.apply("tool.rotate = Shift+R\n", "k").empty());
  EXPECT_EQ(statusHint(e.state, e.keymap).rfind("Shift+R Rotate, G Move Root", 0), 0u);
  e.state.tool.mode = ModalTool::Rotate;
  EXPECT_NE(statusHint(e.state, e.keymap).find("X / Y / Z constrain"), std::string::npos);
  e.state.tool.mode = ModalTool::None;
  e.state.compare.active = true;
  EXPECT_EQ(statusHint(e.state, e.keymap),
            "Compare: Right Step, Shift+Right Step Iteration, Space Play, End Run to End, R Reset, Esc Leave Compare "
            "Mode; drag the target");
}

}  // namespace
}  // namespace kinema::test
