// The panel layout (editor_layout.h): panels tile the window, the 3D view keeps its minimum
// on a small window, everything follows the UI scale, and splitters stay within limits.
#include <gtest/gtest.h>

#include "editor/model/editor_layout.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

LayoutMetrics metricsAt(float scale) {
  LayoutMetrics m;
  m.fontSize = 14.0f * scale;
  m.scale = scale;
  m.framePaddingY = 3.0f * scale;
  return m;
}

BottomPanels both() {
  BottomPanels b;
  b.timeline = true;
  b.animationEditor = true;
  return b;
}

void expectTiles(const EditorLayout& l, float W, float H) {
  EXPECT_FLOAT_EQ(l.menuBar.bottom(), l.outliner.y);
  EXPECT_FLOAT_EQ(l.outliner.bottom(), l.history.y);
  EXPECT_FLOAT_EQ(l.history.bottom(), l.statusBar.y);
  EXPECT_FLOAT_EQ(l.properties.bottom(), l.ikTargets.y);
  EXPECT_FLOAT_EQ(l.ikTargets.bottom(), l.statusBar.y);
  EXPECT_FLOAT_EQ(l.outliner.right(), l.viewport.x);
  EXPECT_FLOAT_EQ(l.viewport.right(), l.properties.x);
  EXPECT_FLOAT_EQ(l.properties.right(), W);
  EXPECT_FLOAT_EQ(l.statusBar.bottom(), H);
  EXPECT_FLOAT_EQ(l.viewport.bottom(), l.animationEditor.y);
  EXPECT_FLOAT_EQ(l.animationEditor.bottom(), l.timeline.y);
  EXPECT_FLOAT_EQ(l.timeline.bottom(), l.statusBar.y);
  EXPECT_FLOAT_EQ(l.timeline.w, l.viewport.w);
}

TEST(EditorLayout, AtTheDefaultSizeTheColumnsHaveTheirWidths) {
  const EditorLayout l = computeEditorLayout(1280, 720, PanelSizes{}, both(), metricsAt(1));
  expectTiles(l, 1280, 720);
  EXPECT_FLOAT_EQ(l.outliner.w, 250.0f);
  EXPECT_FLOAT_EQ(l.properties.w, 310.0f);
  EXPECT_FLOAT_EQ(l.menuBar.h, 20.0f);  // 14 px text + 2 x 3 px padding
  EXPECT_FLOAT_EQ(l.animationEditor.h, kAnimationEditorHeight);
  EXPECT_FLOAT_EQ(l.viewport.w, 1280.0f - 250 - 310);
}

TEST(EditorLayout, OnA640By400WindowThe3dViewKeepsItsMinimum) {
  for (const BottomPanels b : {BottomPanels{}, both()}) {
    const EditorLayout l = computeEditorLayout(640, 400, PanelSizes{}, b, metricsAt(1));
    if (b.timeline) expectTiles(l, 640, 400);
    else EXPECT_FLOAT_EQ(l.viewport.bottom(), l.statusBar.y);  // nothing under the 3D view
    EXPECT_GE(l.viewport.w, kMinViewWidth);
    EXPECT_GE(l.viewport.h, std::min(kMinViewHeight, l.panelArea.h / 2) - 0.01f);
    EXPECT_GE(l.outliner.w, kMinColumnWidth);  // the columns gave way, still usable
    EXPECT_GE(l.properties.w, kMinColumnWidth);
    EXPECT_GT(l.properties.w, l.outliner.w);  // in proportion to what they were
  }
}

TEST(EditorLayout, AtTwiceTheScaleEverythingDoublesWhereThereIsRoom) {
  const EditorLayout one = computeEditorLayout(3000, 2000, PanelSizes{}, both(), metricsAt(1));
  const EditorLayout two = computeEditorLayout(3000, 2000, PanelSizes{}, both(), metricsAt(2));
  EXPECT_FLOAT_EQ(two.menuBar.h, 2 * one.menuBar.h);
  EXPECT_FLOAT_EQ(two.statusBar.h, 2 * one.statusBar.h);
  EXPECT_FLOAT_EQ(two.timeline.h, 2 * one.timeline.h);
  EXPECT_FLOAT_EQ(two.outliner.w, 2 * one.outliner.w);
  EXPECT_FLOAT_EQ(two.animationEditor.h, 2 * one.animationEditor.h);
}

TEST(EditorLayout, ATinyWindowStillGivesEveryPanelAPixel) {
  const EditorLayout l = computeEditorLayout(50, 40, PanelSizes{}, both(), metricsAt(2));
  for (const PanelRect& r : {l.outliner, l.history, l.properties, l.ikTargets, l.viewport, l.animationEditor, l.timeline}) {
    EXPECT_GE(r.w, 1.0f);
    EXPECT_GE(r.h, 1.0f);
  }
  EXPECT_FLOAT_EQ(l.viewport.w, 25.0f);  // half the window
}

TEST(Splitters, DraggingMovesTheBoundaryAndClampsAtTheLimits) {
  const LayoutMetrics m = metricsAt(1);
  const PanelSizes s;
  EXPECT_FLOAT_EQ(dragSplitter(s, Splitter::LeftColumn, 300, 1280, 720, both(), m).leftWidth, 300.0f);
  EXPECT_FLOAT_EQ(dragSplitter(s, Splitter::LeftColumn, 10, 1280, 720, both(), m).leftWidth, kMinColumnWidth);
  // Far right: up to where the 3D view keeps its minimum beside the right column.
  EXPECT_FLOAT_EQ(dragSplitter(s, Splitter::LeftColumn, 1200, 1280, 720, both(), m).leftWidth,
                  1280.0f - 310 - kMinViewWidth);
  EXPECT_FLOAT_EQ(dragSplitter(s, Splitter::RightColumn, 1280 - 200, 1280, 720, both(), m).rightWidth, 200.0f);
  EXPECT_FLOAT_EQ(dragSplitter(s, Splitter::RightColumn, 0, 1280, 720, both(), m).rightWidth,
                  1280.0f - 250 - kMinViewWidth);
  // At scale 2 the stored width is in scale-1 pixels.
  EXPECT_FLOAT_EQ(dragSplitter(s, Splitter::LeftColumn, 600, 3000, 2000, both(), metricsAt(2)).leftWidth, 300.0f);
}

TEST(Splitters, PanelSplitsAndTheAnimationEditorKeepTheirMinimums) {
  const LayoutMetrics m = metricsAt(1);
  const PanelSizes s;
  const EditorLayout l = computeEditorLayout(1280, 720, s, both(), m);
  const PanelSizes half = dragSplitter(s, Splitter::OutlinerHistory, l.panelArea.y + l.panelArea.h / 2, 1280, 720, both(), m);
  EXPECT_NEAR(half.outlinerFraction, 0.5f, 1e-6);
  const PanelSizes top = dragSplitter(s, Splitter::PropertiesIk, 0, 1280, 720, both(), m);
  EXPECT_FLOAT_EQ(computeEditorLayout(1280, 720, top, both(), m).properties.h, kMinPanelHeight);
  // The animation editor's top edge dragged up 100 px grows it by 100 px.
  const PanelSizes taller = dragSplitter(s, Splitter::AnimationEditor, l.animationEditor.y - 100, 1280, 720, both(), m);
  EXPECT_FLOAT_EQ(taller.animationEditorHeight, kAnimationEditorHeight + 100);
  // Dragged to the menu bar: the 3D view keeps its minimum height.
  const PanelSizes tallest = dragSplitter(s, Splitter::AnimationEditor, 0, 1280, 720, both(), m);
  EXPECT_FLOAT_EQ(computeEditorLayout(1280, 720, tallest, both(), m).viewport.h, kMinViewHeight);
  // Dragged to the timeline: its minimum height.
  const PanelSizes flat = dragSplitter(s, Splitter::AnimationEditor, 719, 1280, 720, both(), m);
  EXPECT_FLOAT_EQ(flat.animationEditorHeight, kMinAnimationEditorHeight);
}

}  // namespace
}  // namespace kinema
