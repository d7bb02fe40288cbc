// LinearBlendSkinningJob: hand-derived cases, validate(), and the SIMD loops against the
// double-precision scalar reference on random rigs (every stride, rigid and general).
#include "skin/linear_blend_skinning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "skin/skinning_matrices.h"
#include "skin/skinning_reference.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::propertyCases;

struct Buffers {
  std::vector<glm::vec3> positions, normals, outPositions, outNormals;
  std::vector<uint16_t> joints;
  std::vector<float> weights;
  std::vector<glm::mat4> matrices;

  LinearBlendSkinningJob job(int stride) {
    outPositions.assign(positions.size(), glm::vec3(-7.0f));
    outNormals.assign(normals.size(), glm::vec3(-7.0f));
    LinearBlendSkinningJob j;
    j.positions = positions.data();
    j.normals = normals.empty() ? nullptr : normals.data();
    j.vertexCount = static_cast<int>(positions.size());
    j.influenceJoints = joints.data();
    j.influenceWeights = weights.data();
    j.influencesPerVertex = stride;
    j.jointMatrices = matrices.data();
    j.jointCount = static_cast<int>(matrices.size());
    j.outPositions = outPositions.data();
    j.outNormals = normals.empty() ? nullptr : outNormals.data();
    return j;
  }
};

// Joint 0 sits at the origin, joint 1 at the pivot (1, 0, 0); both bind with identity
// rotation, so IBM_0 = I and IBM_1 = T(-1, 0, 0). Joint 1 turns a quarter about Z:
// world_1 = T(1,0,0) Rz(90), M_1 = T(1,0,0) Rz(90) T(-1,0,0), M_0 = I.
// The vertex (2, 0, 0), weighted 50/50:
//   M_0 p = (2, 0, 0);  M_1 p = (1,0,0) + Rz(90) (1, 0, 0) = (1, 1, 0)
//   p' = 0.5 (2, 0, 0) + 0.5 (1, 1, 0) = (1.5, 0.5, 0).
// Its normal (0, 1, 0): M_0 keeps it, Rz(90) turns it to (-1, 0, 0); the blend
// (-0.5, 0.5, 0) normalised is (-1, 1, 0) / sqrt(2).
TEST(LinearBlendSkinning, TwoJointsHalfWeightsQuarterTurn) {
  Skin skin;
  skin.joints = {0, 1};
  skin.inverseBind = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(-1, 0, 0))};
  const std::vector<glm::mat4> world = {
      glm::mat4(1.0f), glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)), glm::radians(90.0f),
                                   glm::vec3(0, 0, 1))};
  Buffers b;
  computeSkinningMatrices(skin, world, b.matrices);
  b.positions = {{2, 0, 0}, {0.5f, 0, 0}, {1, 0, 0}};
  b.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  b.joints = {0, 1, 0, 1, 1, 0};
  b.weights = {0.5f, 0.5f, 1.0f, 0.0f, 0.5f, 0.5f};
  ASSERT_TRUE(b.job(2).run());
  EXPECT_VEC3_NEAR(b.outPositions[0], glm::vec3(1.5f, 0.5f, 0.0f), 1e-6f);
  EXPECT_VEC3_NEAR(b.outNormals[0], glm::vec3(-1, 1, 0) / std::sqrt(2.0f), 1e-6f);
  // Fully on joint 0: does not move.
  EXPECT_VEC3_NEAR(b.outPositions[1], glm::vec3(0.5f, 0, 0), 1e-6f);
  // The pivot itself: both matrices fix it.
  EXPECT_VEC3_NEAR(b.outPositions[2], glm::vec3(1, 0, 0), 1e-6f);
}

// Normals use the inverse transpose. M = scale(2, 1, 1) stretches the plane x + y = 1
// (normal (1, 1, 0)/sqrt2) into x/2 + y = 1, whose normal is (1/2, 1, 0) -> (1, 2, 0)/sqrt5.
// Two joints scale(2,1,1) and scale(1,4,1) at 50/50: invT gives (1/2, 1, 0) and (1, 1/4, 0)
// (times 1/sqrt2), summing to (3/2, 5/4, 0)/2 -> (6, 5, 0)/sqrt61. (Blending the matrices
// first, diag(3/2, 5/2, 1), would give (2/3, 2/5) ~ (5, 3): the per-joint order matters.)
TEST(LinearBlendSkinning, NormalsUseInverseTransposeUnderNonUniformScale) {
  Buffers b;
  b.matrices = {glm::scale(glm::mat4(1.0f), glm::vec3(2, 1, 1)), glm::scale(glm::mat4(1.0f), glm::vec3(1, 4, 1))};
  const glm::vec3 n = glm::vec3(1, 1, 0) / std::sqrt(2.0f);
  b.positions = {{0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}};
  b.normals = {n, n};
  b.joints = {0, 1, 0, 1};
  b.weights = {1.0f, 0.0f, 0.5f, 0.5f};
  ASSERT_TRUE(b.job(2).run());
  EXPECT_VEC3_NEAR(b.outPositions[0], glm::vec3(1.0f, 0.5f, 0), 1e-6f);
  EXPECT_VEC3_NEAR(b.outNormals[0], glm::vec3(1, 2, 0) / std::sqrt(5.0f), 1e-6f);
  // 0.5 (1, 0.5, 0) + 0.5 (0.5, 2, 0) = (0.75, 1.25, 0)
  EXPECT_VEC3_NEAR(b.outPositions[1], glm::vec3(0.75f, 1.25f, 0), 1e-6f);
  EXPECT_VEC3_NEAR(b.outNormals[1], glm::vec3(6, 5, 0) / std::sqrt(61.0f), 1e-6f);
}

// A uniformly scaled rig (every matrix a rotation times the same s) takes the shortcut
// that skips inverse transposes; normals must still come out unit and right.
TEST(LinearBlendSkinning, UniformScaleRigNormals) {
  Buffers b;
  b.matrices = {glm::scale(glm::mat4(1.0f), glm::vec3(0.01f)),
                glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1)) * 0.01f};
  b.matrices[1][3][3] = 1.0f;
  b.positions = {{1, 0, 0}};
  b.normals = {{0, 1, 0}};
  b.joints = {0, 1};
  b.weights = {0.5f, 0.5f};
  ASSERT_TRUE(b.job(2).run());
  EXPECT_VEC3_NEAR(b.outPositions[0], glm::vec3(0.005f, 0.005f, 0), 1e-8f);
  EXPECT_VEC3_NEAR(b.outNormals[0], glm::vec3(-1, 1, 0) / std::sqrt(2.0f), 1e-6f);
}

// Rigid binding (one influence of weight 1) applies the joint's matrix exactly, as glm does,
// on both loops.
TEST(LinearBlendSkinning, RigidBindingEqualsJointMatrixExactly) {
  std::mt19937 rng(7);
  Buffers b;
  for (int j = 0; j < 5; ++j) b.matrices.push_back(test::randomAffine(rng));
  for (int v = 0; v < 200; ++v) {
    b.positions.push_back(test::randomPoint(rng, 3.0f));
    b.joints.push_back(static_cast<uint16_t>(v % 5));
    b.weights.push_back(1.0f);
  }
  for (const bool avx2 : {true, false}) {
    LinearBlendSkinningJob j = b.job(1);
    j.allowAvx2 = avx2;
    ASSERT_TRUE(j.run());
    for (int v = 0; v < 200; ++v) {
      const glm::vec3 expected(b.matrices[v % 5] * glm::vec4(b.positions[v], 1.0f));
      ASSERT_EQ(b.outPositions[v], expected) << "vertex " << v << (avx2 ? " avx2" : " sse2");
    }
  }
}

TEST(LinearBlendSkinning, ValidateNamesWhatIsWrong) {
  Buffers b;
  b.matrices = {glm::mat4(1.0f), glm::mat4(1.0f)};
  b.positions = {{1, 2, 3}, {4, 5, 6}};
  b.normals = {{0, 1, 0}, {0, 1, 0}};
  b.joints = {0, 1, 1, 0};
  b.weights = {0.5f, 0.5f, 0.5f, 0.5f};
  EXPECT_EQ(b.job(2).validate(), "");

  LinearBlendSkinningJob j = b.job(2);
  j.positions = nullptr;
  EXPECT_NE(j.validate().find("positions"), std::string::npos);
  j = b.job(2);
  j.outPositions = nullptr;
  EXPECT_NE(j.validate().find("outPositions"), std::string::npos);
  j = b.job(2);
  j.influencesPerVertex = 0;
  EXPECT_NE(j.validate().find("influencesPerVertex"), std::string::npos);
  j.influencesPerVertex = kMaxInfluences + 1;
  EXPECT_NE(j.validate().find("influencesPerVertex"), std::string::npos);
  j = b.job(2);
  j.outNormals = nullptr;
  EXPECT_NE(j.validate().find("outNormals"), std::string::npos);
  j = b.job(2);
  j.normals = nullptr;
  EXPECT_NE(j.validate().find("normals is null"), std::string::npos);
  j = b.job(2);
  j.jointCount = 1;  // vertex 0's second influence uses joint 1
  EXPECT_NE(j.validate().find("vertex 0 influence 1 uses joint 1"), std::string::npos) << j.validate();
  j = b.job(2);
  j.vertexCount = -1;
  EXPECT_NE(j.validate().find("vertexCount"), std::string::npos);

  b.matrices[1][2][1] = std::nanf("");
  j = b.job(2);
  EXPECT_NE(j.validate().find("joint matrix 1 is not finite"), std::string::npos) << j.validate();
  // run() refuses and leaves the outputs untouched.
  EXPECT_FALSE(j.run());
  EXPECT_EQ(b.outPositions[0], glm::vec3(-7.0f));
  EXPECT_EQ(b.outNormals[1], glm::vec3(-7.0f));

  // No vertices: nothing to check, nothing to do.
  LinearBlendSkinningJob empty;
  empty.vertexCount = 0;
  EXPECT_EQ(empty.validate(), "");
  EXPECT_TRUE(empty.run());
}

// The SIMD loops (strides 1..8, with and without normals, the uniform-scale shortcut and
// the per-joint normal matrices) against the double-precision reference: within 1e-6 of
// the size of the terms summed (float rounding of a handful of products and sums).
// allowAvx2 false forces the SSE2 loop; normalize false checks the unnormalised sum. An odd
// vertex count now and then runs the AVX2 loop's single-vertex tail after its pairs.
void checkAgainstReference(std::mt19937& rng, int stride, bool rigid, bool normals, bool allowAvx2 = true,
                           bool normalize = true) {
  Buffers b;
  const int joints = 12, vertices = 63 + static_cast<int>(rng() % 2);
  const float scale = rigid ? std::uniform_real_distribution<float>(0.01f, 3.0f)(rng) : 1.0f;
  for (int j = 0; j < joints; ++j)
    b.matrices.push_back(rigid ? test::randomSimilarity(rng, scale) : test::randomAffine(rng));
  std::vector<float> w(stride);
  for (int v = 0; v < vertices; ++v) {
    b.positions.push_back(test::randomPoint(rng, 2.0f));
    if (normals) b.normals.push_back(glm::normalize(test::randomPoint(rng, 1.0f) + glm::vec3(0, 0, 1e-3f)));
    test::randomWeights(rng, stride, w.data());
    for (int k = 0; k < stride; ++k) {
      b.joints.push_back(static_cast<uint16_t>(rng() % joints));
      b.weights.push_back(w[k]);
    }
  }
  LinearBlendSkinningJob job = b.job(stride);
  job.allowAvx2 = allowAvx2;
  job.normalizeNormals = normalize;
  ASSERT_TRUE(job.run());
  for (int v = 0; v < vertices; ++v) {
    const test::ReferenceSkinned r =
        test::referenceLinearBlend(b.positions[v], normals ? b.normals[v] : glm::vec3(0, 0, 1), &b.joints[v * stride],
                                   &b.weights[v * stride], stride, b.matrices.data());
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(b.outPositions[v][c], r.position[c], 1e-6 * r.positionScale)
          << "stride " << stride << (rigid ? " rigid" : " general") << " vertex " << v;
    if (!normals) continue;
    if (!normalize) {
      // sum_i w_i invT(M_i) n itself, also under the shared-similarity shortcut (which
      // blends M_i = s^2 invT(M_i) and must divide by s^2).
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(b.outNormals[v][c], r.normalSum[c], 2e-6 * r.normalScale)
            << "stride " << stride << (rigid ? " rigid" : " general") << " unnormalised normal " << v;
      continue;
    }
    // Normalising divides by |sum|: compare the unnormalised directions at their own scale.
    const double len = glm::length(r.normalSum);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(b.outNormals[v][c] * len, r.normalSum[c], 2e-6 * r.normalScale)
          << "stride " << stride << (rigid ? " rigid" : " general") << " normal " << v;
    ASSERT_NEAR(glm::length(b.outNormals[v]), 1.0f, 1e-6f);
  }
}

TEST(LinearBlendSkinning, SimdLoopsMatchScalarReference) {
  std::mt19937 rng(2024);
  const int cases = propertyCases(300);
  for (int c = 0; c < cases; ++c) {
    const int stride = 1 + c % kMaxInfluences;
    checkAgainstReference(rng, stride, (c / kMaxInfluences) % 2 == 0, (c / (2 * kMaxInfluences)) % 3 != 0);
    if (HasFatalFailure()) return;
  }
}

// The same property on the SSE2 loop (on a CPU with AVX2 + FMA the default run above takes
// the AVX2 loop; on one without, both tests run the SSE2 loop).
TEST(LinearBlendSkinning, Sse2LoopMatchesScalarReference) {
  std::mt19937 rng(2025);
  const int cases = propertyCases(300);
  for (int c = 0; c < cases; ++c) {
    const int stride = 1 + c % kMaxInfluences;
    checkAgainstReference(rng, stride, (c / kMaxInfluences) % 2 == 0, (c / (2 * kMaxInfluences)) % 3 != 0, false);
    if (HasFatalFailure()) return;
  }
}

// normalizeNormals = false: the normals are the weighted sum of inverse-transposed joint
// matrices applied to n, unnormalised, on both loops, rigid (shortcut) and general rigs.
TEST(LinearBlendSkinning, UnnormalizedNormalsMatchReferenceSum) {
  std::mt19937 rng(2026);
  const int cases = propertyCases(200);
  for (int c = 0; c < cases; ++c) {
    const int stride = 1 + c % kMaxInfluences;
    checkAgainstReference(rng, stride, (c / kMaxInfluences) % 2 == 0, true, (c / (2 * kMaxInfluences)) % 2 == 0,
                          false);
    if (HasFatalFailure()) return;
  }
}

// Hand case for the shortcut's 1/s^2: M = 2 I (uniform scale 2, shared by the one joint)
// has invT(M) = I / 2, so the unnormalised normal (0, 0, 1) comes out (0, 0, 0.5).
TEST(LinearBlendSkinning, UnnormalizedNormalUnderUniformScaleIsHalved) {
  for (const bool avx2 : {true, false}) {
    Buffers b;
    b.matrices = {glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))};
    b.positions = {{1, 2, 3}, {0, 0, 1}, {1, 0, 0}};
    b.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    b.joints = {0, 0, 0};
    b.weights = {1, 1, 1};
    LinearBlendSkinningJob j = b.job(1);
    j.normalizeNormals = false;
    j.allowAvx2 = avx2;
    ASSERT_TRUE(j.run());
    EXPECT_EQ(b.outPositions[0], glm::vec3(2, 4, 6));
    EXPECT_EQ(b.outNormals[0], glm::vec3(0, 0, 0.5f)) << (avx2 ? "avx2" : "sse2");
    EXPECT_EQ(b.outNormals[1], glm::vec3(0, 0.5f, 0));
    EXPECT_EQ(b.outNormals[2], glm::vec3(0.5f, 0, 0));
  }
}

// Writing the outputs over the inputs works: each vertex is read before it is written (33
// vertices: the AVX2 loop's pairs and its tail), on both loops.
TEST(LinearBlendSkinning, InPlaceMatchesSeparateOutputs) {
  std::mt19937 rng(11);
  Buffers b;
  for (int j = 0; j < 4; ++j) b.matrices.push_back(test::randomAffine(rng));
  std::vector<float> w(4);
  for (int v = 0; v < 33; ++v) {
    b.positions.push_back(test::randomPoint(rng, 1.0f));
    b.normals.push_back(glm::normalize(test::randomPoint(rng, 1.0f) + glm::vec3(0, 0, 2)));
    test::randomWeights(rng, 4, w.data());
    for (int k = 0; k < 4; ++k) {
      b.joints.push_back(static_cast<uint16_t>(k));
      b.weights.push_back(w[k]);
    }
  }
  const std::vector<glm::vec3> positions = b.positions, normals = b.normals;
  for (const bool avx2 : {true, false}) {
    b.positions = positions;
    b.normals = normals;
    LinearBlendSkinningJob separate = b.job(4);
    separate.allowAvx2 = avx2;
    ASSERT_TRUE(separate.run());
    const std::vector<glm::vec3> expectedP = b.outPositions, expectedN = b.outNormals;
    LinearBlendSkinningJob j = b.job(4);
    j.allowAvx2 = avx2;
    j.outPositions = b.positions.data();
    j.outNormals = b.normals.data();
    ASSERT_TRUE(j.run());
    EXPECT_EQ(b.positions, expectedP) << (avx2 ? "avx2" : "sse2");
    EXPECT_EQ(b.normals, expectedN) << (avx2 ? "avx2" : "sse2");
  }
}

// influenceStride: reading the first 3 of every 8 entries (MeshPrimitive's layout) gives
// exactly what the same influences packed 3 per vertex give; the other 5 are never read.
TEST(LinearBlendSkinning, InfluenceStrideSkipsUnusedSlots) {
  std::mt19937 rng(3);
  Buffers packed, wide;
  for (int j = 0; j < 6; ++j) packed.matrices.push_back(test::randomAffine(rng));
  wide.matrices = packed.matrices;
  std::vector<float> w(3);
  for (int v = 0; v < 50; ++v) {
    packed.positions.push_back(test::randomPoint(rng, 1.0f));
    packed.normals.push_back(glm::normalize(test::randomPoint(rng, 1.0f) + glm::vec3(2, 0, 0)));
    test::randomWeights(rng, 3, w.data());
    for (int k = 0; k < 8; ++k) {
      const uint16_t joint = static_cast<uint16_t>(rng() % 6);
      if (k < 3) {
        packed.joints.push_back(joint);
        packed.weights.push_back(w[k]);
      }
      wide.joints.push_back(k < 3 ? joint : 999);  // past the matrices: must not be read
      wide.weights.push_back(k < 3 ? w[k] : std::nanf(""));
    }
  }
  wide.positions = packed.positions;
  wide.normals = packed.normals;
  ASSERT_TRUE(packed.job(3).run());
  LinearBlendSkinningJob j = wide.job(3);
  j.influenceStride = 8;
  EXPECT_EQ(j.validate(), "");
  ASSERT_TRUE(j.run());
  EXPECT_EQ(wide.outPositions, packed.outPositions);
  EXPECT_EQ(wide.outNormals, packed.outNormals);
  j.influenceStride = 2;
  EXPECT_NE(j.validate().find("influenceStride 2 is smaller than influencesPerVertex 3"), std::string::npos);
  j.influenceStride = 8;
  wide.joints[8 + 2] = 6;  // vertex 1, influence 2: one past the matrices
  EXPECT_NE(j.validate().find("vertex 1 influence 2 uses joint 6"), std::string::npos) << j.validate();
}

TEST(SkinningMatrices, WorldTimesInverseBind) {
  Skin skin;
  skin.joints = {2, 0};
  skin.inverseBind = {glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0)), glm::scale(glm::mat4(1.0f), glm::vec3(2))};
  const std::vector<glm::mat4> world = {glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0)), glm::mat4(3.0f),
                                        glm::rotate(glm::mat4(1.0f), 1.0f, glm::vec3(0, 1, 0))};
  std::vector<glm::mat4> out;
  computeSkinningMatrices(skin, world, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], world[2] * skin.inverseBind[0]);
  EXPECT_EQ(out[1], world[0] * skin.inverseBind[1]);
  // (5, 0, 0) + 2 * (1, 1, 1)
  EXPECT_VEC3_NEAR(glm::vec3(out[1] * glm::vec4(1, 1, 1, 1)), glm::vec3(7, 2, 2), 1e-6f);
}

}  // namespace
}  // namespace kinema
