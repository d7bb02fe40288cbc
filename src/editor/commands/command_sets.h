#pragma once
// The editor's commands by area, each file appending its own in menu order (the registry,
// command_registry.cpp, puts them together). Internal to the commands layer.
#include <vector>

#include "editor/commands/command_registry.h"

namespace kinema {

void addFileCommands(std::vector<Command>& out);             // File menu (file_commands.cpp)
void addEditCommands(std::vector<Command>& out);             // Edit menu (edit_commands.cpp)
void addViewCommands(std::vector<Command>& out);             // View menu (view_commands.cpp)
void addPoseCommands(std::vector<Command>& out);             // Pose menu, selection, R / G (pose_commands.cpp)
void addLatticeCommands(std::vector<Command>& out);          // Pose menu: lattice edit mode (lattice_commands.cpp)
void addClipCommands(std::vector<Command>& out);             // Clip menu: the clip list (clip_commands.cpp)
void addMotionCommands(std::vector<Command>& out);           // Animation menu: contacts, clean up (motion_commands.cpp)
void addSimulateCommands(std::vector<Command>& out);         // Simulate menu (simulate_commands.cpp)
void addCrowdCommands(std::vector<Command>& out);            // Simulate menu: crowds (crowd_commands.cpp)
void addParticleCommands(std::vector<Command>& out);         // Simulate menu: particles (particle_commands.cpp)
void addStiffSpringsCommand(std::vector<Command>& out);      // Teach > Stiff Springs, after every Simulate command (simulate_commands.cpp)
void addTimelineCommands(std::vector<Command>& out);         // play, step, jump (timeline_commands.cpp)
void addAnimationEditorCommands(std::vector<Command>& out);  // dope sheet, curve editor keys
void addCompareCommands(std::vector<Command>& out);          // Teach menu, compare mode keys
void addHelpCommands(std::vector<Command>& out);             // Help menu

// Builds a Command field by field, so the definitions read as one line per property:
//   out.push_back(CommandDef("file.save", "Save").menu("File").key(keys::S, kModCtrl).run(...));
class CommandDef {
 public:
  CommandDef(std::string id, std::string label) {
    c_.id = std::move(id);
    c_.label = std::move(label);
  }
  CommandDef& menu(std::string path, bool separatorBefore = false) {
    c_.menu = std::move(path);
    c_.separatorBefore = separatorBefore;
    return *this;
  }
  CommandDef& key(int key, int mods = 0) {
    c_.keys.push_back(KeyChord{key, mods});
    return *this;
  }
  CommandDef& scope(CommandScope s) {
    c_.scope = s;
    return *this;
  }
  CommandDef& hint(std::string text) {
    c_.hint = std::move(text);
    return *this;
  }
  CommandDef& enabled(std::function<bool(const CommandContext&)> f) {
    c_.enabled = std::move(f);
    return *this;
  }
  CommandDef& checked(std::function<bool(const CommandContext&)> f) {
    c_.checked = std::move(f);
    return *this;
  }
  CommandDef& run(std::function<void(CommandContext&)> f) {
    c_.run = std::move(f);
    return *this;
  }
  operator Command() const { return c_; }

 private:
  Command c_;
};
// The document is hidden while Teach > Compare Solvers is open: no edits of it then.
inline bool documentShown(const CommandContext& ctx) { return !ctx.state.compare.active; }
// The enabled-when rules the command sets share: no drag under way; and no modal tool (grab,
// rotate, box select) running; and a clip to edit. A joint selection.
inline bool documentIdle(const CommandContext& c) { return documentShown(c) && !c.state.doc.dragging(); }
inline bool documentIdleNoTool(const CommandContext& c) { return documentIdle(c) && c.state.tool.mode == ModalTool::None; }
inline bool idleOnClip(const CommandContext& c) { return documentIdleNoTool(c) && c.state.hasMotion(); }
inline bool hasJointSelection(const CommandContext& c) { return documentShown(c) && !c.state.doc.selection.empty(); }
// The clip the timeline, dope sheet and curve editor edit (valid while hasMotion()).
inline const Clip& editedClip(const EditorState& s) { return s.doc.scene().clips[s.clip]; }

}  // namespace kinema
