#include "editor/model/editor_layout.h"

#include <algorithm>

namespace kinema {

namespace {

float atLeast1(float v) { return std::max(v, 1.0f); }

struct Columns {
  float left, right, viewMin;
};
// The side columns' widths on screen: as stored (times the scale, at least their minimum)
// while the 3D view keeps its minimum; otherwise shrunk towards their minimums in proportion
// to what each has above it, and below them, in proportion, when even that does not fit.
Columns columnWidths(float width, const PanelSizes& sizes, const LayoutMetrics& m) {
  const float s = m.scale, colMin = kMinColumnWidth * s;
  Columns c;
  c.viewMin = std::min(kMinViewWidth * s, width * 0.5f);
  c.left = std::max(sizes.leftWidth * s, colMin);
  c.right = std::max(sizes.rightWidth * s, colMin);
  const float room = std::max(width - c.viewMin, 0.0f);
  if (c.left + c.right <= room) return c;
  const float aboveLeft = c.left - colMin, aboveRight = c.right - colMin, excess = c.left + c.right - room;
  if (aboveLeft + aboveRight >= excess) {
    const float k = excess / (aboveLeft + aboveRight);
    c.left -= aboveLeft * k;
    c.right -= aboveRight * k;
  } else {
    const float total = c.left + c.right;
    c.left = room * c.left / total;
    c.right = room - c.left;
  }
  return c;
}

float panelMin(float columnHeight, const LayoutMetrics& m) {
  return std::min(kMinPanelHeight * m.scale, columnHeight * 0.5f);
}

float splitHeight(float columnHeight, float fraction, const LayoutMetrics& m) {
  const float lo = panelMin(columnHeight, m);
  return std::clamp(columnHeight * fraction, lo, std::max(columnHeight - lo, lo));
}

struct Rows {
  float area, timeline, animationEditor, viewMin;
  float lanes;  // of `timeline`, the contact lanes' share over the strip
};
Rows rowHeights(float height, const PanelSizes& sizes, BottomPanels bottom, const LayoutMetrics& m) {
  Rows r;
  r.area = std::max(height - m.menuBarHeight() - m.statusBarHeight(), 1.0f);
  const float lanes = bottom.timeline && bottom.contactLanes ? m.contactLanesHeight() : 0.0f;
  r.timeline = bottom.timeline ? std::min(m.timelineHeight() + lanes, r.area * 0.5f) : 0.0f;
  r.lanes = std::max(r.timeline - m.timelineHeight(), 0.0f);
  r.viewMin = std::min(kMinViewHeight * m.scale, r.area * 0.5f);
  r.animationEditor = 0.0f;
  if (bottom.animationEditor) {
    const float wanted = std::max(sizes.animationEditorHeight, kMinAnimationEditorHeight) * m.scale;
    r.animationEditor = std::clamp(wanted, 0.0f, std::max(r.area - r.timeline - r.viewMin, 0.0f));
  }
  return r;
}

}  // namespace

EditorLayout computeEditorLayout(float W, float H, const PanelSizes& sizes, BottomPanels bottom,
                                 const LayoutMetrics& m) {
  EditorLayout l;
  l.metrics = m;
  W = atLeast1(W);
  H = atLeast1(H);
  const float menu = m.menuBarHeight(), status = m.statusBarHeight();
  const Columns c = columnWidths(W, sizes, m);
  const Rows r = rowHeights(H, sizes, bottom, m);
  l.menuBar = {0.0f, 0.0f, W, menu};
  l.statusBar = {0.0f, H - status, W, status};
  l.panelArea = {0.0f, menu, W, r.area};
  const float outliner = splitHeight(r.area, sizes.outlinerFraction, m);
  l.outliner = {0.0f, menu, atLeast1(c.left), atLeast1(outliner)};
  l.history = {0.0f, menu + outliner, atLeast1(c.left), atLeast1(r.area - outliner)};
  const float properties = splitHeight(r.area, sizes.propertiesFraction, m);
  l.properties = {W - c.right, menu, atLeast1(c.right), atLeast1(properties)};
  l.ikTargets = {W - c.right, menu + properties, atLeast1(c.right), atLeast1(r.area - properties)};
  const float viewW = atLeast1(W - c.left - c.right);
  l.viewport = {c.left, menu, viewW, atLeast1(r.area - r.timeline - r.animationEditor)};
  l.animationEditor = {c.left, l.viewport.bottom(), viewW, atLeast1(r.animationEditor)};
  l.contactLanes = {c.left, menu + r.area - r.timeline, viewW, r.lanes};
  l.timeline = {c.left, menu + r.area - r.timeline + r.lanes, viewW, atLeast1(r.timeline - r.lanes)};
  return l;
}

PanelSizes dragSplitter(const PanelSizes& sizes, Splitter s, float position, float W, float H, BottomPanels bottom,
                        const LayoutMetrics& m) {
  PanelSizes out = sizes;
  const EditorLayout l = computeEditorLayout(W, H, sizes, bottom, m);
  const Columns c = columnWidths(std::max(W, 1.0f), sizes, m);
  const float colMin = kMinColumnWidth * m.scale;
  // Upper bound first, then the minimum only where the window has room for it.
  auto clampWidth = [&](float wanted, float other) {
    const float hi = std::max(W - other - c.viewMin, 0.0f);
    return std::max(std::min(wanted, hi), std::min(colMin, hi));
  };
  auto fraction = [&](float y) {
    const float area = l.panelArea.h, lo = panelMin(area, m);
    return std::clamp(y - l.panelArea.y, lo, std::max(area - lo, lo)) / area;
  };
  switch (s) {
    case Splitter::LeftColumn: out.leftWidth = clampWidth(position, l.properties.w) / m.scale; break;
    case Splitter::RightColumn: out.rightWidth = clampWidth(W - position, l.outliner.w) / m.scale; break;
    case Splitter::OutlinerHistory: out.outlinerFraction = fraction(position); break;
    case Splitter::PropertiesIk: out.propertiesFraction = fraction(position); break;
    case Splitter::AnimationEditor: {
      const Rows r = rowHeights(H, sizes, bottom, m);
      const float bottomEdge = l.panelArea.bottom() - r.timeline;
      const float hi = std::max(l.panelArea.h - r.timeline - r.viewMin, 0.0f);
      const float wanted = std::min(bottomEdge - position, hi);
      out.animationEditorHeight = std::max(wanted, std::min(kMinAnimationEditorHeight * m.scale, hi)) / m.scale;
      break;
    }
  }
  return out;
}

}  // namespace kinema
