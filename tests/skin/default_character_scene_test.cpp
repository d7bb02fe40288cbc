// The default character scene (skeleton + skinned body) and binding meshes in a scene.
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "io/kinema_file.h"
#include "skin/default_body_mesh.h"
#include "scene/default_character_scene.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

void expectNearMatrix(const glm::mat4& a, const glm::mat4& b, float tol, const std::string& what) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tol) << what << " [" << c << "][" << r << "]";
}

// The rest-pose skinned position of vertex v: sum of w * joint world * inverse bind * p.
glm::vec3 skinnedAtRest(const Scene& scene, const MeshInstance& mi, const MeshPrimitive& prim, int v,
                        const std::vector<glm::mat4>& world) {
  const Skin& skin = scene.skins[mi.skin];
  glm::vec3 out(0.0f);
  for (int k = 0; k < kMaxInfluences; ++k) {
    const float w = prim.influenceWeights[v * kMaxInfluences + k];
    if (w == 0.0f) continue;
    const int i = prim.influenceJoints[v * kMaxInfluences + k];
    out += w * glm::vec3(world[skin.joints[i]] * skin.inverseBind[i] * glm::vec4(prim.positions[v], 1.0f));
  }
  return out;
}

TEST(DefaultCharacterScene, SkinCoversEveryJointWithInverseRestWorlds) {
  const Scene scene = makeDefaultCharacterScene();
  const Skeleton bare = makeDefaultCharacter();
  EXPECT_EQ(scene.skeleton.names, bare.names);
  EXPECT_EQ(scene.skeleton.parents, bare.parents);
  EXPECT_EQ(scene.skeleton.rest, bare.rest);
  ASSERT_EQ(scene.skins.size(), 1u);
  const Skin& skin = scene.skins[0];
  ASSERT_EQ(static_cast<int>(skin.joints.size()), bare.size());
  ASSERT_EQ(skin.inverseBind.size(), skin.joints.size());
  const std::vector<glm::mat4> world = computeWorld(bare, Pose::rest(bare));
  for (int j = 0; j < bare.size(); ++j) {
    EXPECT_EQ(skin.joints[j], j);
    expectNearMatrix(skin.inverseBind[j] * world[j], glm::mat4(1.0f), 1e-6f, bare.names[j]);
  }
}

TEST(DefaultCharacterScene, OneSkinnedClayBodyOnTheRoot) {
  const Scene scene = makeDefaultCharacterScene();
  ASSERT_EQ(scene.meshInstances.size(), 1u);
  const MeshInstance& mi = scene.meshInstances[0];
  EXPECT_EQ(mi.joint, 0);
  EXPECT_EQ(mi.skin, 0);
  ASSERT_EQ(mi.mesh, 0);
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
  const MeshPrimitive& prim = scene.meshes[0].primitives[0];
  EXPECT_TRUE(prim.skinned());
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(prim.material, 0);
  const glm::vec4 c = scene.materials[0].baseColor;
  EXPECT_EQ(c.a, 1.0f);
  EXPECT_GT(c.r, c.b) << "a warm clay, not grey or white";
  EXPECT_LT(c.r, 0.95f);
  EXPECT_EQ(prim.positions, makeDefaultBodyMesh().positions);
  // At rest the skinned body is where it was modelled.
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  for (int v = 0; v < prim.vertexCount(); v += 7)
    EXPECT_VEC3_NEAR(skinnedAtRest(scene, mi, prim, v, world), prim.positions[v], 1e-5f);
}

TEST(DefaultCharacterScene, RoundTripsThroughKinemaFiles) {
  const Scene scene = makeDefaultCharacterScene();
  const std::string json = toKinemaJson(scene);
  const Result<Scene> back = parseKinemaJson(json, "default.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back->meshes.size(), 1u);
  const MeshPrimitive &a = scene.meshes[0].primitives[0], &b = back->meshes[0].primitives.at(0);
  EXPECT_EQ(b.positions, a.positions);
  EXPECT_EQ(b.normals, a.normals);
  EXPECT_EQ(b.indices, a.indices);
  EXPECT_EQ(b.influenceJoints, a.influenceJoints);
  EXPECT_EQ(b.influenceWeights, a.influenceWeights);
  ASSERT_EQ(back->skins.size(), 1u);
  EXPECT_EQ(back->skins[0].joints, scene.skins[0].joints);
  EXPECT_EQ(back->skins[0].inverseBind, scene.skins[0].inverseBind);
  ASSERT_EQ(back->meshInstances.size(), 1u);
  EXPECT_EQ(back->meshInstances[0].skin, 0);
  EXPECT_EQ(back->materials.at(0).baseColor, scene.materials[0].baseColor);
  EXPECT_EQ(toKinemaJson(back.value()), json);
}

// A mesh made in Hips-local space and shown on the Hips joint, like an imported prop.
Scene sceneWithUnskinnedBody() {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  MeshPrimitive prim = makeDefaultBodyMesh();
  for (glm::vec3& p : prim.positions) p -= glm::vec3(0.0f, 0.95f, 0.0f);
  Mesh mesh;
  mesh.name = "Prop";
  mesh.primitives.push_back(std::move(prim));
  scene.meshes.push_back(std::move(mesh));
  scene.meshInstances.push_back({0, 0, -1, {}, SkinningMethod::LinearBlend});
  return scene;
}

TEST(BindMeshWithAutomaticWeights, BindsAnUnskinnedInstanceWhereItStands) {
  Scene scene = sceneWithUnskinnedBody();
  std::string error = "stale";
  ASSERT_TRUE(bindMeshWithAutomaticWeights(scene, 0, AutomaticWeightsMethod::Capsule, error)) << error;
  EXPECT_EQ(error, "");
  const MeshInstance& mi = scene.meshInstances[0];
  ASSERT_EQ(mi.skin, 0);
  ASSERT_EQ(scene.skins.size(), 1u);
  EXPECT_EQ(static_cast<int>(scene.skins[0].joints.size()), scene.skeleton.size());
  const MeshPrimitive& prim = scene.meshes[mi.mesh].primitives[0];
  ASSERT_TRUE(prim.skinned());
  // Rest pose: every vertex stays at Hips world x its local position.
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  for (int v = 0; v < prim.vertexCount(); v += 5)
    EXPECT_VEC3_NEAR(skinnedAtRest(scene, mi, prim, v, world), prim.positions[v] + glm::vec3(0.0f, 0.95f, 0.0f), 1e-5f);
  // The weights are those of the body at its world place, whatever space it was modelled in.
  const Scene reference = makeDefaultCharacterScene();
  int same = 0;
  const MeshPrimitive& expected = reference.meshes[0].primitives[0];
  for (int v = 0; v < prim.vertexCount(); ++v) same += prim.influenceJoints[v * kMaxInfluences] == expected.influenceJoints[v * kMaxInfluences];
  EXPECT_GT(same, prim.vertexCount() * 95 / 100) << "the capsule radii differ (default 0.35 x length) but the nearest bone does not";
  // And the bound scene saves and loads.
  const Result<Scene> back = parseKinemaJson(toKinemaJson(scene), "bound.kinema");
  EXPECT_TRUE(back.ok()) << back.error();
}

TEST(BindMeshWithAutomaticWeights, CopiesAMeshSharedWithAnotherInstance) {
  Scene scene = sceneWithUnskinnedBody();
  scene.meshInstances.push_back({3, 0, -1, {}, SkinningMethod::LinearBlend});
  std::string error;
  ASSERT_TRUE(bindMeshWithAutomaticWeights(scene, 1, AutomaticWeightsMethod::Nearest, error)) << error;
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshInstances[0].mesh, 0);
  EXPECT_FALSE(scene.meshes[0].primitives[0].skinned());
  EXPECT_EQ(scene.meshInstances[1].mesh, 1);
  EXPECT_TRUE(scene.meshes[1].primitives[0].skinned());
  const Result<Scene> back = parseKinemaJson(toKinemaJson(scene), "shared.kinema");
  EXPECT_TRUE(back.ok()) << back.error();
}

TEST(BindMeshWithAutomaticWeights, RefusesWhatItCannotBindAndChangesNothing) {
  Scene scene = makeDefaultCharacterScene();
  const std::string before = toKinemaJson(scene);
  std::string error;
  EXPECT_FALSE(bindMeshWithAutomaticWeights(scene, 0, AutomaticWeightsMethod::Capsule, error));
  EXPECT_NE(error.find("already skinned"), std::string::npos) << error;
  EXPECT_FALSE(bindMeshWithAutomaticWeights(scene, 5, AutomaticWeightsMethod::Capsule, error));
  EXPECT_NE(error.find("mesh instance 5"), std::string::npos) << error;
  EXPECT_FALSE(bindMeshWithAutomaticWeights(scene, -1, AutomaticWeightsMethod::Capsule, error));
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_EQ(toKinemaJson(scene), before);
}

}  // namespace
}  // namespace kinema::test
