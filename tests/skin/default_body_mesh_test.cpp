// The generated default body: a closed, outward-wound, symmetric surface of human size.
#include <algorithm>
#include <cmath>
#include <map>

#include "skin/default_body_mesh.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

const MeshPrimitive& body() {
  static const MeshPrimitive mesh = makeDefaultBodyMesh();
  return mesh;
}

double signedVolume(const MeshPrimitive& m) {
  double v = 0.0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]), c(m.positions[m.indices[t + 2]]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

TEST(DefaultBodyMesh, TriangleCountIsAFewThousand) {
  const MeshPrimitive& m = body();
  ASSERT_EQ(m.indices.size() % 3, 0u);
  const size_t triangles = m.indices.size() / 3;
  EXPECT_GE(triangles, 2000u);
  EXPECT_LE(triangles, 8000u);
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
  EXPECT_FALSE(m.skinned());
}

// Closed and consistently wound: every directed edge once, and its reverse once.
TEST(DefaultBodyMesh, IsClosedWithEveryEdgeSharedByTwoTriangles) {
  const MeshPrimitive& m = body();
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = m.indices[t + k], b = m.indices[t + (k + 1) % 3];
      ASSERT_NE(a, b) << "degenerate triangle " << t / 3;
      ++directed[{a, b}];
    }
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used twice the same way";
    const auto reverse = directed.find({edge.second, edge.first});
    ASSERT_TRUE(reverse != directed.end()) << "edge " << edge.first << "-" << edge.second << " is on a hole";
  }
  // Euler characteristic of closed surfaces: V - E + F = 2 per sphere-like part.
  const long v = static_cast<long>(m.positions.size()), e = static_cast<long>(directed.size() / 2),
             f = static_cast<long>(m.indices.size() / 3);
  EXPECT_EQ(v - e + f, 2) << "one closed surface of genus 0";
}

// Outward winding gives a positive volume. A 1.80 m person of 45 to 90 kg at about the
// density of water has 0.045 to 0.09 m^3; and the polygon must hold what the distance
// field holds: counted on a finer (1 cm) grid, independent of the surface nets.
TEST(DefaultBodyMesh, VolumeIsPositiveAndHuman) {
  const double volume = signedVolume(body());
  EXPECT_GT(volume, 0.045);
  EXPECT_LT(volume, 0.09);
  const double h = 0.01;
  long insideCells = 0;
  for (double z = -0.2 + h / 2; z < 0.3; z += h)
    for (double y = h / 2; y < 1.85; y += h)
      for (double x = -1.0 + h / 2; x < 1.0; x += h) insideCells += defaultBodySignedDistance({x, y, z}) < 0.0;
  EXPECT_NEAR(volume, insideCells * h * h * h, 0.04 * volume);
}

TEST(DefaultBodyMesh, NormalsAreUnitAndPointOutward) {
  const MeshPrimitive& m = body();
  std::vector<glm::dvec3> faceSum(m.positions.size(), glm::dvec3(0.0));
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]), c(m.positions[m.indices[t + 2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);  // area-weighted, outward for outward winding
    for (int k = 0; k < 3; ++k) faceSum[m.indices[t + k]] += n;
  }
  for (int v = 0; v < m.vertexCount(); ++v) {
    ASSERT_NEAR(glm::length(m.normals[v]), 1.0f, 1e-4f) << "vertex " << v;
    EXPECT_GT(glm::dot(glm::dvec3(m.normals[v]), glm::normalize(faceSum[v])), 0.0) << "vertex " << v << " normal points in";
  }
}

TEST(DefaultBodyMesh, StandsOnTheGroundAndIsOneEightyTall) {
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& p : body().positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  EXPECT_NEAR(lo.y, 0.0f, 0.005f);
  EXPECT_GE(lo.y, 0.0f);
  EXPECT_NEAR(hi.y, 1.80f, 0.015f);
  // Arms out in the T-pose: fingertips at |x| = 0.89; feet reach forward (+Z).
  EXPECT_NEAR(hi.x, 0.89f, 0.03f);
  EXPECT_NEAR(lo.x, -hi.x, 1e-4f);
  EXPECT_GT(hi.z, 0.15f);
  EXPECT_LT(lo.z, -0.05f);
}

TEST(DefaultBodyMesh, MirrorsAcrossTheYZPlane) {
  const MeshPrimitive& m = body();
  // Every vertex has a mirror image among the vertices (a sorted sweep on y).
  std::vector<glm::vec3> sorted = m.positions;
  std::sort(sorted.begin(), sorted.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.y < b.y; });
  const float tol = 1e-4f;
  for (const glm::vec3& p : m.positions) {
    const glm::vec3 mirror(-p.x, p.y, p.z);
    auto it = std::lower_bound(sorted.begin(), sorted.end(), mirror.y - tol,
                               [](const glm::vec3& a, float y) { return a.y < y; });
    bool found = false;
    for (; it != sorted.end() && it->y <= mirror.y + tol && !found; ++it) found = glm::distance(*it, mirror) < tol;
    EXPECT_TRUE(found) << "no mirror image of (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
}

// Elbows and knees bend well only with several rings of vertices across the joint: no
// edge within 8 cm of them longer than 4.5 cm (the grid is 2.5 cm), most much shorter.
TEST(DefaultBodyMesh, EdgesAreShortAcrossElbowsAndKnees) {
  const MeshPrimitive& m = body();
  const glm::vec3 joints[] = {{0.45f, 1.45f, 0.0f}, {-0.45f, 1.45f, 0.0f}, {0.09f, 0.50f, 0.01f}, {-0.09f, 0.50f, 0.01f}};
  for (const glm::vec3& joint : joints) {
    float longest = 0.0f, total = 0.0f;
    int edges = 0;
    for (size_t t = 0; t < m.indices.size(); t += 3)
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 a = m.positions[m.indices[t + k]], b = m.positions[m.indices[t + (k + 1) % 3]];
        if (glm::distance(0.5f * (a + b), joint) > 0.08f) continue;
        longest = std::max(longest, glm::distance(a, b));
        total += glm::distance(a, b);
        ++edges;
      }
    EXPECT_GT(edges, 100) << "near " << joint.x << ", " << joint.y;
    EXPECT_LT(longest, 0.045f) << "near " << joint.x << ", " << joint.y;
    EXPECT_LT(total / std::max(edges, 1), 0.03f) << "near " << joint.x << ", " << joint.y;
  }
}

TEST(DefaultBodyMesh, IsTheSameOnEveryCall) {
  const MeshPrimitive again = makeDefaultBodyMesh();
  EXPECT_EQ(again.positions, body().positions);
  EXPECT_EQ(again.normals, body().normals);
  EXPECT_EQ(again.indices, body().indices);
}

}  // namespace
}  // namespace kinema::test
