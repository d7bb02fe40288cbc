// Onion-skin ghosts in the renderer (FrameDescription::ghosts and ::meshGhosts): blended
// by their alpha over what is behind them, and hidden behind the opaque skeleton or body in
// front of them; a body ghost blends once per pixel however many of its surfaces overlap.
#include <gtest/gtest.h>

#include "scene/scene.h"
#include "render/headless_renderer.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kSize = 160;
const glm::vec4 kBackground(0.2f, 0.2f, 0.2f, 1.0f);

// One bone from (0, 0, z) to (0, 1, z) in `color` (joints too).
SkeletonDrawList bone(float z, const glm::vec4& color) {
  static const std::vector<int> parents{-1, 0};
  const std::vector<glm::mat4> world{glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, z)),
                                     glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, z))};
  SkeletonDrawJob job;
  job.parents = &parents;
  job.world = &world;
  job.style.bone = job.style.joint = color;
  SkeletonDrawList list;
  EXPECT_TRUE(job.run(list));
  return list;
}

glm::ivec3 centre(const Image& img) {
  const std::uint8_t* p = img.pixel(kSize / 2, kSize / 2);
  return {p[0], p[1], p[2]};
}

Image draw(const SkeletonDrawList* skeleton, const std::vector<SkeletonDrawList>* ghosts) {
  auto opened = HeadlessRenderer::open(HeadlessBackend::Egl, kSize, kSize);
  EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error());
  if (!opened.ok()) return Image();
  FrameDescription frame;
  frame.skeleton = skeleton;
  frame.ghosts = ghosts;
  frame.showGrid = false;
  frame.background = kBackground;
  frame.camera.azimuthDeg = 0.0f;  // looking along -Z at the bone's middle
  frame.camera.elevationDeg = 0.0f;
  frame.camera.target = glm::vec3(0, 0.5f, 0);
  frame.camera.distance = 4.0f;
  frame.camera.fitClipPlanes(2.0f);
  return opened.value()->render(frame);
}

TEST(GhostRender, AGhostIsBlendedByItsAlphaOverTheBackground) {
  // Pure blue at alpha 0.5: red and green are half the background's whatever the lighting,
  // blue is above it.
  const std::vector<SkeletonDrawList> ghosts{bone(0.0f, glm::vec4(0, 0, 1, 0.5f))};
  const Image img = draw(nullptr, &ghosts);
  ASSERT_EQ(img.width, kSize);
  const glm::ivec3 c = centre(img);
  const int half = int(0.5f * 0.2f * 255.0f + 0.5f);  // 26
  EXPECT_NEAR(c.r, half, 2);
  EXPECT_NEAR(c.g, half, 2);
  EXPECT_GT(c.b, 51 + 10);
  // Without ghosts the same pixel is the background.
  const glm::ivec3 none = centre(draw(nullptr, nullptr));
  EXPECT_NEAR(none.r, 51, 1);
  EXPECT_NEAR(none.b, 51, 1);
}

TEST(GhostRender, TheOpaqueSkeletonInFrontHidesAGhost) {
  const SkeletonDrawList front = bone(0.5f, glm::vec4(1, 0, 0, 1));  // nearer the camera (+Z)
  const std::vector<SkeletonDrawList> behind{bone(-0.5f, glm::vec4(0, 0, 1, 0.5f))};
  const glm::ivec3 c = centre(draw(&front, &behind));
  EXPECT_GT(c.r, 60);
  EXPECT_EQ(c.g, 0);
  EXPECT_EQ(c.b, 0) << "no blue from the ghost behind the bone";
  // The ghost in front of the bone tints it: red halved, blue added.
  const std::vector<SkeletonDrawList> ahead{bone(1.0f, glm::vec4(0, 0, 1, 0.5f))};
  const glm::ivec3 d = centre(draw(&front, &ahead));
  EXPECT_GT(d.b, 10);
  EXPECT_LT(d.r, c.r);
}

// A scene of one joint carrying a rigid cube of side 0.5 centred on it (24 vertices: each
// face its own normals), grey.
Scene cubeScene() {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform{});
  MeshPrimitive p;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a)
    for (float sign : {-1.0f, 1.0f}) {
      const glm::vec3 n = sign * axes[a], u = axes[(a + 1) % 3], v = axes[(a + 2) % 3];
      const uint32_t first = static_cast<uint32_t>(p.positions.size());
      for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        p.positions.push_back(0.25f * (n + c.x * u + c.y * v));
        p.normals.push_back(n);
      }
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) p.indices.push_back(first + i);
    }
  Mesh mesh;
  mesh.primitives.push_back(p);
  scene.meshes.push_back(mesh);
  MeshInstance instance;
  instance.joint = 0;
  instance.mesh = 0;
  scene.meshInstances.push_back(instance);
  return scene;
}

std::vector<glm::mat4> at(glm::vec3 p) { return {glm::translate(glm::mat4(1.0f), p)}; }

// The cube scene with its body at `body` and body ghosts at the given places and colours.
glm::ivec3 drawBodies(glm::vec3 body, const std::vector<std::pair<glm::vec3, glm::vec4>>& ghosts) {
  auto opened = HeadlessRenderer::open(HeadlessBackend::Egl, kSize, kSize);
  EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error());
  if (!opened.ok()) return glm::ivec3(-1);
  const Scene scene = cubeScene();
  HeadlessRenderer& r = *opened.value();
  EXPECT_EQ(r.meshes().upload(scene), "");
  const std::vector<glm::mat4> world = at(body);
  std::vector<std::vector<glm::mat4>> poses;
  for (const auto& g : ghosts) poses.push_back(at(g.first));
  std::vector<MeshGhost> list;
  for (size_t i = 0; i < ghosts.size(); ++i) list.push_back({&poses[i], nullptr, ghosts[i].second});
  MeshDraw meshes;
  meshes.renderer = &r.meshes();
  meshes.frame.world = &world;
  FrameDescription frame;
  frame.meshes = &meshes;
  frame.meshGhosts = &list;
  frame.showGrid = false;
  frame.background = kBackground;
  frame.camera.azimuthDeg = 0.0f;
  frame.camera.elevationDeg = 0.0f;
  frame.camera.target = glm::vec3(0, 0.5f, 0);
  frame.camera.distance = 4.0f;
  frame.camera.fitClipPlanes(2.0f);
  return centre(r.render(frame));
}

TEST(GhostRender, ABodyGhostBlendsOncePerPixelOverTheBackground) {
  // Pure blue, opacity 0.5, seen face-on (no rim): alpha 0.85 * 0.5 (mesh.frag). The cube's
  // front and back faces overlap at the centre; blended once, red is the background's times
  // (1 - 0.425) (twice would leave 0.33 of it).
  const glm::vec3 away(5.0f, 0.5f, 0.0f);  // the body itself is out of the view
  const glm::ivec3 c = drawBodies(away, {{glm::vec3(0, 0.5f, 0), glm::vec4(0, 0, 1, 0.5f)}});
  const int once = int(0.575f * 0.2f * 255.0f + 0.5f);  // 29
  EXPECT_NEAR(c.r, once, 2);
  EXPECT_NEAR(c.g, once, 2);
  EXPECT_GT(c.b, 51 + 20);
  const glm::ivec3 none = drawBodies(away, {});
  EXPECT_NEAR(none.r, 51, 1);
}

TEST(GhostRender, TheBodyInFrontHidesABodyGhostAndAGhostInFrontTintsIt) {
  const glm::vec3 body(0, 0.5f, 0.5f);  // nearer the camera (+Z)
  const glm::ivec3 plain = drawBodies(body, {});
  EXPECT_GT(plain.r, 60) << "the grey body at the centre";
  const glm::ivec3 hidden = drawBodies(body, {{glm::vec3(0, 0.5f, -0.5f), glm::vec4(0, 0, 1, 0.5f)}});
  EXPECT_EQ(hidden, plain) << "no blue from the ghost behind the body";
  const glm::ivec3 ahead = drawBodies(body, {{glm::vec3(0, 0.5f, 1.0f), glm::vec4(0, 0, 1, 0.5f)}});
  EXPECT_LT(ahead.r, plain.r - 20);
  EXPECT_GT(ahead.b - ahead.r, plain.b - plain.r + 20);
}

}  // namespace
}  // namespace kinema
