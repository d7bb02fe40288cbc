#pragma once
#include <glm/glm.hpp>

#include "core/mesh.h"

namespace kinema {

// The default character's body (makeDefaultCharacter's T-pose, metres, Y up, facing +Z) as
// a signed distance: negative inside. A smooth union of tapered capsules and ellipsoids
// placed along the bones, folded about x = 0 so left and right are exact mirrors, cut flat
// at y = 0 under the feet.
double defaultBodySignedDistance(const glm::dvec3& p);

// Grid spacing (metres) makeDefaultBodyMesh polygonises the distance on.
constexpr double kDefaultBodyCellSize = 0.025;

// The body as one closed, outward-wound triangle surface with unit normals from the
// distance's gradient (surface nets on a grid of kDefaultBodyCellSize). Not skinned;
// deterministic, the same triangles on every run and machine.
MeshPrimitive makeDefaultBodyMesh();

}  // namespace kinema
