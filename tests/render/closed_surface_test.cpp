// isClosedOutwardSurface and boxInFrontOfNearPlane (closed_surface.h): when the moving view
// may leave a surface's back faces out. Cases built by hand: a unit cube (12 triangles,
// counter-clockwise seen from outside), the same cube opened, turned inside out, split along
// a texture seam, and the default character's body.
#include <gtest/gtest.h>

#include "render/camera.h"
#include "render/closed_surface.h"
#include "scene/default_character_scene.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

struct Cube {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  Cube() {
    for (int k = 0; k < 8; ++k) positions.push_back(glm::vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
    // Each face's corners counter-clockwise seen from outside (its normal by the right hand).
    const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) indices.insert(indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
  }
};

double signedVolume(const Cube& c) {
  double v = 0;
  for (size_t t = 0; t < c.indices.size(); t += 3)
    v += glm::dot(glm::dvec3(c.positions[c.indices[t]]),
                  glm::cross(glm::dvec3(c.positions[c.indices[t + 1]]), glm::dvec3(c.positions[c.indices[t + 2]]))) /
         6.0;
  return v;
}

TEST(ClosedSurface, AClosedOutwardCubeAndWhatBreaksIt) {
  const Cube cube;
  ASSERT_NEAR(signedVolume(cube), 1.0, 1e-12) << "the test's own cube must be wound outward";
  EXPECT_TRUE(isClosedOutwardSurface(cube.positions, cube.indices));

  Cube open = cube;  // one triangle missing: three edges lose their partner
  open.indices.resize(open.indices.size() - 3);
  EXPECT_FALSE(isClosedOutwardSurface(open.positions, open.indices));

  Cube inside = cube;  // every face wound the other way: closed, but facing in
  for (size_t t = 0; t < inside.indices.size(); t += 3) std::swap(inside.indices[t + 1], inside.indices[t + 2]);
  EXPECT_FALSE(isClosedOutwardSurface(inside.positions, inside.indices));

  Cube flipped = cube;  // one face wound the other way: its edges meet others in the same direction
  std::swap(flipped.indices[1], flipped.indices[2]);
  std::swap(flipped.indices[4], flipped.indices[5]);
  EXPECT_FALSE(isClosedOutwardSurface(flipped.positions, flipped.indices));

  Cube seam = cube;  // the top face on vertices of its own at the same places (a texture seam)
  for (int k = 0; k < 8; ++k) seam.positions.push_back(seam.positions[k]);
  for (size_t t = 18; t < 24; ++t) seam.indices[t] += 8;  // face {2, 6, 7, 3}
  EXPECT_TRUE(isClosedOutwardSurface(seam.positions, seam.indices));

  Cube doubled = cube;  // a face twice: edges met twice in one direction
  doubled.indices.insert(doubled.indices.end(), cube.indices.begin(), cube.indices.begin() + 6);
  EXPECT_FALSE(isClosedOutwardSurface(doubled.positions, doubled.indices));

  Cube bad = cube;
  bad.indices[0] = 99;
  EXPECT_FALSE(isClosedOutwardSurface(bad.positions, bad.indices));
  EXPECT_FALSE(isClosedOutwardSurface(cube.positions, {}));
}

TEST(ClosedSurface, TheDefaultCharactersBodyIsClosed) {
  const Scene scene = makeDefaultCharacterScene();
  ASSERT_FALSE(scene.meshes.empty());
  for (const MeshPrimitive& p : scene.meshes[0].primitives) EXPECT_TRUE(isClosedOutwardSurface(p.positions, p.indices));
}

TEST(ClosedSurface, ABoxIsInFrontOfTheNearPlaneOnlyWhenEveryCornerIs) {
  OrbitCamera camera;
  camera.target = glm::vec3(0.0f);
  camera.distance = 5.0f;
  camera.azimuthDeg = 0.0f;
  camera.elevationDeg = 0.0f;
  camera.fitClipPlanes(2.0f);
  const glm::mat4 vp = camera.projection(1.0f) * camera.view();
  const glm::vec3 eye(glm::inverse(camera.view())[3]);
  EXPECT_TRUE(boxInFrontOfNearPlane(vp, glm::vec3(-1.0f), glm::vec3(1.0f)));
  // Reaching the eye: cut by the near plane.
  EXPECT_FALSE(boxInFrontOfNearPlane(vp, glm::vec3(-1.0f), eye + glm::vec3(0.1f)));
  // Behind the eye.
  const glm::vec3 back = eye + 3.0f * glm::normalize(eye);
  EXPECT_FALSE(boxInFrontOfNearPlane(vp, back - glm::vec3(0.1f), back + glm::vec3(0.1f)));
  // Just in front of the eye but nearer than the near plane.
  const glm::vec3 close = eye - 0.5f * camera.nearPlane * glm::normalize(eye);
  ASSERT_GT(camera.nearPlane, 0.0f);
  EXPECT_FALSE(boxInFrontOfNearPlane(vp, close - glm::vec3(1e-4f), close + glm::vec3(1e-4f)));
}

}  // namespace
}  // namespace kinema
