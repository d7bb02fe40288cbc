// SceneDamageJob (issue 20's changed-only redraws): which pixels of the 3D view a new frame
// changes. Expected rectangles come from projecting the moved shapes' corners with glm's own
// glm::project, independently of the job's arithmetic; the pixel-exact check of drawing only
// that rectangle is tests/render/partial_redraw_test.cpp.
#include <gtest/gtest.h>

#include "render/mesh_renderer.h"
#include "render/scene_damage.h"
#include "render/skeleton_renderer.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kX = 40, kY = 20, kW = 400, kH = 300;  // the view inside a larger framebuffer
const PixelRect kWholeView{kX, kY, kX + kW, kY + kH};

FrameDescription frameOf(const SkeletonDrawList* bones, const OverlayDrawList* overlay) {
  FrameDescription f;
  f.skeleton = bones;
  f.overlay = overlay;
  f.camera.azimuthDeg = 0.0f;
  f.camera.elevationDeg = 0.0f;
  f.camera.target = glm::vec3(0.0f);
  f.camera.distance = 10.0f;
  f.camera.fitClipPlanes(5.0f);
  f.x = kX, f.y = kY, f.width = kW, f.height = kH;
  return f;
}

// Two bones, one on each side of the origin; the right one's tail at `tail`.
SkeletonDrawList twoBones(const glm::vec3& tail) {
  SkeletonDrawList l;
  l.boneMatrices = {boneMatrix(glm::vec3(-3, 0, 0), glm::vec3(-3, 1, 0), glm::vec3(1, 0, 0)),
                    boneMatrix(glm::vec3(3, 0, 0), tail, glm::vec3(1, 0, 0))};
  l.boneColors = {glm::vec4(1), glm::vec4(1)};
  return l;
}

// Framebuffer pixel of a world point, by glm::project.
glm::vec2 pixelOf(const FrameDescription& f, const glm::vec3& p) {
  const glm::vec3 w = glm::project(p, f.camera.view(), f.camera.projection(float(kW) / kH), glm::vec4(kX, kY, kW, kH));
  return glm::vec2(w);
}

// The job over one frame description, frame after frame.
struct Damage {
  SceneSnapshot last;
  SceneDamageJob job;
  explicit Damage(const FrameDescription& f) {
    job.frame = &f;
    job.last = &last;
  }
  PixelRect next() {
    EXPECT_TRUE(job.run());
    return job.out;
  }
};

bool holds(const PixelRect& r, const glm::vec2& p) { return p.x >= r.x0 && p.x <= r.x1 && p.y >= r.y0 && p.y <= r.y1; }

TEST(SceneDamage, TheFirstFrameAndAChangedCameraDamageTheWholeViewAndTheSameFrameNothing) {
  const SkeletonDrawList bones = twoBones(glm::vec3(3, 1, 0));
  FrameDescription f = frameOf(&bones, nullptr);
  Damage damage(f);
  EXPECT_EQ(damage.next(), kWholeView);
  EXPECT_TRUE(damage.next().empty());
  f.camera.azimuthDeg = 1.0f;
  EXPECT_EQ(damage.next(), kWholeView);
  f.showGrid = false;  // a switch
  EXPECT_EQ(damage.next(), kWholeView);
}

TEST(SceneDamage, AMovedBoneDamagesItsOldAndNewPlaceAndNotTheOtherBone) {
  SkeletonDrawList bones = twoBones(glm::vec3(3, 1, 0));
  FrameDescription f = frameOf(&bones, nullptr);
  Damage damage(f);
  damage.next();
  bones = twoBones(glm::vec3(3.8f, 0.6f, 0));  // the right bone turns down to the right
  PixelRect out = damage.next();
  ASSERT_FALSE(out.empty());
  for (const glm::vec3& p : {glm::vec3(3, 0, 0), glm::vec3(3, 1, 0), glm::vec3(3.8f, 0.6f, 0)})
    EXPECT_TRUE(holds(out, pixelOf(f, p))) << p.x << " " << p.y;
  // The waist of the old bone: 0.1 of its length out from its axis at a tenth of the way up.
  EXPECT_TRUE(holds(out, pixelOf(f, glm::vec3(2.9f, 0.1f, 0))));
  for (const glm::vec3& p : {glm::vec3(-3, 0, 0), glm::vec3(-3, 1, 0), glm::vec3(0, 0.5f, 0)})
    EXPECT_FALSE(holds(out, pixelOf(f, p))) << p.x << " " << p.y;
  // A colour change alone (selecting the bone) damages it too.
  bones.boneColors[0] = glm::vec4(1, 0.6f, 0.2f, 1);
  out = damage.next();
  EXPECT_TRUE(holds(out, pixelOf(f, glm::vec3(-3, 0.5f, 0))));
  EXPECT_FALSE(holds(out, pixelOf(f, glm::vec3(3.4f, 0.8f, 0))));
}

TEST(SceneDamage, AMovedHandleDamagesItsRadiusInPixelsAroundBothCentres) {
  const SkeletonDrawList bones = twoBones(glm::vec3(3, 1, 0));
  OverlayDrawList overlay;
  overlay.addHandle(glm::vec3(0, 0, 0), 8.0f, glm::vec4(1), OverlayDrawList::HandleShape::Disc);
  FrameDescription f = frameOf(&bones, &overlay);
  Damage damage(f);
  damage.next();
  overlay.handles[0].center = glm::vec3(1, 1, 0);
  PixelRect out = damage.next();
  const glm::vec2 a = pixelOf(f, glm::vec3(0)), b = pixelOf(f, glm::vec3(1, 1, 0));
  EXPECT_TRUE(holds(out, a - glm::vec2(8)));
  EXPECT_TRUE(holds(out, b + glm::vec2(8)));
  EXPECT_FALSE(holds(out, a - glm::vec2(30)));
  EXPECT_FALSE(holds(out, pixelOf(f, glm::vec3(-3, 0.5f, 0))));
  // A screen rectangle (box select) in pixels from the view's top left corner.
  overlay.addScreenRectangle(glm::vec2(10, 10), glm::vec2(50, 40), glm::vec4(1, 1, 1, 0.1f), glm::vec4(1));
  out = damage.next();
  EXPECT_TRUE(holds(out, glm::vec2(kX + 10, kY + kH - 10)));
  EXPECT_TRUE(holds(out, glm::vec2(kX + 50, kY + kH - 40)));
}

TEST(SceneDamage, AMovedGhostDamagesItsPlaceAndAnotherNumberOfGhostsTheWholeView) {
  const SkeletonDrawList bones = twoBones(glm::vec3(3, 1, 0));
  std::vector<SkeletonDrawList> ghosts{twoBones(glm::vec3(3, 1, 0))};
  FrameDescription f = frameOf(&bones, nullptr);
  f.ghosts = &ghosts;
  Damage damage(f);
  damage.next();
  ghosts[0] = twoBones(glm::vec3(3.8f, 0.6f, 0));  // the ghost of the right bone turns
  const PixelRect out = damage.next();
  EXPECT_TRUE(holds(out, pixelOf(f, glm::vec3(3.8f, 0.6f, 0))));
  EXPECT_FALSE(holds(out, pixelOf(f, glm::vec3(-3, 0.5f, 0))));
  ghosts.push_back(ghosts[0]);
  EXPECT_EQ(damage.next(), kWholeView);
}

TEST(SceneDamage, APointBehindTheCameraOrADifferentCountRedrawsEverything) {
  SkeletonDrawList bones = twoBones(glm::vec3(3, 1, 0));
  FrameDescription f = frameOf(&bones, nullptr);
  Damage damage(f);
  damage.next();
  const PixelRect& whole = kWholeView;
  bones = twoBones(glm::vec3(3, 1, 20));  // the tail reaches past the camera (at z = 10)
  EXPECT_EQ(damage.next(), whole);
  bones.boneMatrices.pop_back();
  bones.boneColors.pop_back();
  EXPECT_EQ(damage.next(), whole);
  SceneDamageJob missing;
  EXPECT_FALSE(missing.run());
}

TEST(SceneDamage, MeshesNotPosedOnTheCpuRedrawTheWholeViewWhenTheirJointsMoveAndNothingElse) {
  const SkeletonDrawList bones = twoBones(glm::vec3(3, 1, 0));
  FrameDescription f = frameOf(&bones, nullptr);
  MeshRenderer renderer;  // never initialised: the job only reads what the frame says
  std::vector<glm::mat4> world{glm::mat4(1.0f)};
  MeshDraw meshes;
  meshes.renderer = &renderer;
  meshes.frame.world = &world;
  f.meshes = &meshes;
  Damage damage(f);
  const PixelRect& whole = kWholeView;
  EXPECT_EQ(damage.next(), whole);
  EXPECT_TRUE(damage.next().empty()) << "an idle frame (the weights view, a GPU) draws nothing";
  world[0] = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0, 0));
  EXPECT_EQ(damage.next(), whole) << "the vertices are not known here: the whole view";
}

TEST(PixelRect, MergedDamageIsDisjointCoversEveryInputAndHasAtMostTheCount) {
  const std::vector<PixelRect> in{{0, 0, 10, 10}, {5, 5, 20, 20},    {100, 100, 110, 110}, {200, 0, 210, 5},
                                  {0, 0, 0, 9},   {300, 300, 301, 301}, {19, 19, 25, 25}};
  for (int most : {1, 2, 3, 8}) {
    const std::vector<PixelRect> out = mergeDamage(in, most);
    EXPECT_LE(static_cast<int>(out.size()), most);
    for (size_t i = 0; i < out.size(); ++i)
      for (size_t j = i + 1; j < out.size(); ++j) EXPECT_FALSE(out[i].intersects(out[j]));
    for (const PixelRect& r : in) {
      if (r.empty()) continue;
      // Every pixel of r lies in one of the merged rectangles (they are disjoint, so count).
      long long covered = 0;
      for (const PixelRect& m : out) covered += r.intersected(m).area();
      EXPECT_EQ(covered, r.area());
    }
  }
  // The overlapping pair and the one touching it become one; the far ones stay apart.
  EXPECT_EQ(mergeDamage(in, 8).size(), 4u);
  EXPECT_EQ(PixelRect::covering(1.5, 2.0, 3.2, 2.0, PixelRect{}), (PixelRect{1, 2, 4, 3}));
}

}  // namespace
}  // namespace kinema
