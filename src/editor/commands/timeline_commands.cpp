// The timeline's transport as commands (timeline.h): the keys work over the 3D view and the
// animation editors alike, and the timeline's buttons run the same commands.
#include "editor/commands/command_sets.h"
#include "editor/model/key_codes.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

bool timelineUsable(const CommandContext& c) { return documentShown(c) && c.state.timelineShown(); }

Command transport(const char* id, const char* label, int key, int mods, const char* hint, void (*action)(EditorState&)) {
  return CommandDef(id, label).key(key, mods).hint(hint).enabled(timelineUsable)
      .run([action](CommandContext& c) { action(c.state); });
}

}  // namespace

void addTimelineCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("timeline.play", "Play").key(keys::SPACE).hint("play / pause from the current frame")
                    .enabled(timelineUsable)
                    .checked([](const CommandContext& c) { return c.state.playing; })
                    .run([](CommandContext& c) { togglePlayback(c.state); }));
  out.push_back(transport("timeline.step_back", "Step Back", keys::LEFT, 0, "one frame back",
                          [](EditorState& s) { stepFrame(s, -1); }));
  out.push_back(transport("timeline.step_forward", "Step Forward", keys::RIGHT, 0, "one frame on",
                          [](EditorState& s) { stepFrame(s, 1); }));
  out.push_back(transport("timeline.jump_start", "Jump to Start", keys::LEFT, kModShift, "to the range's first frame",
                          jumpToStart));
  out.push_back(transport("timeline.jump_end", "Jump to End", keys::RIGHT, kModShift, "to the range's last frame",
                          jumpToEnd));
}

}  // namespace kinema
