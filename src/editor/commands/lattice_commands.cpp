// Lattice edit mode (issue 22; Blender's lattice edit mode): Tab (or Pose > Edit Lattice, or
// the Edit button of a lattice in Properties > Deformers) enters and leaves it; in the mode
// the 3D view's G, I, A and Alt+A act on the lattice's control points (scope LatticeEdit,
// which editor_input.h's keyScopes puts before the viewport's pose-mode keys). Also I over a
// keyable field of the Properties panel (scope Property).
#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/key_codes.h"
#include "editor/model/lattice_editing.h"
#include "editor/model/property_keying.h"
#include "editor/viewport/viewport_tools.h"

namespace kinema {

namespace {

bool latticeEditing(const CommandContext& c) { return documentShown(c) && c.state.lattice.active; }
bool latticeToolIdle(const CommandContext& c) { return c.state.tool.mode == ModalTool::None && !c.state.doc.dragging(); }

}  // namespace

void addLatticeCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("lattice.edit", "Edit Lattice").menu("Pose", true).key(keys::TAB).scope(CommandScope::Viewport)
                    .hint("lattice edit mode on the active lattice: select its points, G moves them, I keys them")
                    .enabled([](const CommandContext& c) {
                      int instance = -1, deformer = -1;
                      return documentShown(c) && latticeToolIdle(c) &&
                             (c.state.lattice.active || latticeToEdit(c.state, instance, deformer));
                    })
                    .checked([](const CommandContext& c) { return c.state.lattice.active; })
                    .run([](CommandContext& c) {
                      if (c.state.lattice.active) {
                        exitLatticeEdit(c.state);
                        c.state.statusMessage = "Left lattice edit mode";
                        return;
                      }
                      const std::string error = enterLatticeEdit(c.state);
                      if (!error.empty()) return showEditorError(c.state, error);
                      c.state.statusMessage = "Editing '" + editedLattice(c.state)->name +
                                              "': click or box-select points, G moves, I keys, Tab leaves";
                    }));
  out.push_back(CommandDef("lattice.grab", "Move Lattice Points").key(keys::G).scope(CommandScope::LatticeEdit)
                    .hint("move the selected points with the mouse (then X/Y/Z; auto-key or animated points: keyed)")
                    .enabled([](const CommandContext& c) { return latticeEditing(c) && latticeToolIdle(c) && c.tools; })
                    .run([](CommandContext& c) { c.tools->startLatticeGrab(c.state); }));
  out.push_back(CommandDef("lattice.insert_keyframe", "Insert Lattice Keys").key(keys::I).scope(CommandScope::LatticeEdit)
                    .hint("key the selected points at the current frame")
                    .enabled([](const CommandContext& c) { return latticeEditing(c) && latticeToolIdle(c); })
                    .run([](CommandContext& c) { c.state.statusMessage = keyLatticePoints(c.state); }));
  out.push_back(CommandDef("lattice.select_all", "Select All Lattice Points").key(keys::A).scope(CommandScope::LatticeEdit)
                    .enabled([](const CommandContext& c) { return latticeEditing(c) && latticeToolIdle(c); })
                    .run([](CommandContext& c) { selectAllLatticePoints(c.state); }));
  out.push_back(CommandDef("lattice.select_none", "Deselect Lattice Points").key(keys::A, kModAlt)
                    .scope(CommandScope::LatticeEdit)
                    .enabled([](const CommandContext& c) { return latticeEditing(c) && latticeToolIdle(c); })
                    .run([](CommandContext& c) { selectNoLatticePoints(c.state.lattice); }));
  out.push_back(CommandDef("anim.key_hovered_property", "Insert Keyframe on Property").key(keys::I)
                    .scope(CommandScope::Property)
                    .hint("over a shape slider or a deformer parameter: key it at the current frame")
                    .enabled([](const CommandContext& c) { return documentShown(c) && c.state.hoveredProperty.valid(); })
                    .run([](CommandContext& c) { c.state.statusMessage = keyHoveredProperty(c.state); }));
}

}  // namespace kinema
