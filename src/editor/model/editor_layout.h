#pragma once
#include "editor/model/bottom_panels.h"

namespace kinema {

// The editor's panel layout (window pixels, origin top left): the menu bar along the top,
// outliner over history on the left, properties over IK targets on the right, the status bar
// along the bottom, the 3D view in between with the animation editor and the timeline under
// it. Splitters between them move (PanelSizes); everything scales with the UI scale.
struct PanelRect {
  float x = 0, y = 0, w = 0, h = 0;
  float right() const { return x + w; }
  float bottom() const { return y + h; }
};

// The splitters' positions, in pixels at UI scale 1 (so they follow the scale) or fractions.
struct PanelSizes {
  float leftWidth = 250.0f;            // outliner + history column
  float rightWidth = 310.0f;           // properties + IK targets column
  float outlinerFraction = 0.62f;      // of the left column's height, the outliner's
  float propertiesFraction = 0.55f;    // of the right column's height, the properties'
  float animationEditorHeight = kAnimationEditorHeight;  // dope sheet / curve editor
  bool operator==(const PanelSizes& o) const {
    return leftWidth == o.leftWidth && rightWidth == o.rightWidth && outlinerFraction == o.outlinerFraction &&
           propertiesFraction == o.propertiesFraction && animationEditorHeight == o.animationEditorHeight;
  }
};

// Minimum sizes at UI scale 1 (times the scale on screen).
constexpr float kMinColumnWidth = 140.0f;      // a side column, while the window has room
constexpr float kMinViewWidth = 240.0f;        // the 3D view: columns shrink first to keep it
constexpr float kMinViewHeight = 140.0f;
constexpr float kMinPanelHeight = 60.0f;       // outliner, history, properties, IK targets
constexpr float kMinAnimationEditorHeight = 90.0f;
constexpr float kSplitterThickness = 5.0f;     // the grab zone straddling a boundary

// What the layout depends on besides the splitters: the font's pixel height (the menu bar,
// status bar and timeline are rows of text) and the UI scale (paddings and minimum sizes).
struct LayoutMetrics {
  float fontSize = 13.0f;     // pixels
  float scale = 1.0f;
  float framePaddingY = 3.0f;  // ImGui's style, already scaled
  float frameHeight() const { return fontSize + 2.0f * framePaddingY; }  // one row of widgets
  float menuBarHeight() const { return frameHeight(); }
  float statusBarHeight() const { return fontSize + 11.0f * scale; }
  float timelineHeight() const { return 2.0f * frameHeight() + 2.0f * scale; }  // two rows of widgets
  // The foot contact strip over the timeline: a lane per foot, each most of a row of text.
  float contactLaneHeight() const { return 0.8f * frameHeight(); }
  float contactLanesHeight() const { return 2.0f * contactLaneHeight() + 2.0f * scale; }
};

struct EditorLayout {
  LayoutMetrics metrics;  // what it was computed with
  PanelRect menuBar, outliner, history, properties, ikTargets, viewport, animationEditor, timeline, statusBar;
  // The foot contact lanes (BottomPanels::contactLanes) right over the timeline, as wide;
  // zero height without them.
  PanelRect contactLanes;
  PanelRect panelArea;  // between the menu bar and the status bar, the whole width (the compare mode)
};

// The layout of a `display` (window pixels) with the splitters at `sizes`. The 3D view keeps
// at least kMinViewWidth x kMinViewHeight (times the scale; at most half the window): the
// side columns and the animation editor give way first, down to their minimums, then further
// when the window is smaller still. Every rectangle is at least 1 px each way.
EditorLayout computeEditorLayout(float displayWidth, float displayHeight, const PanelSizes& sizes, BottomPanels bottom,
                                 const LayoutMetrics& metrics);

// The splitters a user drags (panels/panel_splitters.cpp).
enum class Splitter { LeftColumn, RightColumn, OutlinerHistory, PropertiesIk, AnimationEditor };
// `sizes` with splitter `s` dragged to window coordinate `position` (x for the columns, y for
// the others), clamped so every panel keeps its minimum and the 3D view its own.
PanelSizes dragSplitter(const PanelSizes& sizes, Splitter s, float position, float displayWidth, float displayHeight,
                        BottomPanels bottom, const LayoutMetrics& metrics);

}  // namespace kinema
