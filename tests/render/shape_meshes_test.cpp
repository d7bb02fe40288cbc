// Bone, sphere and grid geometry, and the bone instance matrices (no GL context needed).
#include <glm/gtc/matrix_transform.hpp>

#include "render/grid_lines.h"
#include "render/shape_meshes.h"
#include "render/skeleton_draw_list.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// Signed volume by the divergence theorem: positive when every triangle winds
// counter-clockwise seen from outside.
double signedVolume(const ShapeMesh& m) {
  double v = 0;
  for (int i = 0; i + 2 < m.vertexCount(); i += 3)
    v += glm::dot(glm::dvec3(m.positions[i]), glm::cross(glm::dvec3(m.positions[i + 1]), glm::dvec3(m.positions[i + 2]))) / 6.0;
  return v;
}

TEST(OctahedralBone, HasBlendersProportionsAndOutwardFaces) {
  const ShapeMesh m = makeOctahedralBone();
  ASSERT_EQ(m.vertexCount(), 24);  // 8 flat triangles
  // Two square pyramids on the waist (side 0.2, area 0.04), heights 0.1 and 0.9: V = 0.04 * 1 / 3.
  EXPECT_NEAR(signedVolume(m), 0.04 / 3.0, 1e-7);
  float minY = 1e9f, maxY = -1e9f;
  for (int i = 0; i < m.vertexCount(); i += 3) {
    const glm::vec3 centroid = (m.positions[i] + m.positions[i + 1] + m.positions[i + 2]) / 3.0f;
    const glm::vec3 n = m.normals[i];
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    // The shape is convex around (0, 0.1, 0), so each face normal points away from it.
    EXPECT_GT(glm::dot(n, centroid - glm::vec3(0, 0.1f, 0)), 0.0f);
    for (int k = 0; k < 3; ++k) {
      minY = std::min(minY, m.positions[i + k].y);
      maxY = std::max(maxY, m.positions[i + k].y);
      EXPECT_LE(std::abs(m.positions[i + k].x), 0.1f + 1e-7f);
    }
  }
  EXPECT_FLOAT_EQ(minY, 0.0f);
  EXPECT_FLOAT_EQ(maxY, 1.0f);
}

TEST(Sphere, IsAClosedUnitSphereWoundOutward) {
  const ShapeMesh m = makeSphere(16, 10);
  ASSERT_EQ(m.vertexCount() % 3, 0);
  EXPECT_EQ(m.vertexCount(), 3 * (2 * 16 * 10 - 2 * 16));  // quads, minus one triangle per pole cell
  for (int i = 0; i < m.vertexCount(); ++i) EXPECT_NEAR(glm::length(m.positions[i]), 1.0f, 1e-6f);
  // Inscribed polyhedron: a little under 4/3 pi, and close to it when finer.
  const double v = signedVolume(m), fine = signedVolume(makeSphere(64, 40));
  const double exact = 4.0 / 3.0 * 3.14159265358979;
  EXPECT_GT(v, 0.9 * exact);
  EXPECT_LT(v, exact);
  EXPECT_NEAR(fine, exact, 0.01 * exact);
}

// Welding keeps every triangle, corner for corner, and stores each distinct corner once:
// a 16 x 10 sphere has 16 x 9 ring points and two poles, each pole repeated per slice
// with the same position (at the north pole sin(0) = 0 gives +-0, which weld).
TEST(WeldVertices, SameTrianglesEachCornerOnce) {
  for (const ShapeMesh& m : {makeSphere(16, 10), makeOctahedralBone()}) {
    const IndexedShapeMesh w = weldVertices(m);
    ASSERT_EQ(w.indices.size(), m.positions.size());
    ASSERT_EQ(w.positions.size(), w.normals.size());
    for (size_t i = 0; i < w.indices.size(); ++i) {
      ASSERT_LT(w.indices[i], w.positions.size());
      EXPECT_EQ(w.positions[w.indices[i]], m.positions[i]) << i;
      EXPECT_EQ(w.normals[w.indices[i]], m.normals[i]) << i;
    }
    for (size_t a = 0; a < w.positions.size(); ++a)  // no two stored corners alike
      for (size_t b = a + 1; b < w.positions.size(); ++b)
        EXPECT_FALSE(w.positions[a] == w.positions[b] && w.normals[a] == w.normals[b]) << a << " " << b;
  }
  // The north pole welds to one vertex; the south pole's 16 copies are the same point only
  // up to float rounding of sin(pi) (about -8.7e-8), so at most 16 of them stay apart.
  const size_t sphere = weldVertices(makeSphere(16, 10)).positions.size();
  EXPECT_GE(sphere, 16u * 9u + 2u);
  EXPECT_LE(sphere, 16u * 9u + 1u + 16u);
  // Flat faces share no corner normals: the bone's 6 points make 24 distinct corners.
  EXPECT_EQ(weldVertices(makeOctahedralBone()).positions.size(), 24u);
}

TEST(BoneMatrix, TakesTheUnitBoneToTheSegmentWithUniformScale) {
  const glm::vec3 head(1, 2, 3), tail(1, 2, 3 + 2);  // length 2 along +Z
  const glm::mat4 m = boneMatrix(head, tail, glm::vec3(1, 0, 0));
  EXPECT_VEC3_NEAR(glm::vec3(m * glm::vec4(0, 0, 0, 1)), head, 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(m * glm::vec4(0, 1, 0, 1)), tail, 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(m[0]), glm::vec3(2, 0, 0), 1e-6f);  // roll follows the hint
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::length(glm::vec3(m[c])), 2.0f, 1e-6f);
  EXPECT_GT(glm::determinant(glm::mat3(m)), 0.0f);  // no mirroring
  // A hint along the bone still gives a valid frame.
  const glm::mat4 p = boneMatrix(head, tail, glm::vec3(0, 0, 1));
  EXPECT_NEAR(glm::dot(glm::vec3(p[0]), glm::vec3(p[1])), 0.0f, 1e-5f);
  EXPECT_VEC3_NEAR(glm::vec3(p * glm::vec4(0, 1, 0, 1)), tail, 1e-6f);
}

TEST(SkeletonDrawList, OneBonePerParentChildPairAndOneSpherePerJoint) {
  // Root at origin, A 1 up, B 1 up from A, C at A again (zero-length bone: not drawn).
  std::vector<int> parents = {-1, 0, 1, 1};
  std::vector<glm::mat4> world(4, glm::mat4(1));
  world[1][3] = glm::vec4(0, 1, 0, 1);
  world[2][3] = glm::vec4(0, 2, 0, 1);
  world[3][3] = glm::vec4(0, 1, 0, 1);
  SkeletonDrawJob job;
  job.parents = &parents;
  job.world = &world;
  job.selectedJoint = 1;
  SkeletonDrawList list;
  ASSERT_TRUE(job.run(list));
  ASSERT_EQ(list.boneMatrices.size(), 2u);
  EXPECT_VEC3_NEAR(glm::vec3(list.boneMatrices[1] * glm::vec4(0, 1, 0, 1)), glm::vec3(0, 2, 0), 1e-6f);
  EXPECT_EQ(list.boneColors[0], job.style.bone);          // root -> A
  EXPECT_EQ(list.boneColors[1], job.style.selectedBone);  // A -> B starts at the selection
  ASSERT_EQ(list.jointMatrices.size(), 4u);
  EXPECT_EQ(list.jointColors[1], job.style.selectedJoint);
  // Radius = a tenth of the shortest touching bone (0.1), capped at 0.025 x the bounds radius (1);
  // a joint with no drawn bone (C) gets 0.02 x the bounds radius.
  for (int j : {0, 1, 2}) EXPECT_NEAR(list.jointMatrices[j][0][0], 0.025f, 1e-6f);
  EXPECT_NEAR(list.jointMatrices[3][0][0], 0.02f, 1e-6f);

  std::vector<int> bad = {-1, 2, 0};
  job.parents = &bad;
  world.resize(3);
  EXPECT_FALSE(job.validate().empty());
  EXPECT_FALSE(job.run(list));
  EXPECT_TRUE(list.boneMatrices.empty());
}

// A glTF character's mesh and helper nodes are joints of the skeleton but not of the skin:
// with the skin's mask only skin joints are drawn, each bone spanning to the nearest drawn
// ancestor (here B's parent H is a helper, so the bone runs A -> B).
TEST(SkeletonDrawList, ShownJointsSkipHelperNodesAndBridgeToTheNearestShownAncestor) {
  std::vector<int> parents = {-1, 0, 1, 2, 0};  // Armature, A, H, B, MeshNode
  std::vector<glm::mat4> world(5, glm::mat4(1));
  world[0] = glm::scale(glm::mat4(1), glm::vec3(100.0f));  // a big helper transform
  world[1][3] = glm::vec4(0, 1, 0, 1);
  world[2][3] = glm::vec4(0, 1.5f, 0, 1);
  world[3][3] = glm::vec4(0, 2, 0, 1);
  world[4][3] = glm::vec4(5, 0, 0, 1);
  const std::vector<char> shown = {0, 1, 0, 1, 0};
  SkeletonDrawJob job;
  job.parents = &parents;
  job.world = &world;
  job.shownJoints = &shown;
  SkeletonDrawList list;
  ASSERT_TRUE(job.run(list));
  ASSERT_EQ(list.boneMatrices.size(), 1u);
  EXPECT_VEC3_NEAR(glm::vec3(list.boneMatrices[0] * glm::vec4(0, 0, 0, 1)), glm::vec3(0, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(list.boneMatrices[0] * glm::vec4(0, 1, 0, 1)), glm::vec3(0, 2, 0), 1e-6f);
  ASSERT_EQ(list.jointMatrices.size(), 2u);
  // Sized by the drawn joints only (bounds radius 0.5, taken up to the step 1.25^-3 = 0.512),
  // not by the far mesh node (radius over 2.5).
  EXPECT_NEAR(list.jointMatrices[0][0][0], 0.025f * 0.512f, 1e-6f);

  // Without a mask (BVH, bare skeletons) every joint is drawn, as before.
  const std::vector<char> none;
  job.shownJoints = &none;
  ASSERT_TRUE(job.run(list));
  EXPECT_EQ(list.jointMatrices.size(), 5u);
  EXPECT_EQ(list.boneMatrices.size(), 4u);
  const std::vector<char> wrongSize = {1, 1};
  job.shownJoints = &wrongSize;
  EXPECT_FALSE(job.run(list));

  // skinJointMask marks exactly the skin's joints; a scene without skins gives no mask.
  Scene scene;
  for (int i = 0; i < 5; ++i) scene.skeleton.addJoint("n" + std::to_string(i), parents[i], Transform{});
  EXPECT_TRUE(skinJointMask(scene).empty());
  scene.skins.push_back(Skin{"s", {3, 1}, {glm::mat4(1), glm::mat4(1)}, -1});
  EXPECT_EQ(skinJointMask(scene), shown);
}

// Joint spheres are sized by the skeleton's extent in steps of 1.25, so a hand moving a
// little (an IK drag) leaves every other joint's sphere exactly as it was: the partial
// redraw then covers the moving arm only (SceneDamageJob compares the matrices bit for bit).
TEST(SkeletonDrawList, ASmallMoveKeepsTheOtherJointsSpheres) {
  std::vector<int> parents = {-1, 0, 1, 2};
  std::vector<glm::mat4> world(4, glm::mat4(1));
  world[1][3] = glm::vec4(0, 1, 0, 1);
  world[2][3] = glm::vec4(0, 1.05f, 0, 1);  // a short bone: its joints' radius is clamped by the size
  world[3][3] = glm::vec4(0.9f, 1.05f, 0, 1);
  SkeletonDrawJob job;
  job.parents = &parents;
  job.world = &world;
  SkeletonDrawList before, after;
  ASSERT_TRUE(job.run(before));
  world[3][3] = glm::vec4(0.9f, 1.08f, 0.02f, 1);  // the tip moves: the bounds' radius changes a little
  ASSERT_TRUE(job.run(after));
  ASSERT_EQ(before.jointMatrices.size(), 4u);
  ASSERT_EQ(after.jointMatrices.size(), 4u);
  for (int j = 0; j < 3; ++j) EXPECT_EQ(before.jointMatrices[j], after.jointMatrices[j]) << "joint " << j;
  EXPECT_NE(before.jointMatrices[3], after.jointMatrices[3]);
  // Joint 1 sits on the 0.05 bone: a tenth of it (0.005) is under the floor of 0.008 x size,
  // size = the bounds radius (about 0.68) taken up to a power of 1.25 (1.25^-1 = 0.8).
  EXPECT_NEAR(before.jointMatrices[1][0][0], 0.008f * 0.8f, 1e-6f);
}

TEST(GridLines, CoverTheReachWithAxesThroughTheOrigin) {
  const std::vector<LineVertex> v = makeGridLines(0.5f, 2.2f);
  // ceil(2.2 / 0.5) = 5 cells each way: 11 lines in each direction, 2 vertices each, + the Y axis.
  ASSERT_EQ(v.size(), 11u * 2u * 2u + 2u);
  int red = 0, blue = 0;
  for (size_t i = 0; i + 3 < v.size(); i += 2) {  // all but the Y axis, last
    EXPECT_NEAR(std::max(std::abs(v[i].position.x), std::abs(v[i].position.z)), 2.5f, 1e-6f);
    if (v[i].color.r > 0.8f) {
      ++red;
      EXPECT_FLOAT_EQ(v[i].position.z, 0.0f);  // the X axis lies at z = 0
    }
    if (v[i].color.b > 0.8f) {
      ++blue;
      EXPECT_FLOAT_EQ(v[i].position.x, 0.0f);
    }
  }
  EXPECT_EQ(red, 1);
  EXPECT_EQ(blue, 1);
  EXPECT_TRUE(makeGridLines(0.0f, 1.0f).empty());
  EXPECT_LE(makeGridLines(1e-9f, 1e9f).size(), 201u * 4u + 2u);  // bounded for absurd inputs
}

}  // namespace
}  // namespace kinema::test
