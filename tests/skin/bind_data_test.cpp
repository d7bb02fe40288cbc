// Bind data on load: influences renormalised with one warning per primitive naming it and
// counting the vertices (glTF and .kinema), .kinema's per-instance skinning method.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/gltf_reader.h"
#include "io/kinema_file.h"
#include "io/sample_scene.h"
#include "skin/skinned_test_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

int countContaining(const std::vector<std::string>& lines, const std::string& part) {
  return static_cast<int>(std::count_if(lines.begin(), lines.end(),
                                        [&](const std::string& l) { return l.find(part) != std::string::npos; }));
}

float weightSum(const MeshPrimitive& p, int v) {
  float sum = 0;
  for (int k = 0; k < kMaxInfluences; ++k) sum += p.influenceWeights[v * kMaxInfluences + k];
  return sum;
}

// Vertex 0 sums to 0.75 and vertex 2 to 1.2; vertex 1 is off by 5e-4 only (inside 1e-3).
TEST(BindData, GltfWeightsNotSummingToOneAreRenormalisedAndReportedOnce) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/w.gltf",
                  test::skinnedTriangleFile({0.5f, 0.25f, 0, 0, 0.7f, 0.3005f, 0, 0, 0.6f, 0.6f, 0, 0}).gltf());
  const Result<Scene> r = loadGltf(dir + "/w.gltf");
  ASSERT_TRUE(r.ok()) << r.error();
  const Scene& s = r.value();
  EXPECT_EQ(countContaining(s.warnings, "renormalised"), 1);
  EXPECT_EQ(countContaining(s.warnings, "mesh 0 primitive 0: 2 of 3 vertices had skin weights not summing to 1"), 1);
  const MeshPrimitive& p = s.meshes.at(0).primitives.at(0);
  for (int v = 0; v < 3; ++v) EXPECT_NEAR(weightSum(p, v), 1.0f, 1e-6f) << v;
  EXPECT_NEAR(p.influenceWeights[0], 0.5f / 0.75f, 1e-6f);
  EXPECT_NEAR(p.influenceWeights[kMaxInfluences * 2 + 1], 0.5f, 1e-6f);
}

TEST(BindData, GltfWeightsSummingToOneSayNothing) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/ok.gltf", test::skinnedTriangleFile({0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 0.25f, 0.75f, 0, 0}).gltf());
  const Result<Scene> r = loadGltf(dir + "/ok.gltf");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(countContaining(r.value().warnings, "renormalised"), 0);
}

// The sample scene's first primitive, edited in its .kinema text.
nlohmann::json sampleJson() { return nlohmann::json::parse(toKinemaJson(test::makeSampleScene())); }

TEST(BindData, KinemaWeightsAreRenormalisedSortedAndReportedOnce) {
  nlohmann::json j = sampleJson();
  auto& w = j["meshes"][0]["primitives"][0]["weights"];
  auto& joints = j["meshes"][0]["primitives"][0]["joints"];
  const size_t vertices = j["meshes"][0]["primitives"][0]["positions"].size() / 3;
  ASSERT_GE(vertices, 2u);
  // Vertex 0: weights doubled (sum 2), and its first two influences swapped (not sorted).
  for (int k = 0; k < kMaxInfluences; ++k) w[k] = 2 * w[k].get<double>();
  std::swap(w[0], w[1]);
  std::swap(joints[0], joints[1]);
  // Vertex 1: every weight zero -> follows its first joint.
  for (int k = 0; k < kMaxInfluences; ++k) w[kMaxInfluences + k] = 0.0;
  const Result<Scene> r = parseKinemaJson(j.dump(), "w.kinema");
  ASSERT_TRUE(r.ok()) << r.error();
  const std::vector<std::string>& warnings = r.value().warnings;
  EXPECT_EQ(countContaining(warnings, "renormalised"), 1);
  EXPECT_EQ(countContaining(warnings, "meshes[0].primitives[0]: 1 of " + std::to_string(vertices) +
                                          " vertices had skin weights not summing to 1"),
            1)
      << (warnings.empty() ? "" : warnings[0]);
  EXPECT_EQ(countContaining(warnings, "meshes[0].primitives[0]: 1 vertices without skin weight"), 1);
  const Scene original = test::makeSampleScene();
  const MeshPrimitive &p = r.value().meshes[0].primitives[0], &o = original.meshes[0].primitives[0];
  // Back to the original influences: sorted again, halved again.
  for (int k = 0; k < kMaxInfluences; ++k) {
    EXPECT_NEAR(p.influenceWeights[k], o.influenceWeights[k], 1e-6f) << k;
    if (o.influenceWeights[k] > 0) {
      EXPECT_EQ(p.influenceJoints[k], o.influenceJoints[k]) << k;
    }
  }
  EXPECT_EQ(p.influenceWeights[kMaxInfluences], 1.0f);
  EXPECT_NEAR(weightSum(p, 1), 1.0f, 0.0f);
}

// Weights near FLT_MAX sum past float range; the renormalised weights must still be 1/2 each.
TEST(BindData, KinemaHugeWeightsRenormaliseWithoutOverflow) {
  nlohmann::json j = sampleJson();
  auto& w = j["meshes"][0]["primitives"][0]["weights"];
  for (int k = 0; k < kMaxInfluences; ++k) w[k] = k < 2 ? 3.0e38 : 0.0;
  const Result<Scene> r = parseKinemaJson(j.dump(), "huge.kinema");
  ASSERT_TRUE(r.ok()) << r.error();
  const MeshPrimitive& p = r.value().meshes[0].primitives[0];
  EXPECT_EQ(p.influenceWeights[0], 0.5f);
  EXPECT_EQ(p.influenceWeights[1], 0.5f);
}

TEST(BindData, KinemaNegativeWeightIsAnError) {
  nlohmann::json j = sampleJson();
  j["meshes"][0]["primitives"][0]["weights"][3] = -0.25;
  const Result<Scene> r = parseKinemaJson(j.dump(), "neg.kinema");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("neg.kinema: meshes[0].primitives[0].weights[3]: a weight must not be negative"),
            std::string::npos)
      << r.error();
}

// Files our own writer produced read back bit for bit, without warnings.
TEST(BindData, KinemaSavedWeightsReadBackExactly) {
  const Scene original = test::makeSampleScene();
  const Result<Scene> r = parseKinemaJson(toKinemaJson(original), "same.kinema");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_TRUE(r.value().warnings.empty());
  EXPECT_EQ(r.value().meshes[0].primitives[0].influenceWeights, original.meshes[0].primitives[0].influenceWeights);
}

TEST(BindData, KinemaSkinningMethodRoundTrips) {
  Scene scene = test::makeSampleScene();
  ASSERT_FALSE(scene.meshInstances.empty());
  // Linear is the default and is not written.
  EXPECT_EQ(toKinemaJson(scene).find("\"skinning\""), std::string::npos);
  scene.meshInstances[0].skinning = SkinningMethod::DualQuaternion;
  const std::string text = toKinemaJson(scene);
  EXPECT_NE(text.find("\"skinning\": \"dual-quaternion\""), std::string::npos);
  const Result<Scene> back = parseKinemaJson(text, "dq.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back.value().meshInstances[0].skinning, SkinningMethod::DualQuaternion);
  for (size_t i = 1; i < back.value().meshInstances.size(); ++i)
    EXPECT_EQ(back.value().meshInstances[i].skinning, SkinningMethod::LinearBlend);

  nlohmann::json j = nlohmann::json::parse(text);
  j["mesh_instances"][0]["skinning"] = "linear";
  ASSERT_TRUE(parseKinemaJson(j.dump(), "lin.kinema").ok());
  EXPECT_EQ(parseKinemaJson(j.dump(), "lin.kinema").value().meshInstances[0].skinning, SkinningMethod::LinearBlend);
  j["mesh_instances"][0]["skinning"] = "cubic";
  const Result<Scene> bad = parseKinemaJson(j.dump(), "bad.kinema");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("bad.kinema: mesh_instances[0].skinning: expected \"linear\" or \"dual-quaternion\""),
            std::string::npos)
      << bad.error();
}

}  // namespace
}  // namespace kinema
