#pragma once
#include <vector>

#include "core/math.h"

namespace kinema {

// What the viewport draws on top of the scene (gizmos, IK target handles, limit cones, the
// box-select rectangle), built on the CPU each frame and drawn by OverlayRenderer after the
// skeleton. Widths and handle sizes are in pixels so they look the same at any zoom.
struct OverlayDrawList {
  // Scene: depth-tested against the skeleton (limit cones); OnTop: always visible (gizmos).
  enum class Layer { Scene, OnTop };
  enum class HandleShape { Disc, Diamond, Square };

  struct Line {
    glm::vec3 a{0.0f}, b{0.0f};
    glm::vec4 color{1.0f};
    float widthPixels = 1.0f;
    Layer layer = Layer::OnTop;
  };
  // A filled marker centred on a world point, `radiusPixels` across half its width.
  struct Handle {
    glm::vec3 center{0.0f};
    float radiusPixels = 6.0f;
    glm::vec4 color{1.0f};
    HandleShape shape = HandleShape::Disc;
    Layer layer = Layer::OnTop;
    glm::vec4 outline{0.0f, 0.0f, 0.0f, 1.0f};  // alpha 0 = no outline
  };
  // Lines and rectangles in pixels (origin top left), always on top.
  struct ScreenLine {
    glm::vec2 a{0.0f}, b{0.0f};
    glm::vec4 color{1.0f};
    float widthPixels = 1.0f;
  };
  struct ScreenRect {
    glm::vec2 min{0.0f}, max{0.0f};
    glm::vec4 fill{1.0f, 1.0f, 1.0f, 0.1f};  // alpha blended
  };

  std::vector<Line> lines;
  std::vector<Handle> handles;
  std::vector<ScreenLine> screenLines;
  std::vector<ScreenRect> screenRects;

  void clear() { *this = OverlayDrawList{}; }
  // Every line width, and the radius of every handle up to kMarkerPixels (markers, not the
  // larger discs that mark areas), times k: thicker lines for a projector.
  static constexpr float kMarkerPixels = 16.0f;
  void scaleWidths(float k);
  bool empty() const { return lines.empty() && handles.empty() && screenLines.empty() && screenRects.empty(); }
  void addLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color, float widthPixels = 1.0f,
               Layer layer = Layer::OnTop);
  // Consecutive points joined; `closed` joins the last to the first.
  void addPolyline(const std::vector<glm::vec3>& points, bool closed, const glm::vec4& color, float widthPixels = 1.0f,
                   Layer layer = Layer::OnTop);
  // `dashes` dashes of equal length with equal gaps between them, from a to b.
  void addDashedLine(const glm::vec3& a, const glm::vec3& b, int dashes, const glm::vec4& color,
                     float widthPixels = 1.0f, Layer layer = Layer::OnTop);
  void addHandle(const glm::vec3& center, float radiusPixels, const glm::vec4& color, HandleShape shape,
                 Layer layer = Layer::OnTop);
  // A rectangle between two pixel corners (either order): translucent fill + dashed outline.
  void addScreenRectangle(glm::vec2 cornerA, glm::vec2 cornerB, const glm::vec4& fill, const glm::vec4& border);
};

}  // namespace kinema
