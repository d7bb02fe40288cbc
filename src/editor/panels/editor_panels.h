#pragma once
#include <string>

#include "editor/commands/command_context.h"
#include "editor/commands/file_commands.h"
#include "editor/model/editor_state.h"
#include "editor/panels/file_dialog.h"

namespace kinema {

// Immediate-mode ImGui panels over EditorState. Each draws one window and edits the state
// it is given; menu items and action buttons run the registry's commands through `ctx`
// (command_widgets.h), so they match the keys. The window calls drawEditorPanels() once per
// frame between ImGui::NewFrame() and ImGui::Render(); it draws everything below in a
// fixed layout.
void drawEditorPanels(CommandContext& ctx, float fps);

void drawMainMenuBar(CommandContext& ctx);     // File / Edit / View / Pose / Teach / Help, from the registry
void drawOutlinerPanel(CommandContext& ctx);  // joint tree, search, select, rename; the clip list under it
// The clip list at the bottom of the outliner (clip_list_panel.cpp): choose, new, duplicate,
// rename, delete, shown while the scene has clips; clipListHeight is what it takes of the
// outliner's height (0 without clips).
void drawClipList(CommandContext& ctx);
float clipListHeight(const EditorState& state);
void drawClipMenuList(CommandContext& ctx);  // the Clip menu's list of clips (a click chooses)
void drawPropertiesPanel(CommandContext& ctx); // active joint: rotation, location, limits, mesh, shapes
void drawIkTargetsPanel(CommandContext& ctx);  // IK targets and the active joint's target settings
void drawHistoryPanel(EditorState& state);    // undo stack, click to jump
void drawStatusBar(CommandContext& ctx, float fps);
void drawSessionDialogs(CommandContext& ctx);  // file dialog, discard / recover modals, errors, Help > Controls
// File > Import Motion onto Character…: the bone map of the chosen file, Apply / Cancel
// (motion_import_dialog.cpp).
void drawMotionImportDialog(CommandContext& ctx);
void drawAnimationDisplayWindows(EditorState& state);  // onion skin & motion path settings, motion control
void drawPreferencesWindow(CommandContext& ctx);  // Edit > Preferences: UI scale, theme, presentation, loop, new keys
void drawLogWindow(EditorState& state);           // View > Log: every message in full, with its time
void drawPanelSplitters(EditorState& state);      // the draggable boundaries between the panels
// The new-key defaults (radio buttons, named itemPrefix + label), in the Keys popup and Preferences.
void drawKeyPreferenceChoices(EditorState& state, const std::string& itemPrefix);
// Esc closes the open non-modal popups (menus, combos, context popups) above the topmost
// modal (modals answer Esc themselves); sets PanelState::popupOpen. Last in each frame.
void closePopupsOnEscape(EditorState& state);

// Older panels kept for the joint list view and playback.
void drawJointListPanel(EditorState& state);
void drawTimelinePanel(CommandContext& ctx);
void drawContactLanesPanel(CommandContext& ctx);  // the foot contact strip over the timeline (drag to edit)
void drawParticlesWindow(CommandContext& ctx);    // Simulate > Particle Settings…: the shown particle system
void drawSimulationWindow(CommandContext& ctx);   // Simulate > Simulation Settings…: chains, ragdolls, bake
void drawCrowdWindow(CommandContext& ctx);        // Simulate > Show Crowd Panel: the crowd's settings (crowd_window.cpp)
void drawStiffSpringsWindow(CommandContext& ctx); // Teach > Stiff Springs: the integrators' energy at a chosen step
void drawCleanUpWindow(CommandContext& ctx);      // Animation > Clean Up Motion…: contacts, locking, reduction, figures
void drawCurveEditorPanel(CommandContext& ctx);  // curve editor in the animation editor area (Shift+F6)

}  // namespace kinema
