#pragma once
#include <utility>
#include <vector>

#include "editor/model/lattice_editing.h"
#include "editor/viewport/viewport_view.h"
#include "render/overlay_draw_list.h"

namespace kinema {

// Lattice edit mode in the 3D view (model/lattice_editing.h has the rest): picking the
// control points under the mouse, box selecting them, and drawing the cage over the mesh.
// Points are world positions (latticeWorldPoints); pixels are the window's, origin top left.

// The point whose projection lies nearest `mouse` within `radiusPixels`, the nearest to the
// eye of those within 3 pixels of that one (a cage seen end on); -1 when none is that close
// or every point is behind the eye.
int pickLatticePoint(const std::vector<glm::vec3>& points, const ViewportView& view, glm::vec2 mouse,
                     float radiusPixels);
// The points projected inside the rectangle between two pixel corners (ascending).
std::vector<int> boxSelectLatticePointsOnScreen(const std::vector<glm::vec3>& points, const ViewportView& view,
                                                glm::vec2 cornerA, glm::vec2 cornerB);
// The cage: its edges as lines, its points as square handles (selected ones in Blender's
// selection yellow, the hovered one lighter), all drawn on top of the mesh.
void addLatticeCage(OverlayDrawList& out, const std::vector<glm::vec3>& points,
                    const std::vector<std::pair<int, int>>& edges, const LatticeEditState& edit);

}  // namespace kinema
