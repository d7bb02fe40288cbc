// End-to-end test of the 3D view's quality switch (issue 20, model/viewport_quality.h):
// the real `kinema edit` under xvfb-run, with no --screenshot (a screenshot is always the
// still picture). While R rotates the arm the view is drawn with one sample per pixel, even
// on the frames where the mouse rests; once the rotation is confirmed the same view is
// drawn multisampled, then shown again from its kept copy while nothing changes.
#include <cmath>

#include "editor/e2e_harness.h"

namespace kinema::test {
namespace {

using namespace e2e;

class ViewportQualityE2e : public FrontViewSuite<ViewportQualityE2e> {
 public:
  static constexpr const char* kShotFolder = "viewport_quality_e2e";

 protected:
  // runEditor without --screenshot: the dump then tells how the last frame was drawn.
  json runUnshot(const Script& script, const std::string& name) {
    const std::string scriptPath = dir_ + "/" + name + ".jsonl", dump = dir_ + "/" + name + ".json";
    std::ofstream(scriptPath) << script.text();
    std::string out, err;
    const int rc = runCommand(xvfb() + editorEnvironment(dir_) + KINEMA_BINARY + " edit --size " + windowSize() +
                                  " --script " + scriptPath + " --dump-state " + dump,
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

}  // namespace
}  // namespace kinema::test
