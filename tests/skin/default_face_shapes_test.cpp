// The default character's face (issue 22): four named expression shapes made by soft pulls,
// checked against the soft pull's closed forms: the picked vertex moves by the full offset,
// nothing beyond the radius moves, the jaw's weight map keeps the upper face still.
#include <gtest/gtest.h>

#include <limits>

#include "scene/default_character_scene.h"
#include "skin/default_face_shapes.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

int nearestIndex(const std::vector<glm::vec3>& v, const glm::vec3& p) {
  int best = -1;
  float bestDistance = std::numeric_limits<float>::max();
  for (size_t i = 0; i < v.size(); ++i)
    if (glm::dot(v[i] - p, v[i] - p) < bestDistance) {
      bestDistance = glm::dot(v[i] - p, v[i] - p);
      best = static_cast<int>(i);
    }
  return best;
}

TEST(DefaultFace, FourNamedShapesAtWeightZero) {
  const Scene scene = makeDefaultCharacterScene();
  const Mesh& body = scene.meshes[0];
  EXPECT_EQ(body.targetNames, (std::vector<std::string>{"jaw_open", "smile", "brow_raise", "blink"}));
  EXPECT_EQ(body.morphWeights, (std::vector<float>{0, 0, 0, 0}));
  const MeshPrimitive& prim = body.primitives[0];
  ASSERT_EQ(prim.targets.size(), 4u);
  for (const MorphTarget& t : prim.targets) {
    EXPECT_EQ(t.positionDeltas.size(), prim.positions.size());
    EXPECT_EQ(t.normalDeltas.size(), prim.positions.size());
  }
}

TEST(DefaultFace, ShapesFollowTheSoftPullClosedForms) {
  const Scene scene = makeDefaultCharacterScene();
  const MeshPrimitive& prim = scene.meshes[0].primitives[0];
  const std::vector<glm::vec3>& v = prim.positions;
  const DefaultFaceLandmarks f = defaultFaceLandmarks();
  auto front = [&](float x, float y) { return nearestIndex(v, glm::vec3(x, y, f.frontZ(x, y))); };
  // The picked vertices move by the full offset (the other side's pull is farther than its radius).
  EXPECT_VEC3_NEAR(prim.targets[1].positionDeltas[front(f.mouthX, f.mouthY)], glm::vec3(0.012f, 0.016f, -0.006f), 1e-6f);
  EXPECT_VEC3_NEAR(prim.targets[1].positionDeltas[front(-f.mouthX, f.mouthY)], glm::vec3(-0.012f, 0.016f, -0.006f), 1e-6f);
  EXPECT_VEC3_NEAR(prim.targets[2].positionDeltas[front(f.browX, f.browY)], glm::vec3(0.0f, 0.016f, 0.003f), 1e-6f);
  EXPECT_VEC3_NEAR(prim.targets[3].positionDeltas[front(-f.eyeX, f.eyeY)], glm::vec3(0.0f, -0.01f, -0.01f), 1e-6f);
  // The chin's vertex is under the mouth by more than the ramp: weight 1, the full offset.
  EXPECT_VEC3_NEAR(prim.targets[0].positionDeltas[front(0.0f, f.chinY)], glm::vec3(0.0f, -0.035f, -0.012f), 1e-6f);
  // Nothing below the neck moves, and the jaw leaves everything above the mouth line.
  for (size_t i = 0; i < v.size(); ++i) {
    if (v[i].y < 1.4f) {
      for (int k = 0; k < 4; ++k) ASSERT_EQ(prim.targets[k].positionDeltas[i], glm::vec3(0.0f)) << i << " " << k;
    }
    if (v[i].y >= f.mouthY + 0.01f) {
      ASSERT_EQ(prim.targets[0].positionDeltas[i], glm::vec3(0.0f)) << i;
    }
  }
  // Every shape moves something: how many vertices each moves by more than a millimetre.
  for (int k = 0; k < 4; ++k) {
    int moved = 0;
    for (const glm::vec3& d : prim.targets[k].positionDeltas) moved += glm::length(d) > 1e-3f;
    EXPECT_GE(moved, 2) << scene.meshes[0].targetNames[k];
  }
}

}  // namespace
}  // namespace kinema
