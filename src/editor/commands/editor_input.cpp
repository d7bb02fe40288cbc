#include "editor/commands/editor_input.h"

#include "editor/model/key_codes.h"
#include "editor/viewport/viewport_tools.h"

namespace kinema {

namespace {

const Keymap& keymapOf(const CommandContext& ctx) {
  static const Keymap defaults;
  return ctx.keymap ? *ctx.keymap : defaults;
}

}  // namespace

std::vector<CommandScope> keyScopes(const EditorState& state, glm::vec2 mouse) {
  if (state.compare.active) return {CommandScope::Compare, CommandScope::Global};
  if (state.dopeSheet.gesture != DopeSheetState::Gesture::None || state.curveEditor.drag != CurveEditorState::Drag::None)
    return {};
  if (state.animationEditorContains(mouse))
    return {state.animationEditor == AnimationEditorKind::DopeSheet ? CommandScope::DopeSheet : CommandScope::CurveEditor,
            CommandScope::Global};
  std::vector<CommandScope> scopes;
  if (state.hoveredProperty.valid()) scopes.push_back(CommandScope::Property);
  if (state.lattice.active) scopes.push_back(CommandScope::LatticeEdit);
  scopes.push_back(CommandScope::Viewport);
  scopes.push_back(CommandScope::Global);
  return scopes;
}

const Command* runChord(const Keymap& keymap, CommandContext& ctx, KeyChord chord, const std::vector<CommandScope>& scopes) {
  for (CommandScope scope : scopes) {
    const Command* c = keymap.holder(scope, chord);
    if (c && c->isEnabled(ctx)) {
      c->run(ctx);
      return c;
    }
  }
  return nullptr;
}

void EditorInput::handle(CommandContext& ctx, const InputEvent& e, const SkeletonDrawList& list, bool mouseCaptured,
                         bool keyboardCaptured) {
  EditorState& state = ctx.state;
  const int mods = held_.track(e);
  ctx.mouse = held_.mouse;
  if (e.type == InputEventType::Command) {
    const std::string why = runCommand(keymapOf(ctx).registry(), e.text, ctx);
    if (!why.empty()) state.statusMessage = why;
    return;
  }
  // The Esc that closes an open menu or combo (closePopupsOnEscape) is that popup's alone.
  if (e.type == InputEventType::KeyDown && e.key == keys::ESCAPE && state.panels.popupOpen) return;
  const bool toolRunning = state.tool.mode != ModalTool::None;  // before the event: Esc may end it
  // Esc closes Help > Controls, as a Blender pop-up closes (a running tool's Esc stays the tool's).
  if (e.type == InputEventType::KeyDown && e.key == keys::ESCAPE && state.panels.showHelp && !toolRunning) {
    state.panels.showHelp = false;
    return;
  }
  if (state.compare.active) handleCompareEvent(state.compare, e, mouseCaptured);
  else if (ctx.tools) ctx.tools->handle(state, e, ctx.view, list, mouseCaptured);
  if (e.type != InputEventType::KeyDown || isModifierKey(e.key) || keyboardCaptured || (toolRunning && !state.compare.active))
    return;
  runChord(keymapOf(ctx), ctx, KeyChord{e.key, mods & (kModShift | kModCtrl | kModAlt | kModSuper)},
           keyScopes(state, held_.mouse));
}

}  // namespace kinema
