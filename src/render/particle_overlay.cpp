#include "render/particle_overlay.h"

#include <algorithm>
#include <cmath>

namespace kinema {

float particleRadiusPixels(const OrbitCamera& camera, const glm::vec3& p, float size, float viewportHeight) {
  const float tanHalf = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
  // World units the viewport's half-height spans at the particle's depth.
  const float depth = camera.orthographic ? camera.distance : glm::dot(p - camera.eye(), camera.forward());
  const float halfHeight = depth * tanHalf;
  if (!(halfHeight > 0.0f)) return 0.0f;
  return std::max(0.5f, 0.5f * size * (0.5f * viewportHeight) / halfHeight);
}

void appendParticles(const ParticleSystemSettings& settings, const ParticleState& state, const OrbitCamera& camera,
                     float viewportHeight, OverlayDrawList& out) {
  const bool quads = settings.style == ParticleDrawStyle::Quads;
  const glm::vec3 eye = camera.eye(), forward = camera.forward();
  out.handles.reserve(out.handles.size() + state.positions.size());
  for (const glm::vec3& p : state.positions) {
    if (!camera.orthographic && glm::dot(p - eye, forward) <= camera.nearPlane) continue;
    OverlayDrawList::Handle h;
    h.center = p;
    h.radiusPixels = quads ? particleRadiusPixels(camera, p, settings.size, viewportHeight) : 0.5f * settings.size;
    h.color = settings.colour;
    h.shape = quads ? OverlayDrawList::HandleShape::Square : OverlayDrawList::HandleShape::Disc;
    h.layer = OverlayDrawList::Layer::Scene;
    h.outline = glm::vec4(0.0f);
    out.handles.push_back(h);
  }
}

}  // namespace kinema
