// .kinema keeps what glTF scenes add (meshes, skins, instances, materials, images, node
// order): exact round trips, and one-line errors naming the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/gltf_writer.h"
#include "io/kinema_file.h"
#include "io/sample_scene.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

void expectSameAssets(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.nodeOfJoint, b.nodeOfJoint);
  EXPECT_EQ(a.nodeNames, b.nodeNames);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t m = 0; m < a.meshes.size(); ++m) {
    EXPECT_EQ(a.meshes[m].name, b.meshes[m].name);
    EXPECT_EQ(a.meshes[m].morphWeights, b.meshes[m].morphWeights);
    EXPECT_EQ(a.meshes[m].targetNames, b.meshes[m].targetNames);
    ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size());
    for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
      const MeshPrimitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
      EXPECT_EQ(x.positions, y.positions);
      EXPECT_EQ(x.normals, y.normals);
      EXPECT_EQ(x.texcoords, y.texcoords);
      EXPECT_EQ(x.indices, y.indices);
      EXPECT_EQ(x.influenceJoints, y.influenceJoints);
      EXPECT_EQ(x.influenceWeights, y.influenceWeights);
      EXPECT_EQ(x.material, y.material);
      ASSERT_EQ(x.targets.size(), y.targets.size());
      for (size_t t = 0; t < x.targets.size(); ++t) {
        EXPECT_EQ(x.targets[t].positionDeltas, y.targets[t].positionDeltas);
        EXPECT_EQ(x.targets[t].normalDeltas, y.targets[t].normalDeltas);
      }
    }
  }
  ASSERT_EQ(a.skins.size(), b.skins.size());
  for (size_t s = 0; s < a.skins.size(); ++s) {
    EXPECT_EQ(a.skins[s].name, b.skins[s].name);
    EXPECT_EQ(a.skins[s].joints, b.skins[s].joints);
    EXPECT_EQ(a.skins[s].inverseBind, b.skins[s].inverseBind);
    EXPECT_EQ(a.skins[s].skeletonRoot, b.skins[s].skeletonRoot);
  }
  ASSERT_EQ(a.meshInstances.size(), b.meshInstances.size());
  for (size_t i = 0; i < a.meshInstances.size(); ++i) {
    EXPECT_EQ(a.meshInstances[i].joint, b.meshInstances[i].joint);
    EXPECT_EQ(a.meshInstances[i].mesh, b.meshInstances[i].mesh);
    EXPECT_EQ(a.meshInstances[i].skin, b.meshInstances[i].skin);
    EXPECT_EQ(a.meshInstances[i].morphWeights, b.meshInstances[i].morphWeights);
    EXPECT_EQ(a.meshInstances[i].skinning, b.meshInstances[i].skinning);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    EXPECT_EQ(a.materials[i].baseColor, b.materials[i].baseColor);
    EXPECT_EQ(a.materials[i].baseColorImage, b.materials[i].baseColorImage);
    EXPECT_EQ(a.materials[i].doubleSided, b.materials[i].doubleSided);
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (size_t i = 0; i < a.images.size(); ++i) {
    EXPECT_EQ(a.images[i].name, b.images[i].name);
    EXPECT_EQ(a.images[i].width, b.images[i].width);
    EXPECT_EQ(a.images[i].height, b.images[i].height);
    EXPECT_EQ(a.images[i].rgba, b.images[i].rgba);
  }
}

TEST(KinemaSceneAssets, RoundTripKeepsEveryMeshSkinMaterialAndImage) {
  const Scene scene = test::makeSampleScene();
  const Result<Scene> back = parseKinemaJson(toKinemaJson(scene), "sample.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  expectSameAssets(scene, back.value());
  // glTF written from the re-read scene is byte for byte the same file.
  EXPECT_EQ(gltfBytes(scene, {}).value(), gltfBytes(back.value(), {}).value());
}

TEST(KinemaSceneAssets, FilesWithoutAssetsStayAsTheyWere) {
  Scene scene;
  scene.skeleton.addJoint("a", -1, Transform::identity());
  const std::string text = toKinemaJson(scene);
  for (const char* key : {"meshes", "skins", "mesh_instances", "materials", "images", "node_of_joint"})
    EXPECT_EQ(text.find(key), std::string::npos) << key;
}

// Each edit breaks one thing; the error names where.
TEST(KinemaSceneAssets, ErrorsNameTheJsonPath) {
  const std::string good = toKinemaJson(test::makeSampleScene());
  struct Case {
    const char* pointer;
    nlohmann::json value;
    const char* path;
  };
  const Case cases[] = {
      {"/mesh_instances/0/mesh", 5, "mesh_instances[0].mesh: 5 is out of range"},
      {"/meshes/0/primitives/0/indices/4", 8, "meshes[0].primitives[0].indices[4]: 8 is out of range"},
      {"/meshes/0/primitives/0/positions/2", "x", "meshes[0].primitives[0].positions[2]: expected a number"},
      {"/meshes/0/primitives/0/normals", nlohmann::json::array({0, 0, 1}),
       "meshes[0].primitives[0].normals: one normal per position"},
      {"/images/0/png", "not base64!", "images[0].png: not base64"},
      {"/images/0/png", "AAAA", "images[0].png: not a PNG image"},
      {"/skins/0/joints/1", "Nobody", "skins[0].joints[1]: no joint named 'Nobody'"},
      {"/skins/0/inverse_bind", nlohmann::json::array({1, 0, 0, 0}), "skins[0].inverse_bind: expected an array of numbers, 16"},
      {"/node_of_joint/1", 2, "node_of_joint[1]: node 2 is given to two joints"},
      {"/materials/0/base_color_image", 3, "materials[0].base_color_image: 3 is out of range"},
      {"/meshes/0/primitives/0/joints/0", 70000, "meshes[0].primitives[0].joints[0]: 70000 is out of range"},
      {"/meshes/0/primitives/0/joints/0", 9, "mesh_instances[0]: meshes[0].primitives[0].joints[0] = 9 is past the skin's 8 joints"},
  };
  for (const Case& c : cases) {
    nlohmann::json j = nlohmann::json::parse(good);
    j[nlohmann::json::json_pointer(c.pointer)] = c.value;
    const Result<Scene> r = parseKinemaJson(j.dump(), "bad.kinema");
    ASSERT_FALSE(r.ok()) << c.pointer;
    EXPECT_NE(r.error().find(std::string("bad.kinema: ") + c.path), std::string::npos) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  }
}

TEST(KinemaSceneAssets, SavingRefusesDanglingReferences) {
  const std::string dir = test::makeTempDir();
  Scene scene = test::makeSampleScene();
  scene.meshInstances[0].skin = 4;
  const std::string error = saveKinemaFile(dir + "/x.kinema", scene);
  EXPECT_NE(error.find("not saved: mesh instance 0"), std::string::npos) << error;
}

}  // namespace
}  // namespace kinema
