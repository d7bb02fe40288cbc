// The default character's skinned body, posed by rotating named joints (elbows and a knee
// bent, arms lowered), rendered in-process on EGL and OSMesa and compared with a golden image.
// Regenerate: KINEMA_UPDATE_GOLDEN=1 build/tests/kinema_tests --gtest_filter='DefaultCharacterRender*'
// (tests/render/update_golden.sh does it), then LOOK at the image before committing.
#include <cstdlib>

#include "core/forward_kinematics.h"
#include "io/image.h"
#include "render/image_compare.h"
#include "render/headless_renderer.h"
#include "render/skeleton_view.h"
#include "scene/default_character_scene.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::differingPixels;

constexpr int kWidth = 320, kHeight = 240;

void turn(const Skeleton& skeleton, Pose& pose, const char* joint, float degrees, glm::vec3 axis) {
  const int j = skeleton.find(joint);
  ASSERT_GE(j, 0) << joint;
  pose.local[j].rotation = glm::angleAxis(glm::radians(degrees), axis) * pose.local[j].rotation;
}

// Arms lowered 50 degrees and bent 70 degrees forward at the elbows; the left thigh raised
// 40 degrees forward and its knee bent 60 degrees back; the character faces +Z.
std::vector<glm::mat4> posedWorld(const Scene& scene) {
  Pose pose = Pose::rest(scene.skeleton);
  const Skeleton& s = scene.skeleton;
  turn(s, pose, "UpperArm.L", -50.0f, glm::vec3(0, 0, 1));
  turn(s, pose, "UpperArm.R", 50.0f, glm::vec3(0, 0, 1));
  turn(s, pose, "LowerArm.L", -70.0f, glm::vec3(0, 1, 0));
  turn(s, pose, "LowerArm.R", 70.0f, glm::vec3(0, 1, 0));
  turn(s, pose, "UpperLeg.L", -40.0f, glm::vec3(1, 0, 0));
  turn(s, pose, "LowerLeg.L", 60.0f, glm::vec3(1, 0, 0));
  return computeWorld(scene.skeleton, pose);
}

// deformation: -1 as the renderer chose, 0 in the vertex shader, 1 on the CPU
// (MeshRenderer::setCpuDeformation). `ghosts`: onion-skin ghosts of the body, may be null.
Image render(HeadlessBackend backend, const Scene& scene, const std::vector<glm::mat4>& world, int deformation = -1,
             const std::vector<MeshGhost>* ghosts = nullptr) {
  Result<std::unique_ptr<HeadlessRenderer>> opened = HeadlessRenderer::open(backend, kWidth, kHeight);
  EXPECT_TRUE(opened.ok()) << (opened ? "" : opened.error());
  if (!opened) return Image();
  HeadlessRenderer& renderer = *opened.value();
  if (deformation >= 0) renderer.meshes().setCpuDeformation(deformation == 1);
  EXPECT_EQ(renderer.meshes().upload(scene), "");
  const std::vector<char> skinJoints = skinJointMask(scene);
  SkeletonDrawList list;
  SkeletonDrawJob job;
  job.parents = &scene.skeleton.parents;
  job.world = &world;
  job.shownJoints = &skinJoints;
  job.run(list);
  MeshDraw meshes;
  meshes.renderer = &renderer.meshes();
  meshes.frame.world = &world;
  FrameDescription frame;
  frame.skeleton = &list;
  frame.meshes = &meshes;
  frame.meshGhosts = ghosts;
  frame.bones = BoneDisplay::None;
  Bounds bounds = jointBounds(world);
  bounds.add(bounds.min - glm::vec3(0.15f));  // the body reaches past the joints a little
  bounds.add(bounds.max + glm::vec3(0.15f));
  frame.camera = defaultCamera(bounds, float(kWidth) / kHeight);
  frame.camera.azimuthDeg = 60.0f;  // three-quarter: both elbows and the bent knee show
  frame.sceneRadius = bounds.radius();
  return renderer.render(frame);
}

TEST(DefaultCharacterRender, PosedBodyMatchesGoldenWithEglAndOsMesa) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  const Scene scene = makeDefaultCharacterScene();
  ASSERT_FALSE(scene.meshInstances.empty());
  const std::vector<glm::mat4> world = posedWorld(scene);
  const std::string golden = std::string(KINEMA_SOURCE_DIR) + "/tests/render/golden/default_character_posed.png";
  const Image egl = render(HeadlessBackend::Egl, scene, world);
  ASSERT_EQ(egl.width, kWidth);
  if (std::getenv("KINEMA_UPDATE_GOLDEN")) {
    ASSERT_EQ(savePng(golden, egl), "");
    GTEST_SKIP() << "wrote " << golden << "; look at it before committing";
  }
  Result<Image> reference = loadPng(golden);
  ASSERT_TRUE(reference.ok()) << reference.error();
  // As the other goldens: at most 0.1% of the pixels off by more than 8 levels.
  const int diff = differingPixels(egl, reference.value(), 8);
  EXPECT_GE(diff, 0);
  EXPECT_LE(diff, kWidth * kHeight / 1000) << "egl: " << diff << " pixels differ from the golden image";
  if (!osMesaAvailable()) return;
  const Image osmesa = render(HeadlessBackend::OsMesa, scene, world);
  const int d2 = differingPixels(osmesa, reference.value(), 8);
  EXPECT_GE(d2, 0);
  EXPECT_LE(d2, kWidth * kHeight / 1000) << "osmesa: " << d2 << " pixels differ from the golden image";
}

// Software rasterisers deform the body on the CPU (SceneDeformationJob) and draw it with the
// shader's unskinned path; the picture must be the one the skinning shader draws, body and
// onion-skin ghosts alike (a wrong vertex offset or a missed instance moves whole limbs).
TEST(DefaultCharacterRender, CpuDeformedBodyAndGhostsMatchTheSkinningShader) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  const Scene scene = makeDefaultCharacterScene();
  const std::vector<glm::mat4> world = posedWorld(scene);
  const std::vector<glm::mat4> rest = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  const std::vector<MeshGhost> ghosts{{&rest, nullptr, glm::vec4(0.2f, 0.9f, 0.3f, 0.4f)}};
  for (const std::vector<MeshGhost>* g : {static_cast<const std::vector<MeshGhost>*>(nullptr), &ghosts}) {
    const Image shader = render(HeadlessBackend::Egl, scene, world, 0, g);
    const Image cpu = render(HeadlessBackend::Egl, scene, world, 1, g);
    ASSERT_EQ(shader.width, kWidth);
    ASSERT_EQ(cpu.width, kWidth);
    const int diff = differingPixels(cpu, shader, 8);
    EXPECT_GE(diff, 0);
    EXPECT_LE(diff, kWidth * kHeight / 1000) << (g ? "with a ghost: " : "") << diff << " pixels differ";
    // The body is there at all: the picture is not the empty background (the body covers
    // about 3 % of this picture, 2,500 pixels).
    const Image empty = render(HeadlessBackend::Egl, Scene(), world, 1);
    EXPECT_GT(differingPixels(cpu, empty, 8), kWidth * kHeight / 50);
  }
  // And the ghost changed the picture (so the comparison above covered drawGhosts).
  EXPECT_GT(differingPixels(render(HeadlessBackend::Egl, scene, world, 1, &ghosts), render(HeadlessBackend::Egl, scene, world, 1),
                            8),
            kWidth * kHeight / 100);
}

TEST(DefaultCharacterRender, SoftwareRasterisersDeformOnTheCpu) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  Result<std::unique_ptr<HeadlessRenderer>> opened = HeadlessRenderer::open(HeadlessBackend::Egl, 8, 8);
  ASSERT_TRUE(opened.ok()) << (opened ? "" : opened.error());
  const std::string name = queryRenderSizeLimit().renderer;
  const bool software = name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
  EXPECT_EQ(opened.value()->meshes().cpuDeformation(), software) << name;
}

}  // namespace
}  // namespace kinema
