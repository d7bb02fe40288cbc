#include "editor/viewport/particle_display.h"

#include "editor/model/timeline.h"
#include "render/particle_overlay.h"

namespace kinema {

void buildParticleDisplay(EditorState& state, float viewportHeightPixels, OverlayDrawList& out) {
  const std::vector<ParticleState>* states = liveParticlesAt(state.liveParticles, state.doc, state.clip, currentFrame(state));
  if (!states) return;
  const std::vector<ParticleSystemSettings>& systems = state.doc.scene().simulation.particles;
  for (size_t i = 0; i < states->size() && i < systems.size(); ++i)
    appendParticles(systems[i], (*states)[i], state.camera, viewportHeightPixels, out);
}

}  // namespace kinema
