#pragma once
// Particles drawn by both front ends (kinema render, the editor's viewport): each live
// particle becomes an overlay handle on the depth-tested Scene layer, a camera-facing
// square (quads: `size` file units across, so it shrinks with distance) or a disc (points:
// `size` pixels across), in the system's colour.
#include "render/camera.h"
#include "render/overlay_draw_list.h"
#include "sim/particle_system.h"

namespace kinema {

// The pixel half-width of a quad particle `size` file units across at world point `p`,
// seen by `camera` in a viewport `viewportHeight` pixels high (at least half a pixel, so a
// far particle stays visible).
float particleRadiusPixels(const OrbitCamera& camera, const glm::vec3& p, float size, float viewportHeight);

// Appends one handle per live particle of `state` to `out` (none behind the camera).
void appendParticles(const ParticleSystemSettings& settings, const ParticleState& state, const OrbitCamera& camera,
                     float viewportHeight, OverlayDrawList& out);

}  // namespace kinema
