// The Clip menu's commands without a window (issue 18): each runs by id as its menu item,
// panel button and a script's command event do, is one undo step, and the views (the
// timeline's clip) follow the active clip at once, through undo and redo as well.
#include <cstdio>

#include "editor/commands/clip_commands.h"
#include "editor/commands/editor_input.h"
#include "editor/model/key_codes.h"
#include "editor/model/timeline.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// Two clips moving the root: "Walk" along X, "Run" along Z (2 units per second, 24 fps).
Scene twoClips() {
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform{});
  scene.skeleton.addJoint("Tip", 0, Transform{glm::vec3(0, 1, 0)});
  for (int c = 0; c < 2; ++c) {
    Clip clip;
    clip.name = c == 0 ? "Walk" : "Run";
    clip.frameTime = 1.0 / 24.0;
    glm::vec4 end(0.0f);
    end[c == 0 ? 0 : 2] = 2.0f;
    clip.channels.push_back(
        Channel{0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f}, {glm::vec4(0.0f), end}});
    scene.clips.push_back(clip);
  }
  return scene;
}

struct ClipEditor {
  EditorState state;
  Keymap keymap;
  EditorInput input;
  SkeletonDrawList list;
  ClipEditor() {
    state.doc = Document(twoClips());
    resetTimeline(state);
    evaluateEditorPose(state);
  }
  CommandContext context() {
    CommandContext ctx(state);
    ctx.keymap = &keymap;
    ctx.view.size = glm::vec2(800, 600);
    return ctx;
  }
  std::string run(const std::string& id) {
    CommandContext ctx = context();
    return runCommand(editorCommands(), id, ctx);  // no evaluate: the views must follow at once
  }
  void key(int k) {
    for (InputEventType t : {InputEventType::KeyDown, InputEventType::KeyUp}) {
      InputEvent e;
      e.type = t;
      e.key = k;
      CommandContext ctx = context();
      input.handle(ctx, e, list, false, false);
    }
  }
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const Clip& c : state.doc.scene().clips) n.push_back(c.name);
    return n;
  }
  float rootZ() const { return state.world()[0][3].z; }
};

TEST(ClipCommands, EachIsInTheClipMenu) {
  for (const char* id : {"clip.new", "clip.duplicate", "clip.rename", "clip.delete", "clip.previous", "clip.next"}) {
    const Command* c = editorCommands().find(id);
    ASSERT_NE(c, nullptr) << id;
    EXPECT_EQ(c->menu, "Clip") << id;
  }
  const Keymap k;
  EXPECT_EQ(k.shortcuts("clip.next"), "Page Up");
  EXPECT_EQ(k.shortcuts("clip.previous"), "Page Down");
}

TEST(ClipCommands, NextChoosesRunAndThePoseFollowsAtOnceUndoGoesBack) {
  ClipEditor e;
  goToFrame(e.state, 12);  // t = 0.5
  EXPECT_EQ(e.run("clip.previous"), "Previous Clip is not available now");  // Walk is the first
  e.key(keys::PAGE_UP);  // clip.next
  EXPECT_EQ(e.state.doc.activeClip(), 1);
  EXPECT_EQ(e.state.clip, 1);
  EXPECT_NEAR(e.rootZ(), 1.0f, 1e-6f);  // Run at t = 0.5
  EXPECT_EQ(e.state.statusMessage, "Clip Run");
  EXPECT_EQ(e.state.doc.historyLabels(), std::vector<std::string>{"Choose clip Run"});
  EXPECT_EQ(e.run("clip.next"), "Next Clip is not available now");  // Run is the last
  ASSERT_EQ(e.run("edit.undo"), "");
  EXPECT_EQ(e.state.clip, 0);
  EXPECT_NEAR(e.rootZ(), 0.0f, 1e-6f);
  ASSERT_EQ(e.run("edit.redo"), "");
  EXPECT_EQ(e.state.clip, 1);
  EXPECT_NEAR(e.rootZ(), 1.0f, 1e-6f);
}

TEST(ClipCommands, NewDuplicateDeleteAreOneUndoStepEach) {
  ClipEditor e;
  ASSERT_EQ(e.run("clip.duplicate"), "");
  EXPECT_EQ(e.names(), (std::vector<std::string>{"Walk", "Walk.001", "Run"}));
  EXPECT_EQ(e.state.clip, 1);
  ASSERT_EQ(e.run("clip.new"), "");
  EXPECT_EQ(e.names(), (std::vector<std::string>{"Walk", "Walk.001", "Run", "Action"}));
  EXPECT_EQ(e.state.clip, 3);
  ASSERT_EQ(e.run("clip.delete"), "");
  EXPECT_EQ(e.names(), (std::vector<std::string>{"Walk", "Walk.001", "Run"}));
  EXPECT_EQ(e.state.clip, 2);
  EXPECT_EQ(e.state.statusMessage, "Deleted clip Action");
  EXPECT_EQ(e.state.doc.historyLabels(),
            (std::vector<std::string>{"Duplicate clip Walk", "New clip Action", "Delete clip Action"}));
  for (int undo = 0; undo < 3; ++undo) ASSERT_EQ(e.run("edit.undo"), "");
  EXPECT_EQ(e.names(), (std::vector<std::string>{"Walk", "Run"}));
  EXPECT_EQ(e.state.clip, 0);
  // Delete every clip: the commands that need one grey out; New still works.
  ASSERT_EQ(e.run("clip.delete"), "");
  ASSERT_EQ(e.run("clip.delete"), "");
  EXPECT_TRUE(e.names().empty());
  EXPECT_FALSE(e.state.hasMotion());
  EXPECT_EQ(e.run("clip.delete"), "Delete Clip is not available now");
  EXPECT_EQ(e.run("clip.duplicate"), "Duplicate Clip is not available now");
  EXPECT_EQ(e.run("clip.rename"), "Rename Clip... is not available now");
  ASSERT_EQ(e.run("clip.new"), "");
  EXPECT_TRUE(e.state.hasMotion());
}

TEST(ClipCommands, RenameOpensTheFieldAndRefusesATakenName) {
  ClipEditor e;
  ASSERT_EQ(e.run("clip.rename"), "");
  EXPECT_EQ(e.state.panels.renamingClip, 0);
  EXPECT_STREQ(e.state.panels.clipRenameBuffer, "Walk");
  std::snprintf(e.state.panels.clipRenameBuffer, sizeof(e.state.panels.clipRenameBuffer), "Run");
  finishClipRename(e.state);
  EXPECT_EQ(e.state.panels.renamingClip, 0) << "the field stays open";
  EXPECT_NE(e.state.panels.clipRenameError.find("'Run'"), std::string::npos);
  EXPECT_NE(e.state.statusMessage.find("'Run'"), std::string::npos);
  EXPECT_FALSE(e.state.doc.canUndo());
  std::snprintf(e.state.panels.clipRenameBuffer, sizeof(e.state.panels.clipRenameBuffer), "Stroll");
  finishClipRename(e.state);
  EXPECT_EQ(e.state.panels.renamingClip, -1);
  EXPECT_EQ(e.names(), (std::vector<std::string>{"Stroll", "Run"}));
  EXPECT_EQ(e.state.doc.historyLabels(), std::vector<std::string>{"Rename clip Walk to Stroll"});
}

}  // namespace
}  // namespace kinema::test
