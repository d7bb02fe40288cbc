// End-to-end test of the 3D view's quality switch (issue 20, model/viewport_quality.h):
// the real `kinema edit` under xvfb-run, with no --screenshot (a screenshot is always the
// still picture). While R rotates the arm the view is drawn with one sample per pixel, even
// on the frames where the mouse rests; once the rotation is confirmed the same view is
// drawn multisampled, then shown again from its kept copy while nothing changes.
#include <cmath>

#include "editor/e2e_harness.h"
#include "render/image_compare.h"

namespace kinema::test {
namespace {

using namespace e2e;

class ViewportQualityE2e : public FrontViewSuite<ViewportQualityE2e> {
 public:
  static constexpr const char* kShotFolder = "viewport_quality_e2e";

 protected:
  // runEditor without --screenshot: the dump then tells how the last frame was drawn.
  // `extra`: more options (--redraw, --screenshot).
  json runUnshot(const Script& script, const std::string& name, const std::string& extra = "") {
    const std::string scriptPath = dir_ + "/" + name + ".jsonl", dump = dir_ + "/" + name + ".json";
    std::ofstream(scriptPath) << script.text();
    std::string out, err;
    const int rc = runCommand(xvfb() + editorEnvironment(dir_) + KINEMA_BINARY + " edit --size " + windowSize() +
                                  " --script " + scriptPath + " --dump-state " + dump + " " + extra,
                              &out, &err);
    EXPECT_EQ(rc, 0) << err;
    return rc == 0 ? readJson(dump) : json();
  }
};

TEST_F(ViewportQualityE2e, OneSampleWhileRotatingFullQualityAndKeptOnceStill) {
  const DumpCamera camera(front_);
  const glm::dvec2 elbow = camera.pixel(jointIn(front_, "LowerArm.L"));
  Script rotating;
  rotating.select("UpperArm.L").move(elbow).key("R").path(elbow, elbow + glm::dvec2(0, -60), 6);
  const json moving = runUnshot(rotating, "rotating");
  ASSERT_TRUE(moving.is_object());
  EXPECT_EQ(moving["tool"], "rotate");  // still running on the last frame (the mouse rested for two)
  EXPECT_EQ(moving["viewport_render"]["samples"], 1);
  EXPECT_FALSE(bool(moving["viewport_render"]["from_cache"]));

  Script confirmed = rotating;
  confirmed.down().up().wait(4);
  const json still = runUnshot(confirmed, "confirmed");
  ASSERT_TRUE(still.is_object());
  EXPECT_EQ(still["tool"], "none");
  const glm::dquat before = rotationIn(front_, "UpperArm.L"), after = rotationIn(still, "UpperArm.L");
  EXPECT_LT(std::abs(glm::dot(before, after)), 0.9999) << "the rotation did not happen";
  EXPECT_EQ(still["viewport_render"]["samples"], 4);  // llvmpipe offers 4
  EXPECT_TRUE(bool(still["viewport_render"]["from_cache"]));
}

// Changed-only redraws (issue 20, model/window_redraw.h): on llvmpipe, while R rotates the
// arm, a frame draws again only a part of the window; after a whole run of changed-only
// frames (panels changing, the view moving, then still) the window holds exactly the pixels
// of a run that drew every frame whole.
TEST_F(ViewportQualityE2e, WhileRotatingOnlyTheChangedPartIsDrawnAndTheWindowEqualsWholeRedraws) {
  const DumpCamera camera(front_);
  const glm::dvec2 elbow = camera.pixel(jointIn(front_, "LowerArm.L"));
  Script rotating;
  rotating.select("UpperArm.L").move(elbow).key("R").path(elbow, elbow + glm::dvec2(0, -60), 6);
  // Stopped on the frame of the last move, while the arm turns.
  const json moving = runUnshot(rotating, "rotating_changed", "--frame-count " + std::to_string(rotating.lastFrame()));
  ASSERT_TRUE(moving.is_object());
  const long long pixelsInWindow = static_cast<long long>(e2e::windowPixels().x) * e2e::windowPixels().y;
  EXPECT_TRUE(bool(moving["window_redraw"]["changed_only"]));
  EXPECT_GE(int(moving["window_redraw"]["rectangles"]), 1);
  EXPECT_LT(moving["window_redraw"]["pixels"].get<long long>(), pixelsInWindow / 2);

  Script confirmed = rotating;
  confirmed.down().up().wait(4);
  const std::string changedShot = dir_ + "/changed.png", wholeShot = dir_ + "/whole.png";
  const json changed = runUnshot(confirmed, "confirmed_changed", "--redraw changed --screenshot " + changedShot);
  const json whole = runUnshot(confirmed, "confirmed_whole", "--redraw whole --screenshot " + wholeShot);
  ASSERT_TRUE(changed.is_object() && whole.is_object());
  EXPECT_FALSE(bool(whole["window_redraw"]["changed_only"]));
  EXPECT_EQ(whole["window_redraw"]["pixels"].get<long long>(), pixelsInWindow);
  // Kept in the window's back buffer (Mesa's GLX): the same pixels. Kept in a copy: blended
  // pixels may round one step differently in the copy's colour format.
  const bool inBackBuffer = changed["window_redraw"]["kept_in"] == "back_buffer";
  EXPECT_EQ(differingPixels(loadImageOrFail(changedShot), loadImageOrFail(wholeShot), inBackBuffer ? 0 : 1), 0);
}

}  // namespace
}  // namespace kinema::test
