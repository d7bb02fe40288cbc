#include "editor/viewport/lattice_cage.h"

#include "editor/viewport/box_select.h"

#include <algorithm>
#include <cmath>

namespace kinema {

int pickLatticePoint(const std::vector<glm::vec3>& points, const ViewportView& view, glm::vec2 mouse,
                     float radiusPixels) {
  // Points of a cage seen end on project onto each other, a pixel or two apart: among those
  // within kTiePixels of the nearest on screen, the one nearest the eye is picked (the
  // front of the cage, what the user sees on top).
  constexpr float kTiePixels = 3.0f;
  const glm::mat4 vp = view.viewProjection();
  std::vector<float> pixels(points.size(), -1.0f), depths(points.size(), 0.0f);
  float nearest = radiusPixels;
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::vec4 clip = vp * glm::vec4(points[i], 1.0f);
    glm::vec2 pixel;
    if (clip.w <= 1e-7f || !view.project(points[i], pixel)) continue;  // behind the eye
    const float d = glm::length(pixel - mouse);
    if (d > radiusPixels) continue;
    pixels[i] = d;
    depths[i] = clip.z / clip.w;
    nearest = std::min(nearest, d);
  }
  int best = -1;
  for (size_t i = 0; i < points.size(); ++i)
    if (pixels[i] >= 0.0f && pixels[i] <= nearest + kTiePixels && (best < 0 || depths[i] < depths[best]))
      best = static_cast<int>(i);
  return best;
}

std::vector<int> boxSelectLatticePointsOnScreen(const std::vector<glm::vec3>& points, const ViewportView& view,
                                                glm::vec2 cornerA, glm::vec2 cornerB) {
  std::vector<glm::mat4> at;
  at.reserve(points.size());
  for (const glm::vec3& p : points) at.push_back(glm::translate(glm::mat4(1.0f), p));
  return boxSelectJoints(at, view, cornerA, cornerB);
}

void addLatticeCage(OverlayDrawList& out, const std::vector<glm::vec3>& points,
                    const std::vector<std::pair<int, int>>& edges, const LatticeEditState& edit) {
  // Blender's lattice colours: a dark wire, black unselected points, yellow-orange selected.
  const glm::vec4 wire(0.05f, 0.05f, 0.05f, 0.85f), wireSelected(1.0f, 0.63f, 0.16f, 0.95f);
  const glm::vec4 point(0.1f, 0.1f, 0.1f, 1.0f), selected(1.0f, 0.63f, 0.16f, 1.0f), hover(0.75f, 0.75f, 0.75f, 1.0f);
  for (const auto& [a, b] : edges) {
    if (a < 0 || b < 0 || a >= static_cast<int>(points.size()) || b >= static_cast<int>(points.size())) continue;
    const bool both = latticePointSelected(edit, a) && latticePointSelected(edit, b);
    out.addLine(points[a], points[b], both ? wireSelected : wire, both ? 2.0f : 1.5f);
  }
  for (size_t i = 0; i < points.size(); ++i) {
    const int p = static_cast<int>(i);
    const bool on = latticePointSelected(edit, p);
    out.addHandle(points[i], on ? 5.0f : 4.0f, on ? selected : p == edit.hovered ? hover : point,
                  OverlayDrawList::HandleShape::Square);
    out.handles.back().outline = on ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(0.9f, 0.9f, 0.9f, 0.9f);
  }
}

}  // namespace kinema
