// End-to-end tests of the one selection (issue 17): the real `kinema edit` under xvfb-run,
// driven by --script, checked in --dump-state (the active joint, and the joint the
// properties panel showed: properties_joint) and in the screenshot's pixels (the selection
// drawn with the bones hidden). Joint pixels come from the harness's own camera.
#include <cmath>

#include "editor/e2e_harness.h"
#include "io/image.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

std::vector<std::string> selection(const json& d) {
  std::vector<std::string> names;
  for (const json& n : d["selection"]) names.push_back(n);
  return names;
}

// The selected bones' colour (SkeletonStyle::selectedBone, 1.0 0.62 0.20) lit by the bone
// shader: red well above blue, green between them. Skin, the grey background and the
// grey bones are not.
bool orange(const Image& shot, glm::dvec2 p) {
  const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
  if (x < 0 || y < 0 || x >= shot.width || y >= shot.height) return false;
  const unsigned char* c = &shot.rgba[(size_t(y) * shot.width + x) * 4];
  return c[0] > 150 && c[0] > c[2] + 90 && c[1] > c[2] + 20 && c[1] < c[0] - 30;
}

// Orange pixels within `radius` of p (a bone a few pixels wide, rounding of the projection).
int orangeAround(const Image& shot, glm::dvec2 p, int radius = 3) {
  int n = 0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) n += orange(shot, p + glm::dvec2(dx, dy));
  return n;
}

class SelectionE2e : public FrontViewSuite<SelectionE2e> {
 public:
  static constexpr const char* kShotFolder = "selection_e2e";

 protected:
  glm::dvec2 pixelOf(const std::string& name) const { return DumpCamera(front_).pixel(jointIn(front_, name)); }
  // A point on the bone from `head` to `tail`, a fraction `f` of the way.
  glm::dvec2 onBone(const std::string& head, const std::string& tail, double f = 0.5) const {
    return DumpCamera(front_).pixel(glm::mix(jointIn(front_, head), jointIn(front_, tail), f));
  }
  glm::dvec2 viewportCentre() const {
    const json& v = front_["viewport"];
    return {double(v["x"]) + double(v["width"]) / 2, double(v["y"]) + double(v["height"]) / 2};
  }
  Image shot(const std::string& name) {
    Result<Image> image = loadPng(shotDir() + "/" + name + ".png");
    EXPECT_TRUE(image.ok()) << (image ? "" : image.error());
    return image ? image.value() : Image();
  }
};

// Regression: after a box select no joint was active, so the status bar and the
// properties panel said "nothing selected" (the old dump had "active": null) while R
// rotated the three joints. Now the box's joint nearest the root is active and shown.
TEST_F(SelectionE2e, BoxSelectMakesAnActiveJointThePropertiesPanelShows) {
  const glm::dvec2 a = pixelOf("LowerArm.L") + glm::dvec2(-15, -25), b = pixelOf("Fingertip.L") + glm::dvec2(15, 25);
  const json d = run(Script().move(a).down().path(a, b).up().wait(2), "box_select");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(selection(d), (std::vector<std::string>{"LowerArm.L", "Hand.L", "Fingertip.L"}));
  EXPECT_EQ(d["active"], "LowerArm.L");
  EXPECT_EQ(d["properties_joint"], "LowerArm.L");
}

// B (issue 39, item 10; Blender's box select): the next drag is a box even when it starts
// over a bone. Before, B did nothing and the press picked the bone under it.
TEST_F(SelectionE2e, BStartsABoxFromOverABone) {
  const glm::dvec2 a = onBone("UpperArm.L", "LowerArm.L"), b = pixelOf("Fingertip.L") + glm::dvec2(15, 25);
  const json d = run(Script().move(a).wait(1).key("B").wait(2).down().path(a, b).up().wait(2), "b_box_select");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(selection(d), (std::vector<std::string>{"LowerArm.L", "Hand.L", "Fingertip.L"}));
  // Esc disarms it: the same press then picks the bone under it.
  const json esc = run(Script().move(a).wait(1).key("B").wait(1).key("ESCAPE").wait(2).down().up().wait(2), "b_escape");
  ASSERT_TRUE(esc.is_object());
  EXPECT_EQ(selection(esc), (std::vector<std::string>{"UpperArm.L"}));
}

// Regression: A (select all) with nothing active left none active; now the root is.
TEST_F(SelectionE2e, SelectAllMakesTheRootActive) {
  const json d = run(Script().move(viewportCentre()).key("A").wait(2), "select_all");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(selection(d).size(), d["joints"].size());
  EXPECT_EQ(d["active"], d["joints"][0]["name"]);
  EXPECT_EQ(d["properties_joint"], d["joints"][0]["name"]);
}

// Regression: with the bones hidden (Alt+Z twice: on -> x-ray -> none) nothing in the 3D
// view marked the selection; now the selected bone is drawn alone, x-ray, in the selection
// colour, over the body. Its mirror image, not selected, stays hidden under the skin.
TEST_F(SelectionE2e, WithTheBonesHiddenTheSelectedBoneIsStillDrawn) {
  Script s;
  s.click(onBone("LowerArm.L", "Hand.L")).wait(2);
  s.keyDown("LEFT_ALT").key("Z").keyUp("LEFT_ALT").wait(2).keyDown("LEFT_ALT").key("Z").keyUp("LEFT_ALT").wait(3);
  const json d = run(s, "hidden_bones_selection");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["bones"], "none");
  ASSERT_EQ(selection(d), std::vector<std::string>{"LowerArm.L"});
  const Image image = shot("hidden_bones_selection");
  ASSERT_GT(image.width, 0);
  int selectedPixels = 0, mirrorPixels = 0;
  for (double f : {0.3, 0.5, 0.7}) {
    selectedPixels += orangeAround(image, onBone("LowerArm.L", "Hand.L", f)) > 0;
    mirrorPixels += orangeAround(image, onBone("LowerArm.R", "Hand.R", f)) > 0;
  }
  EXPECT_EQ(selectedPixels, 3) << "the selected forearm is drawn at 30, 50 and 70% of its length";
  EXPECT_EQ(mirrorPixels, 0) << "the unselected forearm stays hidden";
}

}  // namespace
}  // namespace kinema::test
