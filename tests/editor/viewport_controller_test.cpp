// Viewport navigation and picking as plain math (no window, no GL).
#include "editor/model/editor_state.h"
#include "editor/viewport/viewport_controller.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(ViewportController, OrbitTurnsByTheConfiguredRateAndClampsElevation) {
  ViewportController c;
  OrbitCamera cam;
  cam.azimuthDeg = 10;
  cam.elevationDeg = 0;
  c.orbit(cam, {25, 50});  // 0.4 degrees per pixel
  EXPECT_FLOAT_EQ(cam.azimuthDeg, 0.0f);
  EXPECT_FLOAT_EQ(cam.elevationDeg, 20.0f);
  c.orbit(cam, {0, 1000});
  EXPECT_FLOAT_EQ(cam.elevationDeg, 89.9f);
}

TEST(ViewportController, PanKeepsThePointUnderTheCursorUnderTheCursor) {
  ViewportController c;
  OrbitCamera cam;
  cam.azimuthDeg = 30;
  cam.elevationDeg = 20;
  cam.distance = 4;
  cam.target = {0, 1, 0};
  const float height = 600, aspect = 1.5f;
  const glm::vec3 anchor = cam.target;  // a point at the target's depth, at the screen centre
  c.pan(cam, {60, -30}, height);
  // After dragging 60 px right and 30 px up, the anchor must sit 60 px right, 30 px up of centre.
  const glm::vec4 clip = cam.projection(aspect) * cam.view() * glm::vec4(anchor, 1);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  EXPECT_NEAR(ndc.x * 0.5f * height * aspect, 60.0f, 1e-2f);
  EXPECT_NEAR(ndc.y * 0.5f * height, 30.0f, 1e-2f);
  EXPECT_NEAR(cam.distance, 4.0f, 1e-6f);
}

TEST(ViewportController, ZoomDividesTheDistancePerNotch) {
  ViewportController c;
  OrbitCamera cam;
  cam.distance = 1.44f;
  c.zoom(cam, 2);
  EXPECT_NEAR(cam.distance, 1.0f, 1e-6f);
  c.zoom(cam, -1);
  EXPECT_NEAR(cam.distance, 1.2f, 1e-6f);
  c.zoom(cam, 1e6f);
  EXPECT_GT(cam.distance, 0.0f);
}

TEST(PickJoint, FindsTheNearestJointOnScreenWithinTheRadius) {
  OrbitCamera cam;
  cam.azimuthDeg = 0;
  cam.elevationDeg = 0;
  cam.distance = 5;
  std::vector<glm::mat4> world(3, glm::mat4(1));
  world[1][3] = glm::vec4(1, 0, 0, 1);
  world[2][3] = glm::vec4(0, 0, 10, 1);  // behind the eye (eye at z = 5)
  const glm::vec2 size(800, 600);
  const glm::mat4 vp = cam.projection(size.x / size.y) * cam.view();
  EXPECT_EQ(pickJoint(world, vp, size, {400, 300}, 10), 0);  // the origin is the screen centre
  // Joint 1 is 1 unit right at depth 5: 1 / (5 tan 17.5 deg) of the half-height (300 px).
  const float px = 300.0f / (5.0f * std::tan(glm::radians(17.5f)));
  EXPECT_EQ(pickJoint(world, vp, size, {400 + px - 3, 302}, 10), 1);
  EXPECT_EQ(pickJoint(world, vp, size, {400 + px / 2, 300}, 10), -1);
}

TEST(EditorState, PlaybackWrapsWhenLoopingAndStopsOtherwise) {
  EditorState s;
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform{});
  Clip clip;
  Channel ch;
  ch.joint = 0;
  ch.target = ChannelTarget::Translation;
  ch.times = {0.0f, 2.0f};
  ch.values = {glm::vec4(0), glm::vec4(4, 0, 0, 0)};
  clip.channels.push_back(ch);
  clip.frameTime = 0.5;
  scene.clips.push_back(clip);
  s.doc = Document(scene);
  EXPECT_EQ(ownFrameGrid(s.doc.scene().clips[0]).nearestFrame(s.duration()), 4);  // frames 0..4, 0.5 s apart
  s.playing = true;
  s.time = 1.5;
  advancePlayback(s, 1.0);
  EXPECT_NEAR(s.time, 0.5, 1e-12);
  s.loop = false;
  advancePlayback(s, 3.0);
  EXPECT_NEAR(s.time, 2.0, 1e-12);
  EXPECT_FALSE(s.playing);
  s.time = 1.0;
  s.sampleClip = true;  // the timeline moved while stopped: the document takes that frame
  evaluateEditorPose(s);
  EXPECT_VEC3_NEAR(glm::vec3(s.world()[0][3]), glm::vec3(2, 0, 0), 1e-6f);
}

TEST(EditorPlayback, PausingHandsTheFrameToTheDocument) {
  // A root moving 1 unit per second along X: while playing, and after pausing at t = 1.5,
  // the document's pose (what edits start from) is the clip's frame, set with
  // Document::setAnimatedPose: no undo step and nothing unsaved (Blender re-evaluates the
  // action on a frame change).
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform{});
  Clip clip;
  clip.channels.push_back(Channel{0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 4.0f},
                                  {glm::vec4(0), glm::vec4(4, 0, 0, 0)}});
  scene.clips.push_back(clip);
  EditorState s;
  s.doc = Document(scene);
  s.playing = true;
  evaluateEditorPose(s);
  advancePlayback(s, 1.5);
  evaluateEditorPose(s);
  EXPECT_VEC3_NEAR(glm::vec3(s.world()[0][3]), glm::vec3(1.5f, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(s.doc.pose().local[0].translation, glm::vec3(1.5f, 0, 0), 1e-6f);
  s.playing = false;
  evaluateEditorPose(s);
  EXPECT_VEC3_NEAR(s.doc.pose().local[0].translation, glm::vec3(1.5f, 0, 0), 1e-6f);
  EXPECT_EQ(s.doc.historyPosition(), 0);
  EXPECT_FALSE(s.doc.dirty());
}

TEST(EditorPlayback, LoopsOverTheClipsPlaybackRange) {
  EditorState s;
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform{});
  Clip clip;
  clip.channels.push_back(Channel{0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 4.0f},
                                  {glm::vec4(0), glm::vec4(4, 0, 0, 0)}});
  clip.hasRange = true;  // play 1 s .. 3 s of a 4 s clip, as Blender's start/end frames do
  clip.rangeStart = 1.0f;
  clip.rangeEnd = 3.0f;
  scene.clips.push_back(clip);
  s.doc = Document(scene);
  s.playing = true;
  s.time = 0.0;
  advancePlayback(s, 0.25);
  EXPECT_NEAR(s.time, 1.0, 1e-12);  // before the range: jumps to its start
  s.time = 2.5;
  advancePlayback(s, 1.0);          // 3.5 wraps to 1 + 0.5
  EXPECT_NEAR(s.time, 1.5, 1e-12);
  s.loop = false;
  advancePlayback(s, 5.0);
  EXPECT_NEAR(s.time, 3.0, 1e-12);
  EXPECT_FALSE(s.playing);
}

}  // namespace
}  // namespace kinema::test
