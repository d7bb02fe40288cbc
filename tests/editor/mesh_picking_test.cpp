// Picking on a skinned body: a strip of two quads in the z = 0 plane, x = 0..2, whose
// vertices at x = 0 belong to skin slot 0, at x = 1 to slots 0 (0.4) and 1 (0.6), at x = 2
// to slot 1; the skin maps slot 0 to skeleton joint 2 and slot 1 to joint 1. Rays straight
// down -Z from z = 5: the hit is at distance 5 and the corner nearest it decides.
#include "editor/viewport/mesh_picking.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

Scene stripScene() {
  Scene s;
  s.skeleton.addJoint("Root", -1, Transform{});
  s.skeleton.addJoint("A", 0, Transform{});
  s.skeleton.addJoint("B", 0, Transform{});
  MeshPrimitive p;
  // Vertex 2k at (k, -0.5), 2k + 1 at (k, 0.5).
  for (int k = 0; k < 3; ++k) {
    p.positions.push_back({float(k), -0.5f, 0.0f});
    p.positions.push_back({float(k), 0.5f, 0.0f});
  }
  p.indices = {0, 2, 1, 1, 2, 3, 2, 4, 3, 3, 4, 5};
  p.influenceJoints.assign(6 * kMaxInfluences, 0);
  p.influenceWeights.assign(6 * kMaxInfluences, 0.0f);
  auto set = [&](int v, std::initializer_list<std::pair<int, float>> w) {
    int k = 0;
    for (auto [slot, weight] : w) {
      p.influenceJoints[v * kMaxInfluences + k] = static_cast<uint16_t>(slot);
      p.influenceWeights[v * kMaxInfluences + k++] = weight;
    }
  };
  set(0, {{0, 1.0f}});
  set(1, {{0, 1.0f}});
  set(2, {{1, 0.6f}, {0, 0.4f}});
  set(3, {{1, 0.6f}, {0, 0.4f}});
  set(4, {{1, 1.0f}});
  set(5, {{1, 1.0f}});
  Mesh mesh;
  mesh.name = "strip";
  mesh.primitives.push_back(p);
  s.meshes.push_back(mesh);
  Skin skin;
  skin.joints = {2, 1};
  skin.inverseBind = {glm::mat4(1.0f), glm::mat4(1.0f)};
  s.skins.push_back(skin);
  MeshInstance instance;
  instance.joint = 0;
  instance.mesh = 0;
  instance.skin = 0;
  s.meshInstances.push_back(instance);
  return s;
}

PickRay downAt(float x, float y) {
  PickRay r;
  r.origin = {x, y, 5.0f};
  r.direction = {0, 0, -1};
  return r;
}

TEST(MeshPicking, TheJointWeighingMostAtTheNearestCornerOfTheHitTriangle) {
  const Scene s = stripScene();
  const std::vector<glm::mat4> world(3, glm::mat4(1.0f));  // skinning = identity: the strip as built
  MeshPick m = pickMeshJointAt(s, world, downAt(0.2f, 0.1f));
  ASSERT_TRUE(m.hit());
  EXPECT_EQ(m.joint, 2);  // slot 0 -> joint 2
  EXPECT_NEAR(m.distance, 5.0f, 1e-5f);
  EXPECT_EQ(m.instance, 0);
  m = pickMeshJointAt(s, world, downAt(1.1f, -0.3f));  // nearest corner: vertex 2 at (1, -0.5)
  EXPECT_EQ(m.vertex, 2);
  EXPECT_EQ(m.joint, 1);  // 0.6 of slot 1 beats 0.4 of slot 0
  m = pickMeshJointAt(s, world, downAt(1.9f, 0.4f));
  EXPECT_EQ(m.vertex, 5);
  EXPECT_EQ(m.joint, 1);
  EXPECT_FALSE(pickMeshJointAt(s, world, downAt(2.5f, 0.0f)).hit());   // past the strip
  EXPECT_FALSE(pickMeshJointAt(s, world, downAt(1.0f, 0.7f)).hit());   // above it
}

TEST(MeshPicking, FollowsThePoseAndTakesTheNearestSurface) {
  // Joint 2 (slot 0) lifted 3 units towards the eye: the vertices at x = 0 move to z = 3
  // (inverse bind identity, so skinning matrix = the joint's world). A ray at x = 0.1 first
  // meets the tilted triangle near x = 0; the ray at x = 1.9 still meets the flat part.
  const Scene s = stripScene();
  std::vector<glm::mat4> world(3, glm::mat4(1.0f));
  world[2] = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 3));
  MeshPick m = pickMeshJointAt(s, world, downAt(0.1f, 0.0f));
  ASSERT_TRUE(m.hit());
  EXPECT_EQ(m.joint, 2);
  // Triangle (0,-0.5,3) (1,-0.5,1.2) (0,0.5,3): vertex 2 takes 0.4 of the lift, z = 1.2, so
  // z = 3 - 1.8 x on it: at x = 0.1, z = 2.82, distance 5 - 2.82.
  EXPECT_NEAR(m.distance, 5.0f - (3.0f - 1.8f * 0.1f), 1e-4f);
  m = pickMeshJointAt(s, world, downAt(1.9f, 0.0f));
  EXPECT_EQ(m.joint, 1);
  // No mesh at all: nothing.
  Scene bare = s;
  bare.meshInstances.clear();
  EXPECT_FALSE(pickMeshJointAt(bare, world, downAt(0.2f, 0.0f)).hit());
}

}  // namespace
}  // namespace kinema::test
