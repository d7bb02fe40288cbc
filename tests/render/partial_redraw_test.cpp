// Changed-only redraws (issue 20): the editor keeps its window (in its back buffer, or in a
// one-sample ViewportTarget) and, on a software rasteriser, draws only the rectangle SceneDamageJob finds, with
// FrameDescription::limit, over the previous picture. That must give exactly the pixels of
// drawing the new frame whole, frame after frame, for the skinned body, bones and overlay.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include <glad/gl.h>

#include "core/forward_kinematics.h"
#include "io/image.h"
#include "render/headless_renderer.h"
#include "render/image_compare.h"
#include "render/scene_damage.h"
#include "render/skeleton_view.h"
#include "render/viewport_target.h"
#include "scene/default_character_scene.h"
#include "evaluation/scene_deformation.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kWidth = 240, kHeight = 180;

Image readCanvas() {
  Image img(kWidth, kHeight);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  return img;
}

// One frame of the default character with its forearm bent `elbow` degrees, an onion-skin
// ghost of its skeleton 20 degrees behind and a handle on the hand, everything the frame
// points at kept alive here.
struct Frame {
  std::vector<glm::mat4> world;
  std::vector<DeformedPrimitive> posed;
  SkeletonDrawList bones;
  std::vector<SkeletonDrawList> ghosts;
  OverlayDrawList overlay;
  MeshDraw meshes;
  FrameDescription description;
  Frame(const Scene& scene, MeshRenderer& renderer, float elbow) {
    const int forearm = scene.skeleton.find("LowerArm.L"), hand = scene.skeleton.find("Hand.L");
    EXPECT_GE(forearm, 0);
    EXPECT_GE(hand, 0);
    auto bent = [&](float degrees) {
      Pose pose = Pose::rest(scene.skeleton);
      pose.local[forearm].rotation = glm::angleAxis(glm::radians(degrees), glm::vec3(0, 1, 0)) * pose.local[forearm].rotation;
      return computeWorld(scene.skeleton, pose);
    };
    world = bent(elbow);
    const std::vector<glm::mat4> ghostWorld = bent(elbow - 20.0f);
    SkeletonDrawJob ghostJob;
    ghostJob.parents = &scene.skeleton.parents;
    ghostJob.world = &ghostWorld;
    ghostJob.style.bone = ghostJob.style.joint = glm::vec4(0.3f, 0.6f, 1.0f, 0.4f);
    ghosts.emplace_back();
    EXPECT_TRUE(ghostJob.run(ghosts.back()));
    SceneDeformationJob deform;
    deform.scene = &scene;
    deform.world = &world;
    deform.out = &posed;
    EXPECT_TRUE(deform.run());
    SkeletonDrawJob job;
    job.parents = &scene.skeleton.parents;
    job.world = &world;
    EXPECT_TRUE(job.run(bones));
    overlay.addHandle(glm::vec3(world[hand][3]), 7.0f, glm::vec4(1, 0.5f, 0, 1), OverlayDrawList::HandleShape::Disc);
    meshes.renderer = &renderer;
    meshes.frame.world = &world;
    meshes.frame.posed = &posed;
    description.skeleton = &bones;
    description.ghosts = &ghosts;
    description.overlay = &overlay;
    description.meshes = &meshes;
    description.bones = BoneDisplay::XRay;
    Bounds bounds = jointBounds(computeWorld(scene.skeleton, Pose::rest(scene.skeleton)));  // the same camera each frame
    bounds.add(bounds.min - glm::vec3(0.15f));
    bounds.add(bounds.max + glm::vec3(0.15f));
    description.camera = defaultCamera(bounds, float(kWidth) / kHeight);
    description.sceneRadius = bounds.radius();
    description.width = kWidth;
    description.height = kHeight;
    description.clear = false;  // the caller clears, as the editor's window does
  }
};

void clearTo(const FrameDescription& f, const PixelRect& r) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(r.x0, r.y0, r.width(), r.height());
  glClearColor(f.background.r, f.background.g, f.background.b, f.background.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

// The default character uploaded for drawing from CPU-posed vertices (as on llvmpipe, where
// the editor redraws changed parts) and a renderer, in a headless context of kWidth x kHeight.
class DefaultCharacterCanvas : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
    Result<std::unique_ptr<HeadlessRenderer>> opened = HeadlessRenderer::open(HeadlessBackend::Egl, kWidth, kHeight);
    ASSERT_TRUE(opened.ok()) << (opened ? "" : opened.error());
    headless_ = std::move(opened.value());
    headless_->meshes().setCpuDeformation(true);
    ASSERT_EQ(headless_->meshes().upload(scene), "");
    ASSERT_EQ(renderer.init(), "");
  }
  const Scene scene = makeDefaultCharacterScene();
  std::unique_ptr<HeadlessRenderer> headless_;  // before the renderer: its context outlives the renderer's GL objects
  SkeletonRenderer renderer;
};
class PartialRedraw : public DefaultCharacterCanvas {};
class FrontFacesOnly : public DefaultCharacterCanvas {};

TEST_F(PartialRedraw, DrawingOnlyTheDamagedRectangleGivesTheWholeFramesPixels) {
  const PixelRect view{0, 0, kWidth, kHeight};
  // Held still (every face drawn) and moving (closed shapes' front faces alone).
  for (const bool frontFacesOnly : {false, true}) {
    ViewportTarget partial, whole;  // one sample each, as the editor's canvas
    SceneSnapshot snapshot;
    // The elbow bends, holds, bends again: each frame drawn both ways.
    const float elbows[] = {0.0f, 25.0f, 25.0f, 70.0f, 72.0f};
    for (size_t step = 0; step < std::size(elbows); ++step) {
      SCOPED_TRACE("frame " + std::to_string(step) + ", elbow " + std::to_string(elbows[step]) +
                   (frontFacesOnly ? ", front faces only" : ""));
      Frame frame(scene, headless_->meshes(), elbows[step]);
      frame.description.frontFacesOnly = frontFacesOnly;
      SceneDamageJob job;
      job.frame = &frame.description;
      job.scene = &scene;
      job.last = &snapshot;
      ASSERT_TRUE(job.run());
      EXPECT_EQ(partial.holds(kWidth, kHeight), step > 0);
      ASSERT_EQ(partial.begin(kWidth, kHeight, 1), "");
      if (step == 0) {
        EXPECT_EQ(job.out, view) << "nothing kept: the whole view";
      }
      if (step == 2) {
        EXPECT_TRUE(job.out.empty()) << "the same frame again changes nothing";
      }
      if (step == 1 || step == 3 || step == 4) {
        EXPECT_FALSE(job.out.empty());
        EXPECT_LT(job.out.area(), view.area() / 2) << "a forearm's move is a small part of the view";
      }
      if (!job.out.empty()) {
        clearTo(frame.description, job.out);
        frame.description.limit = job.out;
        renderer.draw(frame.description);
      }
      const Image changedOnly = readCanvas();
      partial.resolve();  // kept for the next frame
      ASSERT_EQ(whole.begin(kWidth, kHeight, 1), "");
      clearTo(frame.description, view);
      frame.description.limit = PixelRect{};
      renderer.draw(frame.description);
      const Image drawnWhole = readCanvas();
      EXPECT_EQ(test::differingPixels(changedOnly, drawnWhole, 0), 0);
    }
  }
}

// The same with the body deformed on the CPU (a deformer stack's output, MeshFrame::deformed,
// drawn through the shader path): the head's vertices pushed sideways a little more each
// frame, as a lattice point dragged there would.
TEST_F(PartialRedraw, ADeformedBodyRedrawnInPartGivesTheWholeFramesPixels) {
  ViewportTarget partial, whole;
  SceneSnapshot snapshot;
  const PixelRect view{0, 0, kWidth, kHeight};
  for (int step = 0; step < 4; ++step) {
    SCOPED_TRACE("frame " + std::to_string(step));
    Frame frame(scene, headless_->meshes(), 0.0f);
    frame.description.bones = BoneDisplay::None;
    std::vector<DeformedPrimitive> deformed = frame.posed;
    for (DeformedPrimitive& d : deformed)
      for (glm::vec3& p : d.positions)
        if (p.y > 1.45f) p.x += 0.01f * static_cast<float>(step);
    frame.meshes.frame.posed = nullptr;
    frame.meshes.frame.deformed = &deformed;
    SceneDamageJob job;
    job.frame = &frame.description;
    job.scene = &scene;
    job.last = &snapshot;
    ASSERT_TRUE(job.run());
    if (step > 0) {
      EXPECT_FALSE(job.out.empty());
      EXPECT_LT(job.out.area(), view.area() / 4) << "the head's move is a small part of the view";
    }
    ASSERT_EQ(partial.begin(kWidth, kHeight, 1), "");
    if (!job.out.empty()) {
      clearTo(frame.description, job.out);
      frame.description.limit = job.out;
      renderer.draw(frame.description);
    }
    const Image changedOnly = readCanvas();
    partial.resolve();
    ASSERT_EQ(whole.begin(kWidth, kHeight, 1), "");
    clearTo(frame.description, view);
    frame.description.limit = PixelRect{};
    renderer.draw(frame.description);
    EXPECT_EQ(test::differingPixels(changedOnly, readCanvas(), 0), 0);
  }
}

// FrameDescription::frontFacesOnly (while the view moves): the closed body, bones and joint
// spheres without their back faces look the same from outside. Only a pixel on a silhouette
// may differ (where the pixel's centre fell on the back face side of the outline edge), so
// every differing pixel must have a 4-neighbour that differs strongly from it in the picture
// drawn with every face (an edge); and there are few of them.
Image drawnOnce(SkeletonRenderer& renderer, Frame& frame, const PixelRect& view) {
  clearTo(frame.description, view);
  renderer.draw(frame.description);
  return readCanvas();
}

bool onAnEdge(const Image& img, int x, int y) {
  const uint8_t* c = img.pixel(x, y);
  const int near[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& d : near) {
    const int nx = x + d[0], ny = y + d[1];
    if (nx < 0 || ny < 0 || nx >= img.width || ny >= img.height) continue;
    const uint8_t* n = img.pixel(nx, ny);
    if (std::abs(int(c[0]) - n[0]) + std::abs(int(c[1]) - n[1]) + std::abs(int(c[2]) - n[2]) > 24) return true;
  }
  return false;
}

TEST_F(FrontFacesOnly, TheClosedBodyAndBonesDifferOnlyOnSilhouettes) {
  ViewportTarget target;
  ASSERT_EQ(target.begin(kWidth, kHeight, 1), "");
  const PixelRect view{0, 0, kWidth, kHeight};
  for (const BoneDisplay bones : {BoneDisplay::On, BoneDisplay::XRay}) {
    Frame frame(scene, headless_->meshes(), 40.0f);
    frame.description.bones = bones;
    frame.description.ghosts = nullptr;
    const Image every = drawnOnce(renderer, frame, view);
    frame.description.frontFacesOnly = true;
    const Image front = drawnOnce(renderer, frame, view);
    int differing = 0, offEdge = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (std::memcmp(every.pixel(x, y), front.pixel(x, y), 3) != 0) {
          ++differing;
          offEdge += !onAnEdge(every, x, y);
        }
    EXPECT_EQ(offEdge, 0) << "pixels away from any outline differ: back faces were seen, or front faces left out";
    EXPECT_LT(differing, kWidth * kHeight / 200) << "more than silhouette ties";
  }
}

// With the camera inside the body (the near plane cuts it) its inside is what shows: back
// faces, which must then stay. The picture is the same to the pixel with the switch on.
TEST_F(FrontFacesOnly, ANearPlaneCuttingTheBodyKeepsItsBackFaces) {
  ViewportTarget target;
  ASSERT_EQ(target.begin(kWidth, kHeight, 1), "");
  const PixelRect view{0, 0, kWidth, kHeight};
  Frame frame(scene, headless_->meshes(), 0.0f);
  frame.description.bones = BoneDisplay::None;
  frame.description.ghosts = nullptr;
  const int chest = scene.skeleton.find("Chest");
  ASSERT_GE(chest, 0);
  frame.description.camera.target = glm::vec3(frame.world[chest][3]);
  frame.description.camera.distance = 0.02f;  // the eye inside the chest
  frame.description.camera.nearPlane = 0.005f;
  frame.description.camera.farPlane = 10.0f;
  const Image every = drawnOnce(renderer, frame, view);
  frame.description.frontFacesOnly = true;
  const Image front = drawnOnce(renderer, frame, view);
  EXPECT_EQ(test::differingPixels(every, front, 0), 0);
  // The view does show the body's inside (not the background alone).
  int body = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) body += every.pixel(x, y)[0] > 100;
  EXPECT_GT(body, kWidth * kHeight / 2);
}

}  // namespace
}  // namespace kinema
