// Round trips through our writers and readers on the shared files: glTF -> .kinema ->
// glTF and BVH -> glTF -> BVH keep every joint's world position at every frame.
#include <gtest/gtest.h>

#include <dirent.h>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "io/bvh.h"
#include "io/bvh_writer.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

std::vector<std::string> filesUnder(const std::string& dir, const std::vector<std::string>& extensions) {
  std::vector<std::string> out;
  DIR* d = opendir(dir.c_str());
  if (!d) return out;
  while (dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    const std::string path = dir + "/" + name;
    if (e->d_type == DT_DIR) {
      for (const std::string& f : filesUnder(path, extensions)) out.push_back(f);
      continue;
    }
    for (const std::string& ext : extensions)
      if (name.size() > ext.size() && name.substr(name.size() - ext.size()) == ext) out.push_back(path);
  }
  closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<glm::vec3> worldPositions(const Scene& s, int clip, float t) {
  Pose pose = Pose::rest(s.skeleton);
  if (clip < static_cast<int>(s.clips.size())) sampleClip(s.clips[clip], t, pose);
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, pose);
  std::vector<glm::vec3> out;
  for (const glm::mat4& m : world) out.emplace_back(m[3]);
  return out;
}

// Every key time of the clip and a 60 fps grid over it.
std::vector<float> frameTimes(const Clip& clip) {
  std::vector<float> t;
  for (const Channel& ch : clip.channels) t.insert(t.end(), ch.times.begin(), ch.times.end());
  for (int f = 0; f / 60.0f <= clip.duration(); ++f) t.push_back(f / 60.0f);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

// Largest distance between the joints of `a` and `b` paired by glTF node index.
double maxNodeDistance(const Scene& a, const Scene& b) {
  std::vector<int> jointOfNodeB(b.skeleton.size(), -1);
  for (int j = 0; j < b.skeleton.size(); ++j) jointOfNodeB.at(b.fileIndexOf(j)) = j;
  double worst = 0.0;
  const size_t clips = std::max<size_t>(1, a.clips.size());
  for (size_t c = 0; c < clips; ++c) {
    const std::vector<float> times = c < a.clips.size() ? frameTimes(a.clips[c]) : std::vector<float>{0.0f};
    for (float t : times) {
      const std::vector<glm::vec3> pa = worldPositions(a, int(c), t), pb = worldPositions(b, int(c), t);
      for (int j = 0; j < a.skeleton.size(); ++j)
        worst = std::max(worst, double(glm::length(pa[j] - pb[jointOfNodeB.at(a.fileIndexOf(j))])));
    }
  }
  return worst;
}

TEST(GltfRoundTrip, GltfToKinemaToGltfKeepsEveryNodeAtEveryFrame) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::vector<std::string> files = filesUnder(test::sharedDataDir() + "/gltf", {".gltf", ".glb"});
  ASSERT_GE(files.size(), 7u);
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const Result<Scene> original = loadGltf(path);
    ASSERT_TRUE(original.ok()) << original.error();
    const Result<Scene> kinema = parseKinemaJson(toKinemaJson(original.value()), "copy.kinema");
    ASSERT_TRUE(kinema.ok()) << kinema.error();
    std::vector<std::string> report;
    const Result<std::string> bytes = gltfBytes(kinema.value(), {}, &report);
    ASSERT_TRUE(bytes.ok()) << bytes.error();
    // The shared files use STEP, LINEAR and CUBICSPLINE only: nothing is resampled.
    EXPECT_TRUE(report.empty()) << report.front();
    const Result<Scene> back = parseGltf(bytes.value(), "back.gltf");
    ASSERT_TRUE(back.ok()) << back.error();

    EXPECT_EQ(back->nodeNames, original->nodeNames);
    EXPECT_EQ(back->nodeOfJoint.size(), original->nodeOfJoint.size());
    ASSERT_EQ(back->clips.size(), original->clips.size());
    for (size_t c = 0; c < back->clips.size(); ++c) EXPECT_EQ(back->clips[c].name, original->clips[c].name);
    EXPECT_LT(maxNodeDistance(original.value(), back.value()), 1e-4);
    // Meshes, skins and materials come back as they were.
    ASSERT_EQ(back->meshes.size(), original->meshes.size());
    for (size_t m = 0; m < back->meshes.size(); ++m) {
      ASSERT_EQ(back->meshes[m].primitives.size(), original->meshes[m].primitives.size());
      for (size_t p = 0; p < back->meshes[m].primitives.size(); ++p) {
        const MeshPrimitive &x = original->meshes[m].primitives[p], &y = back->meshes[m].primitives[p];
        EXPECT_EQ(x.positions, y.positions);
        EXPECT_EQ(x.normals, y.normals);
        EXPECT_EQ(x.texcoords, y.texcoords);
        EXPECT_EQ(x.indices, y.indices);
        EXPECT_EQ(x.influenceJoints, y.influenceJoints);
        ASSERT_EQ(x.influenceWeights.size(), y.influenceWeights.size());
        for (size_t i = 0; i < x.influenceWeights.size(); ++i)
          ASSERT_NEAR(x.influenceWeights[i], y.influenceWeights[i], 1e-6f);
        EXPECT_EQ(x.targets.size(), y.targets.size());
        EXPECT_EQ(x.material, y.material);
      }
      EXPECT_EQ(back->meshes[m].morphWeights, original->meshes[m].morphWeights);
    }
    ASSERT_EQ(back->skins.size(), original->skins.size());
    for (size_t s = 0; s < back->skins.size(); ++s) EXPECT_EQ(back->skins[s].inverseBind, original->skins[s].inverseBind);
    ASSERT_EQ(back->images.size(), original->images.size());
    for (size_t i = 0; i < back->images.size(); ++i) EXPECT_EQ(back->images[i].rgba, original->images[i].rgba);
    ASSERT_EQ(back->materials.size(), original->materials.size());
    for (size_t i = 0; i < back->materials.size(); ++i)
      EXPECT_EQ(back->materials[i].baseColor, original->materials[i].baseColor);
  }
}

TEST(GltfRoundTrip, BvhToGltfToBvhKeepsEveryJointAtEveryFrame) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::vector<std::string> files = filesUnder(test::sharedDataDir() + "/bvh", {".bvh"});
  ASSERT_FALSE(files.empty());
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const Result<BvhData> original = loadBvh(path);
    ASSERT_TRUE(original.ok()) << original.error();
    Scene scene;
    scene.skeleton = original->skeleton();
    scene.clips.push_back(original->clip());
    GltfWriteOptions glb;
    glb.binary = true;
    std::vector<std::string> report;
    const Result<std::string> bytes = gltfBytes(scene, glb, &report);
    ASSERT_TRUE(bytes.ok()) << bytes.error();
    EXPECT_TRUE(report.empty()) << report.front();  // BVH motion is LINEAR: exact in glTF
    const Result<Scene> viaGltf = parseGltf(bytes.value(), "motion.glb");
    ASSERT_TRUE(viaGltf.ok()) << viaGltf.error();
    ASSERT_EQ(viaGltf->clips.size(), 1u);
    // The glTF clip has no frame grid: the writer finds it from the key times.
    report.clear();
    const Result<std::string> text = bvhText(viaGltf->skeleton, &viaGltf->clips[0], {}, &report);
    ASSERT_TRUE(text.ok()) << text.error();
    EXPECT_TRUE(report.empty()) << report.front();
    const Result<BvhData> back = parseBvh(text.value(), "back.bvh");
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->frameCount, original->frameCount);
    EXPECT_NEAR(back->frameTime, original->frameTime, 1e-9);
    ASSERT_EQ(back->joints.size(), original->joints.size());
    const Skeleton so = original->skeleton(), sb = back->skeleton();
    double worst = 0.0;
    for (int f = 0; f < original->frameCount; ++f) {
      const std::vector<glm::mat4> wo = computeWorld(so, original->framePose(f)), wb = computeWorld(sb, back->framePose(f));
      for (int j = 0; j < so.size(); ++j) {
        ASSERT_EQ(sb.names[j], so.names[j]);
        worst = std::max(worst, double(glm::length(glm::vec3(wo[j][3]) - glm::vec3(wb[j][3]))));
      }
    }
    EXPECT_LT(worst, 1e-4);
  }
}

// glTF characters to BVH: rest rotations folded into the channels, every named joint at
// the same place at every BVH frame (CesiumMan's and the Fox's scales are 1).
TEST(GltfRoundTrip, GltfCharactersToBvhKeepJointPositions) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (const char* name : {"CesiumMan.glb", "Fox.glb"}) {
    SCOPED_TRACE(name);
    const Result<Scene> scene = loadGltf(test::sharedDataDir() + "/gltf/" + name);
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_FALSE(scene->clips.empty());
    const Result<std::string> text = bvhText(scene->skeleton, &scene->clips[0], {});
    ASSERT_TRUE(text.ok()) << text.error();
    const Result<BvhData> bvh = parseBvh(text.value(), "character.bvh");
    ASSERT_TRUE(bvh.ok()) << bvh.error();
    const Skeleton sb = bvh->skeleton();
    ASSERT_GT(bvh->frameCount, 1);
    double worst = 0.0;
    for (int f = 0; f < bvh->frameCount; ++f) {
      const std::vector<glm::vec3> want = worldPositions(scene.value(), 0, float(f * bvh->frameTime));
      const std::vector<glm::mat4> got = computeWorld(sb, bvh->framePose(f));
      for (int j = 0; j < scene->skeleton.size(); ++j) {
        const int b = sb.find(scene->skeleton.names[j]);
        ASSERT_GE(b, 0) << scene->skeleton.names[j];
        worst = std::max(worst, double(glm::length(want[j] - glm::vec3(got[b][3]))));
      }
    }
    EXPECT_LT(worst, 1e-4);
  }
}

}  // namespace
}  // namespace kinema
