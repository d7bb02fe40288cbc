// Free-form deformation (Sederberg & Parry 1986) against closed forms: Bernstein bases against
// C(n,i)(1-t)^(n-i)t^i in double, partition of unity and linear precision, an undisturbed lattice
// leaving points in place, an affine map of the control points moving points by the same map.
#include "deform/ffd_lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "deform/bernstein.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

TEST(Bernstein, MatchesTheClosedFormSumsToOneAndReproducesLines) {
  float b[kMaxBernsteinDegree + 1];
  for (int n = 0; n <= kMaxBernsteinDegree; ++n)
    for (double t : {0.0, 0.05, 0.25, 0.5, 0.61, 0.9, 1.0}) {
      bernsteinBasis(n, static_cast<float>(t), b);
      double sum = 0.0, mean = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double expected = binomial(n, i) * std::pow(1.0 - t, n - i) * std::pow(t, i);
        EXPECT_NEAR(b[i], expected, 2e-7) << "n=" << n << " i=" << i << " t=" << t;
        EXPECT_GE(b[i], 0.0f);
        sum += b[i];
        mean += b[i] * (n > 0 ? double(i) / n : t);
      }
      EXPECT_NEAR(sum, 1.0, 1e-6) << "n=" << n << " t=" << t;
      EXPECT_NEAR(mean, t, 1e-6) << "n=" << n << " t=" << t;  // linear precision
    }
}

FfdLattice skewedLattice(int nx, int ny, int nz) {
  const int counts[3] = {nx, ny, nz};
  const glm::vec3 axes[3] = {{1.2f, 0.1f, 0.0f}, {-0.2f, 0.9f, 0.3f}, {0.0f, 0.2f, 0.7f}};
  return makeLattice(counts, glm::vec3(-0.4f, 0.1f, 0.25f), axes);
}

std::vector<glm::vec3> pointsInside(const FfdLattice& l, int n, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec3> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(l.origin + u(rng) * l.axes[0] + u(rng) * l.axes[1] + u(rng) * l.axes[2]);
  return pts;
}

TEST(FfdLattice, AnUndisturbedLatticeReproducesEveryPoint) {
  std::mt19937 rng(7);
  for (int n : {2, 3, 4, 8}) {
    const FfdLattice l = skewedLattice(n, n == 8 ? 3 : n, n == 2 ? 5 : n);
    ASSERT_EQ(l.validate(), "");
    std::vector<glm::vec3> pts = pointsInside(l, 500, rng);
    // And points outside: they move by the boundary's displacement, zero here.
    pts.push_back(l.origin - 3.0f * l.axes[0]);
    pts.push_back(l.origin + 2.5f * l.axes[1] + 4.0f * l.axes[2]);
    std::vector<glm::vec3> out(pts.size());
    FfdJob job;
    job.lattice = &l;
    job.positions = pts.data();
    job.count = static_cast<int>(pts.size());
    job.outPositions = out.data();
    ASSERT_EQ(job.validate(), "");
    ASSERT_TRUE(job.run());
    for (size_t i = 0; i < pts.size(); ++i) {
      EXPECT_VEC3_NEAR(out[i], pts[i], 1e-6f);
      if (i < 500) EXPECT_VEC3_NEAR(evaluateLattice(l, latticeCoordinates(l, pts[i])), pts[i], 2e-6f);
    }
  }
}

TEST(FfdLattice, AnAffineMapOfTheControlPointsMovesPointsByThatMap) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    FfdLattice l = skewedLattice(2 + trial % 7, 2 + (trial * 3) % 7, 2 + (trial * 5) % 7);
    // A random affine map: well-conditioned linear part plus a translation.
    glm::mat3 a(1.0f);
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) a[c][r] += 0.4f * u(rng);
    const glm::vec3 shift(u(rng), u(rng), u(rng));
    for (glm::vec3& p : l.points) p = a * p + shift;
    const std::vector<glm::vec3> pts = pointsInside(l, 200, rng);
    std::vector<glm::vec3> out(pts.size());
    FfdJob job;
    job.lattice = &l;
    job.positions = pts.data();
    job.count = static_cast<int>(pts.size());
    job.outPositions = out.data();
    ASSERT_TRUE(job.run());
    for (size_t i = 0; i < pts.size(); ++i) EXPECT_VEC3_NEAR(out[i], a * pts[i] + shift, 2e-5f);
  }
}

// The job's displacement form equals the plain Bernstein sum inside the box.
TEST(FfdLattice, TheJobEqualsTheBernsteinSumOnARandomLattice) {
  std::mt19937 rng(3);
  std::normal_distribution<float> jitter(0.0f, 0.15f);
  FfdLattice l = skewedLattice(4, 3, 5);
  for (glm::vec3& p : l.points) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
  const std::vector<glm::vec3> pts = pointsInside(l, 300, rng);
  std::vector<glm::vec3> out(pts.size());
  FfdJob job;
  job.lattice = &l;
  job.positions = pts.data();
  job.count = static_cast<int>(pts.size());
  job.outPositions = out.data();
  ASSERT_TRUE(job.run());
  for (size_t i = 0; i < pts.size(); ++i)
    EXPECT_VEC3_NEAR(out[i], evaluateLattice(l, latticeCoordinates(l, pts[i])), 2e-6f);
  // Moving one corner point moves a point at that corner by the same amount, the others not.
  FfdLattice one = skewedLattice(3, 3, 3);
  const glm::vec3 move(0.1f, -0.2f, 0.3f);
  one.points[one.index(2, 0, 2)] += move;
  // At a corner of the box every basis is 0 or 1: only that control point counts there.
  const glm::vec3 corner = one.restPoint(2, 0, 2);
  const glm::vec3 farCorner = one.restPoint(0, 2, 0);
  glm::vec3 io[2] = {corner, farCorner};
  job.lattice = &one;
  job.positions = io;
  job.count = 2;
  job.outPositions = io;  // in place
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(io[0], corner + move, 1e-6f);
  EXPECT_VEC3_NEAR(io[1], farCorner, 1e-6f);
}

TEST(FfdLattice, OutsidePointsMoveByTheBoundarysDisplacementAndWeightsBlend) {
  FfdLattice l = skewedLattice(3, 3, 3);
  const glm::vec3 lift(0.0f, 0.5f, 0.0f);
  for (glm::vec3& p : l.points) p += lift;  // a translation: every point inside moves by it
  // Outside, the clamped coordinates see the same translation.
  const glm::vec3 far = l.origin + 5.0f * l.axes[0] - 2.0f * l.axes[2];
  const glm::vec3 inside = l.origin + 0.5f * (l.axes[0] + l.axes[1] + l.axes[2]);
  const glm::vec3 in[2] = {far, inside};
  const float weights[2] = {1.0f, 0.25f};
  glm::vec3 out[2];
  FfdJob job;
  job.lattice = &l;
  job.positions = in;
  job.count = 2;
  job.weights = weights;
  job.outPositions = out;
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(out[0], far + lift, 1e-5f);
  EXPECT_VEC3_NEAR(out[1], inside + 0.25f * lift, 1e-5f);
}

// A lattice parented to a joint: deforming in the moved frame equals moving the deformed rest.
TEST(FfdLattice, AFrameMovesTheLatticeRigidlyWithItsPoints) {
  std::mt19937 rng(5);
  std::normal_distribution<float> jitter(0.0f, 0.1f);
  FfdLattice l = skewedLattice(3, 4, 2);
  for (glm::vec3& p : l.points) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
  const std::vector<glm::vec3> rest = pointsInside(l, 100, rng);
  const glm::mat4 frame = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, -3)) *
                          glm::mat4_cast(glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3))));
  std::vector<glm::vec3> restOut(rest.size()), moved(rest.size()), movedOut(rest.size());
  for (size_t i = 0; i < rest.size(); ++i) moved[i] = glm::vec3(frame * glm::vec4(rest[i], 1.0f));
  FfdJob job;
  job.lattice = &l;
  job.count = static_cast<int>(rest.size());
  job.positions = rest.data();
  job.outPositions = restOut.data();
  ASSERT_TRUE(job.run());
  job.positions = moved.data();
  job.outPositions = movedOut.data();
  job.frame = frame;
  ASSERT_TRUE(job.run());
  for (size_t i = 0; i < rest.size(); ++i)
    EXPECT_VEC3_NEAR(movedOut[i], glm::vec3(frame * glm::vec4(restOut[i], 1.0f)), 1e-5f);
}

TEST(FfdLattice, FitsAroundTheSelectionAndRefusesBadLattices) {
  const std::vector<glm::vec3> pts = {{0, 0, 0}, {2, 1, 0}, {1, 3, 0}, {50, 50, 50}};
  const int counts[3] = {4, 4, 4};
  const FfdLattice l = fitLattice(pts, {0, 1, 2}, counts, 0.1f);
  ASSERT_EQ(l.validate(), "");
  // Box (0,0,0)-(2,3,0) padded by 0.3 on each side; the flat z side still has volume.
  EXPECT_VEC3_NEAR(l.origin, glm::vec3(-0.3f, -0.3f, -0.3f), 1e-6f);
  EXPECT_NEAR(l.axes[0].x, 2.6f, 1e-6f);
  EXPECT_NEAR(l.axes[1].y, 3.6f, 1e-6f);
  EXPECT_NEAR(l.axes[2].z, 0.6f, 1e-6f);
  for (int v = 0; v < 3; ++v) {
    const glm::vec3 stu = latticeCoordinates(l, pts[v]);
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT(stu[a], 0.0f);
      EXPECT_LT(stu[a], 1.0f);
    }
  }
  FfdLattice bad = l;
  bad.counts[1] = 9;
  EXPECT_NE(bad.validate().find("2 to 8"), std::string::npos);
  bad = l;
  bad.points.pop_back();
  EXPECT_NE(bad.validate().find("points"), std::string::npos);
  bad = l;
  bad.axes[2] = bad.axes[0];
  EXPECT_NE(bad.validate().find("flat"), std::string::npos);
  bad = l;
  bad.points[5].y = std::nanf("");
  EXPECT_NE(bad.validate().find("point 5"), std::string::npos);
  FfdJob job;
  job.lattice = &bad;
  EXPECT_FALSE(job.run());
}

}  // namespace
}  // namespace kinema
