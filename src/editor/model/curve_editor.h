#pragma once
#include <functional>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/rotation.h"
#include "editor/model/joint_selection.h"

namespace kinema {

// The curve editor's model (Blender's Graph Editor), window-free: which scalar curves the
// selected joints' channels show, their points and keys in display units, the 2D view
// (time x value) with fit / zoom / pan / normalize, and the key edits (values, times,
// interpolation, Bezier and Hermite handles) applied to a Clip. The panel
// (curve_editor_panel.cpp) wraps each edit in one Document edit or drag.

// How rotation (quaternion) channels are shown: as Euler angles in a chosen order (sampled
// from the quaternion curve and unwrapped), or as the quaternion's x, y, z, w.
enum class RotationView { Euler, Quaternion };

// One scalar curve: a component of a channel of the edited clip.
struct CurveRef {
  int channel = -1;
  int component = 0;
  bool operator==(const CurveRef& o) const { return channel == o.channel && component == o.component; }
};
// One key of one curve (the key itself belongs to the whole channel).
struct CurveKeyRef {
  int channel = -1;
  int component = 0;
  int key = -1;
  bool operator==(const CurveKeyRef& o) const {
    return channel == o.channel && component == o.component && key == o.key;
  }
};

// The visible part of the plane: times t0..t1 (seconds) across, values v0..v1 up.
struct CurveView {
  float t0 = 0.0f, t1 = 1.0f, v0 = -1.0f, v1 = 1.0f;
};
// The plot in window pixels (origin top left, y down).
struct PlotRect {
  float x = 0.0f, y = 0.0f, w = 1.0f, h = 1.0f;
};
glm::vec2 curveToScreen(const CurveView& view, const PlotRect& rect, float time, float value);
glm::vec2 screenToCurve(const CurveView& view, const PlotRect& rect, glm::vec2 pixel);  // (time, value)

// Display units per stored unit of a channel's curves: angles (Euler channels, rotations
// in the Euler view) are shown, typed and dragged in degrees, as the properties panel shows
// them (180 / pi); locations, scales, quaternion components and scalars as stored (1).
// The data stay radians / quaternions.
float displayUnitScale(const Channel& channel, RotationView view);
// "deg" for angle curves, "" otherwise (the dump's and the value field's unit).
const char* displayUnitName(const Channel& channel, RotationView view);

// A curve in display units: dense points from the first key to the last (the key times
// included exactly) and the keys' display values. Euler angles of rotation channels are
// unwrapped along the points (each angle within 180 degrees of the previous point's),
// starting from the first key's decomposition, so keys and curve agree.
struct CurvePoints {
  std::vector<float> times, values;
  std::vector<float> keyTimes, keyValues;
};
CurvePoints curvePoints(const Channel& channel, int component, RotationView view, EulerOrder order,
                        int samplesPerSegment = 12);

// The curve as the clip plays it, its channel modifiers applied (noise, cycles, wave), at
// `count` (>= 2) evenly spaced times from t0 to t1 (the visible range: cycles and noise go
// on past the keys), display units, Euler angles unwrapped along the points; no keys. Empty
// for a channel without enabled modifiers (the keyed curve is then what plays).
CurvePoints modifiedCurvePoints(const Channel& channel, int component, RotationView view, EulerOrder order, float t0,
                                float t1, int count);

// The curve's display value at `time` (sampled, not read off the points); Euler angles are
// unwrapped next to the plotted points, so it lies on the drawn curve.
float curveValueAt(const Channel& channel, int component, RotationView view, EulerOrder order,
                   const CurvePoints& points, float time);

// Value range of a curve (its points); a flat curve gets a unit-wide range around its value.
struct ValueRange {
  float lo = -1.0f, hi = 1.0f;
};
ValueRange curveRange(const CurvePoints& points);
// The normalized view (Blender's Normalize): each curve's range mapped to [-1, 1].
float normalizeValue(const ValueRange& range, float value);
float denormalizeValue(const ValueRange& range, float normalized);
// Display value -> curve value difference (the normalized view scales by half the range).
float displayToValueScale(const ValueRange& range, bool normalized);

// Everything the curve editor remembers between frames (not part of the document).
struct CurveEditorState {
  RotationView rotationView = RotationView::Euler;
  EulerOrder eulerOrder = EulerOrder::XYZ;
  bool normalized = false;
  CurveView view;
  bool fitPending = true;             // fit on the next frame (opened, channels changed, Home)
  std::vector<CurveRef> hidden;       // curves switched off in the channel list
  std::vector<CurveKeyRef> selected;  // selected keys
  // Mouse drags in the plot (one Document drag each for keys and handles). Box: a
  // rectangle from dragStart to the mouse selects the keys inside on release (a plain
  // drag on empty plot space, or any drag after B); Shift adds to the selection.
  enum class Drag { None, Keys, Handle, Pan, Box } drag = Drag::None;
  bool boxArmed = false;    // B: the next left drag in the plot is a box, wherever it starts
  bool boxExtend = false;   // the box adds to the selection (Shift at its press)
  glm::vec2 dragStart{0.0f};
  CurveKeyRef dragHandleKey;
  bool dragHandleRight = false;
  bool dragHandleHermite = false;
  glm::vec2 dragHandleStart{0.0f};  // the handle's offset (time, display value) at the start
  std::vector<ValueRange> dragRanges;  // per selected key: its curve's range at the start
  std::vector<CurveKeyRef> dragStartKeys;  // Keys drag: the selection and display values at its start
  std::vector<float> dragStartValues;
  int lastChannelCount = -1;  // the shown curves changed: fit again
  PlotRect plot;              // where the panel drew the plot last frame (for --dump-state)

  bool isHidden(CurveRef c) const;
  void toggleHidden(CurveRef c);
  bool isSelected(const CurveKeyRef& k) const;
};

// Channels of `clip` animating a selected joint, in clip order.
std::vector<int> shownChannels(const Clip& clip, const JointSelection& selection);

// One curve the editor shows this frame: its points (display units) and value range.
struct ShownCurve {
  CurveRef ref;
  CurvePoints points;
  ValueRange range;
};
// The curves of the selected joints' channels in the editor's rotation view (hidden ones
// included: CurveEditorState::isHidden says which are drawn). Dense keys (imported
// motion, over 200) are sampled only at the keys; authored keys with 12 points a segment.
std::vector<ShownCurve> shownCurves(const Clip& clip, const JointSelection& selection, const CurveEditorState& state);
// A key's place in the plot's plane: (time, display value, normalized when the view is).
glm::vec2 keyPlotPoint(const ShownCurve& curve, int key, bool normalized);
// Every key of the visible (not hidden) curves (A: select all).
std::vector<CurveKeyRef> allVisibleKeys(const std::vector<ShownCurve>& curves, const CurveEditorState& state);
// The keys of the visible curves inside the window-pixel rectangle spanned by a and b
// (either corner first), in the state's view and plot.
std::vector<CurveKeyRef> keysInBox(const std::vector<ShownCurve>& curves, const CurveEditorState& state, glm::vec2 a,
                                   glm::vec2 b);
// Box select: the box's keys replace the selection, or are added to it (extend).
void applyBoxSelection(CurveEditorState& state, const std::vector<CurveKeyRef>& boxed, bool extend);
// Scalar curves a channel shows: 3 (translation, scale, Euler; rotation in the Euler view),
// 4 (rotation in the quaternion view) or 1 (scalar).
int curveCount(const Channel& channel, RotationView view);
// "Hips Location X", "Hips Rotation W", "Hips Euler Z (XYZ)" ...
std::string curveLabel(const Skeleton& skeleton, const Channel& channel, int component, RotationView view,
                       EulerOrder order);

// The view that shows all these curves (display units: normalized or not) with a margin
// of `margin` times the extent on each side; a single time or value gets a unit extent.
CurveView fitView(const std::vector<CurvePoints>& curves, bool normalized, float margin = 0.1f);
// Zoom by `factor` (> 1 zooms in) about the pixel `anchor`, on the time axis, the value
// axis or both; the point under the anchor stays put.
void zoomView(CurveView& view, const PlotRect& rect, glm::vec2 anchor, float factor, bool timeAxis, bool valueAxis);
// Pan by a mouse movement in pixels (the plane follows the mouse).
void panView(CurveView& view, const PlotRect& rect, glm::vec2 pixelDelta);

// Nearest frame of the clip's grid (Clip::secondsPerFrame, the timeline's), as a time.
float snapToFrame(const FrameGrid& grid, float time);

// Sets a key's component to a display value (degrees for angles: displayUnitScale):
// vectors directly; quaternion components renormalise the quaternion; Euler angles of a
// rotation key are converted back to the quaternion (kept in the key's hemisphere).
void setKeyDisplayValue(Channel& channel, int key, int component, RotationView view, EulerOrder order, float value);
// A key's component in display units (Euler: the plain decomposition, not unwrapped).
float keyDisplayValue(const Channel& channel, int key, int component, RotationView view, EulerOrder order);

// Moves keys by dt seconds (snapped to frames) and their display value by dvDisplay (times
// each key's displayToValueScale from `scales`, one per key). `start` holds the keys'
// original display values (the drag restarts from the state at its beginning). Returns the
// keys' refs after the move (indices change when keys pass each other).
std::vector<CurveKeyRef> moveCurveKeys(Clip& clip, const FrameGrid& grid, const std::vector<CurveKeyRef>& keys, const std::vector<float>& start,
                                       const std::vector<float>& scales, float dt, float dvDisplay, RotationView view,
                                       EulerOrder order);

// Whether an interpolation applies to a channel's target (the rules of Clip::validate).
bool interpolationSuits(Interpolation interpolation, ChannelTarget target);
// Changes the settings of each selected key's channel key through `change` (once per key,
// also when several components of it are selected). Keys whose channel cannot take the
// resulting interpolation are left alone; returns how many of them were skipped.
int changeKeySettings(Clip& clip, const std::vector<CurveKeyRef>& keys, const std::function<void(KeySettings&)>& change);

// Handle dragging. Pixel movement -> change of a handle's (time, display value) offset.
glm::vec2 handleDeltaFromPixels(const CurveView& view, const PlotRect& rect, glm::vec2 pixelDelta);
// Sets a key's Bezier handle of one component to (timeOffset, valueOffset) with setBezierHandle
// (Blender's type rules: auto -> aligned, vector -> free). The handle's time offset is shared
// by the channel's components: the other components keep their slopes. When the other handle
// is aligned it turns to stay collinear and keeps its length in this component's plane, with
// time measured in frames (`framesPerSecond`) as Blender's graph does.
void dragBezierHandle(Channel& channel, int key, bool right, int component, float timeOffset, float valueOffset,
                      float framesPerSecond);
// The handles the plot shows on a selected key, relative to it in (seconds, display units,
// not normalized). A key whose own segment or the one before it is Bezier shows both its
// handles (an end key's outer one mirrors the inner, as in Blender); rotations in the
// Euler view show where each handle's control point turns the joint (the quaternion
// key plus the handle, normalised, in Euler angles), which is the curve's tangent
// direction at the key. Hermite tangents show on their own sides (not in the Euler view
// of rotations, where tangents of quaternion components have no single angle).
struct CurveHandle {
  CurveKeyRef key;
  bool right = false, hermite = false;
  glm::vec2 offset{0.0f};
};
std::vector<CurveHandle> curveHandles(const Channel& channel, const CurveKeyRef& key, RotationView view,
                                      EulerOrder order);
// Moves one of curveHandles' handles to `offset` (seconds, display units, not normalized),
// with dragBezierHandle / setHermiteTangentFromHandle, or for a rotation's Euler view by
// turning the handle's control point to that angle (the other angles kept) and setting
// the quaternion handle with setBezierHandle (Blender's type rules).
void dragCurveHandle(Channel& channel, const CurveHandle& handle, glm::vec2 offset, RotationView view, EulerOrder order,
                     float framesPerSecond);

// Hermite tangents as handles: the handle of a slope m sits at (±h, ±m h); setting it from a
// dragged offset stores the slope (value per second) in outTangent (right) or inTangent (left).
void setHermiteTangentFromHandle(Channel& channel, int key, bool right, int component, float timeOffset,
                                 float valueOffset);

}  // namespace kinema
