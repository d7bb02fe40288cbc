#include "editor/viewport/crowd_display.h"

#include "editor/viewport/animation_display.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

const CrowdSettings* shownCrowd(const EditorState& state) {
  const auto& crowds = state.doc.scene().simulation.crowds;
  if (!state.crowds.live || crowds.empty() || state.compare.active) return nullptr;
  return &crowds[static_cast<size_t>(std::clamp(state.crowds.active, 0, static_cast<int>(crowds.size()) - 1))];
}

}  // namespace

void buildCrowdDisplay(EditorState& state, const std::vector<char>& shownJoints, bool meshesOnGpu, CrowdDisplay& d) {
  d.bodies.clear();
  d.bones.clear();
  d.radius = 0.0f;
  const CrowdSettings* crowd = shownCrowd(state);
  if (!crowd) return;
  const int index = std::clamp(state.crowds.active, 0, static_cast<int>(state.doc.scene().simulation.crowds.size()) - 1);
  CrowdPreview& p = state.crowds.preview;
  // The debug vectors start at the member's middle: half its character's rest height.
  if (!updateCrowdPreview(p, state.doc, index, state.time, -1.0f, 0.15f)) return;
  for (const std::vector<glm::mat4>& w : p.world)
    for (const glm::mat4& m : w) d.radius = std::max(d.radius, glm::length(glm::vec3(m[3])));
  for (const BoidSphere& s : crowd->boids.spheres) d.radius = std::max(d.radius, glm::length(s.centre) + s.radius);
  std::vector<std::vector<glm::mat4>> asBones;
  const bool bodies = crowd->character.empty() && meshesOnGpu;
  if (bodies) d.noMorphs.assign(state.doc.scene().meshInstances.size(), {});
  // Bodies for the members nearest the debug member (the one the view is usually on).
  std::vector<float> distance(p.world.size());
  const glm::vec3 centre = p.run.at(p.frame, crowd->debugMember).position;
  for (size_t m = 0; m < p.world.size(); ++m) distance[m] = glm::distance(p.run.at(p.frame, static_cast<int>(m)).position, centre);
  std::vector<float> sorted = distance;
  const size_t budget = std::min(sorted.size(), static_cast<size_t>(std::max(state.crowds.bodyBudget, 1)));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(budget - 1), sorted.end());
  const float reach = sorted[budget - 1];
  int shown = 0;
  for (size_t m = 0; m < p.world.size(); ++m) {
    if (bodies && distance[m] <= reach && shown++ < static_cast<int>(budget))
      d.bodies.push_back(&p.world[m]);
    else
      asBones.push_back(p.world[m]);
  }
  std::vector<GhostFrame> ghosts(asBones.size());
  for (GhostFrame& g : ghosts) g.color = glm::vec4(0.85f, 0.9f, 1.0f, 1.0f);
  const std::vector<char> all;
  d.bones = buildGhostDrawLists(p.character->skeleton.parents, crowd->character.empty() ? shownJoints : all, ghosts,
                                asBones);
}

void addCrowdOverlay(const EditorState& state, OverlayDrawList& overlay) {
  const CrowdSettings* crowd = shownCrowd(state);
  if (!crowd) return;
  const glm::vec4 obstacle(0.95f, 0.85f, 0.3f, 1.0f);
  for (const BoidSphere& s : crowd->boids.spheres) {  // its outline on the ground and its height
    std::vector<glm::vec3> ring;
    for (int i = 0; i < 48; ++i) {
      const float a = 6.2831853f * static_cast<float>(i) / 48.0f;
      ring.push_back(glm::vec3(s.centre.x + s.radius * std::cos(a), 0.0f, s.centre.z + s.radius * std::sin(a)));
    }
    overlay.addPolyline(ring, true, obstacle, 2.0f, OverlayDrawList::Layer::Scene);
  }
  for (const BoidBox& b : crowd->boids.boxes) {
    const std::vector<glm::vec3> foot = {{b.min.x, 0.0f, b.min.z}, {b.max.x, 0.0f, b.min.z}, {b.max.x, 0.0f, b.max.z},
                                         {b.min.x, 0.0f, b.max.z}};
    overlay.addPolyline(foot, true, obstacle, 2.0f, OverlayDrawList::Layer::Scene);
  }
  if (crowd->boids.hasGoal) {
    const glm::vec3 g(crowd->boids.goal.x, 0.0f, crowd->boids.goal.z);
    overlay.addLine(g, g + glm::vec3(0.0f, 2.0f, 0.0f), glm::vec4(0.75f, 0.35f, 0.95f, 1.0f), 3.0f);
    overlay.addHandle(g + glm::vec3(0.0f, 2.0f, 0.0f), 6.0f, glm::vec4(0.75f, 0.35f, 0.95f, 1.0f),
                      OverlayDrawList::HandleShape::Disc);
  }
  const CrowdPreview& p = state.crowds.preview;
  if (p.vectors.empty()) return;
  overlay.addHandle(p.vectors.front().from, 6.0f, glm::vec4(1.0f), OverlayDrawList::HandleShape::Disc);
  for (const CrowdDebugVector& v : p.vectors) {
    overlay.addLine(v.from, v.to, v.color, 4.0f);
    overlay.addHandle(v.to, 4.5f, v.color, OverlayDrawList::HandleShape::Disc);
  }
}

}  // namespace kinema
