// One skinning-matrix decomposition (skin/skinning_decomposition.h, issue 17) for the CPU
// dual quaternion job and the GPU's joint texels. Before, the GPU's copy returned the
// identity for a singular matrix and the CPU's orthonormalised its first two columns, so a
// joint scaled to zero along Y deformed differently on the two paths (and sensibly on
// neither). The GPU half of the test is in tests/render/mesh_skinning_gpu_test.cpp.
#include "skin/skinning_decomposition.h"

#include <gtest/gtest.h>

#include <random>

#include "skin/dual_quaternion_skinning.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

void expectMat3Near(const glm::mat3& a, const glm::mat3& e, float tol, const char* what) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(a[c][r], e[c][r], tol) << what << " [" << c << "][" << r << "]";
}

void expectRotation(const glm::mat3& r, const char* what) {
  expectMat3Near(glm::transpose(r) * r, glm::mat3(1.0f), 1e-5f, what);
  EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f) << what;
}

const glm::mat3 kQuarterZ = glm::mat3_cast(glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1)));

TEST(SkinningDecomposition, AJointFlattenedAlongOneAxisKeepsItsRotation) {
  // A = R diag(1, 0, 1): the polar rotation is undefined, the sensible one is R.
  const glm::mat3 r = glm::mat3_cast(glm::normalize(glm::quat(0.9f, 0.1f, -0.3f, 0.2f)));
  const glm::mat3 flat = r * glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0), glm::vec3(0, 0, 1));
  expectMat3Near(nearestRotation(flat), r, 1e-5f, "flattened along Y");
  const glm::mat3 flatX = r * glm::mat3(glm::vec3(0), glm::vec3(0, 2, 0), glm::vec3(0, 0, 3));
  expectMat3Near(nearestRotation(flatX), r, 1e-5f, "flattened along X, scaled");
  // Rank one and zero still give rotations; the zero matrix the identity.
  const glm::mat3 line = r * glm::mat3(glm::vec3(2, 0, 0), glm::vec3(0), glm::vec3(0));
  const glm::mat3 lineRotation = nearestRotation(line);
  expectRotation(lineRotation, "rank one");
  EXPECT_NEAR(glm::dot(lineRotation[0], r[0]), 1.0f, 1e-5f) << "the one direction kept";
  expectMat3Near(nearestRotation(glm::mat3(0.0f)), glm::mat3(1.0f), 0.0f, "zero");
  // The split still reproduces the matrix: R S = A.
  const SkinningDecomposition d = decomposeSkinningMatrix(glm::mat4(flat));
  expectMat3Near(glm::mat3_cast(d.real) * d.stretch, flat, 1e-5f, "R S = A");
}

TEST(SkinningDecomposition, RegularMatricesGiveThePolarRotation) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> scale(0.3f, 3.0f);
  for (int i = 0; i < 50; ++i) {
    const glm::mat3 r = glm::mat3_cast(test::randomRotation(rng));
    const glm::mat3 s(glm::vec3(scale(rng), 0, 0), glm::vec3(0, scale(rng), 0), glm::vec3(0, 0, scale(rng)));
    expectMat3Near(nearestRotation(r * s), r, 1e-4f, "rotation times a stretch");  // A = R S, S symmetric positive
    const glm::mat3 reflected = nearestRotation(r * s * glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)));
    expectRotation(reflected, "a reflection becomes a rotation");
  }
}

// The CPU job on a singular joint: a vertex (1, 1, 0) weighted half and half between joint
// 0 (a quarter turn about Z, flattened along Y: Q diag(1, 0, 1)) and joint 1 (the quarter
// turn Q). Both rotations are Q, the stretch blends to diag(1, 1/2, 1): the vertex goes to
// Q (1, 1/2, 0) = (-1/2, 1, 0). The old CPU split (first two columns) turned joint 0 by a
// half turn about (1, 1, 0) and put the vertex elsewhere.
TEST(SkinningDecomposition, CpuDualQuaternionSkinningOfAFlattenedJoint) {
  const glm::mat3 flat = kQuarterZ * glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0), glm::vec3(0, 0, 1));
  const std::vector<glm::mat4> matrices = {glm::mat4(flat), glm::mat4(kQuarterZ)};
  const std::vector<glm::vec3> positions = {glm::vec3(1, 1, 0), glm::vec3(1, 0, 1)};
  const std::vector<uint16_t> joints = {0, 1, 0, 1};
  const std::vector<float> weights = {0.5f, 0.5f, 0.5f, 0.5f};
  std::vector<glm::vec3> out(2);
  DualQuaternionSkinningJob job;
  job.positions = positions.data();
  job.vertexCount = 2;
  job.influenceJoints = joints.data();
  job.influenceWeights = weights.data();
  job.influencesPerVertex = 2;
  job.jointMatrices = matrices.data();
  job.jointCount = 2;
  job.outPositions = out.data();
  ASSERT_EQ(job.validate(), "");
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(out[0], glm::vec3(-0.5f, 1.0f, 0.0f), 1e-5f);
  EXPECT_VEC3_NEAR(out[1], glm::vec3(0.0f, 1.0f, 1.0f), 1e-5f);
}

}  // namespace
}  // namespace kinema
