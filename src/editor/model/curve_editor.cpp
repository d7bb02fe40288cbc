#include "editor/model/curve_editor.h"

#include <algorithm>
#include <cmath>

#include "anim/bezier_handles.h"
#include "anim/channel_modifiers.h"
#include "anim/sampling.h"
#include "core/math.h"

namespace kinema {

namespace {


bool isRotationEuler(const Channel& ch, RotationView view) {
  return ch.target == ChannelTarget::Rotation && view == RotationView::Euler;
}

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }
glm::vec4 toVec(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

constexpr float kDegrees = 180.0f / kPi;

// A channel with one interpolation for all keys (`keys` empty) gets per-key settings, each
// the channel's, before one key's are edited. (Filling after a resize would read the
// default-constructed ones: Channel::settings reads `keys` once it is not empty.)
void giveKeysTheirSettings(Channel& ch) {
  if (ch.keys.empty()) ch.keys.assign(ch.times.size(), ch.settings(0));
}

// `angle` plus whole turns (`turn`: 2 pi in radians, 360 in degrees), within half a turn of `previous`.
float unwrapNear(float angle, float previous, float turn) {
  return angle - turn * std::round((angle - previous) / turn);
}

// The channel's value at `time` in display units (all components).
glm::vec4 displayAt(const Channel& ch, float time, RotationView view, EulerOrder order, bool modified = false) {
  const glm::vec4 v = modified ? sampleModifiedChannel(ch, time) : sampleChannel(ch, time);
  const float unit = displayUnitScale(ch, view);
  if (!isRotationEuler(ch, view)) return v * unit;
  return glm::vec4(quatToEuler(toQuat(v), order) * unit, 0.0f);
}

// Linear interpolation of the plotted points at `time` (clamped to their ends).
float pointsAt(const CurvePoints& p, float time) {
  if (p.times.empty()) return 0.0f;
  const auto it = std::upper_bound(p.times.begin(), p.times.end(), time);
  if (it == p.times.begin()) return p.values.front();
  if (it == p.times.end()) return p.values.back();
  const size_t hi = size_t(it - p.times.begin()), lo = hi - 1;
  const float span = p.times[hi] - p.times[lo];
  const float u = span > 0.0f ? (time - p.times[lo]) / span : 0.0f;
  return p.values[lo] + (p.values[hi] - p.values[lo]) * u;
}

}  // namespace

float displayUnitScale(const Channel& ch, RotationView view) {
  return ch.target == ChannelTarget::Euler || isRotationEuler(ch, view) ? kDegrees : 1.0f;
}

const char* displayUnitName(const Channel& ch, RotationView view) {
  return displayUnitScale(ch, view) == 1.0f ? "" : "deg";
}

float curveValueAt(const Channel& ch, int component, RotationView view, EulerOrder order, const CurvePoints& points,
                   float time) {
  const float v = displayAt(ch, time, view, order)[component];
  if (!isRotationEuler(ch, view) || points.times.empty()) return v;
  return unwrapNear(v, pointsAt(points, time), 2.0f * kPi * displayUnitScale(ch, view));
}

glm::vec2 curveToScreen(const CurveView& v, const PlotRect& r, float time, float value) {
  const float sx = r.w / std::max(v.t1 - v.t0, 1e-9f), sy = r.h / std::max(v.v1 - v.v0, 1e-9f);
  return {r.x + (time - v.t0) * sx, r.y + r.h - (value - v.v0) * sy};
}

glm::vec2 screenToCurve(const CurveView& v, const PlotRect& r, glm::vec2 p) {
  return {v.t0 + (p.x - r.x) / r.w * (v.t1 - v.t0), v.v0 + (r.y + r.h - p.y) / r.h * (v.v1 - v.v0)};
}

CurvePoints curvePoints(const Channel& ch, int component, RotationView view, EulerOrder order, int samplesPerSegment) {
  CurvePoints out;
  const int n = ch.keyCount();
  if (n == 0) return out;
  const int steps = std::max(1, samplesPerSegment);
  const bool euler = isRotationEuler(ch, view);
  const float turn = 2.0f * kPi * displayUnitScale(ch, view);
  glm::vec4 previous(0.0f);
  bool first = true;
  auto add = [&](float t, bool isKey, const glm::vec4* exact) {
    glm::vec4 v = exact ? *exact : displayAt(ch, t, view, order);
    if (euler) {
      for (int i = 0; i < 3; ++i) v[i] = first ? v[i] : unwrapNear(v[i], previous[i], turn);
      previous = v;
      first = false;
    }
    out.times.push_back(t);
    out.values.push_back(v[component]);
    if (isKey) {
      out.keyTimes.push_back(t);
      out.keyValues.push_back(v[component]);
    }
  };
  for (int k = 0; k < n; ++k) {
    add(ch.times[k], true, nullptr);
    if (k + 1 == n) break;
    const float t0 = ch.times[k], t1 = ch.times[k + 1];
    if (ch.settings(k).interpolation == Interpolation::Step) {
      const glm::vec4 held = displayAt(ch, t0, view, order);
      add(t1, false, &held);  // the held value up to the next key, then the jump
      continue;
    }
    for (int i = 1; i < steps; ++i) add(t0 + (t1 - t0) * float(i) / float(steps), false, nullptr);
  }
  return out;
}

CurvePoints modifiedCurvePoints(const Channel& ch, int component, RotationView view, EulerOrder order, float t0,
                                float t1, int count) {
  CurvePoints out;
  if (!hasActiveModifiers(ch) || ch.keyCount() == 0 || !(t1 >= t0) || count < 2) return out;
  const bool euler = isRotationEuler(ch, view);
  const float turn = 2.0f * kPi * displayUnitScale(ch, view);
  glm::vec4 previous(0.0f);
  for (int i = 0; i < count; ++i) {
    const float t = t0 + (t1 - t0) * float(i) / float(count - 1);
    glm::vec4 v = displayAt(ch, t, view, order, true);
    if (euler && i > 0)
      for (int k = 0; k < 3; ++k) v[k] = unwrapNear(v[k], previous[k], turn);
    previous = v;
    out.times.push_back(t);
    out.values.push_back(v[component]);
  }
  return out;
}

ValueRange curveRange(const CurvePoints& p) {
  if (p.values.empty()) return {};
  const auto [lo, hi] = std::minmax_element(p.values.begin(), p.values.end());
  if (*hi - *lo < 1e-6f) return {*lo - 0.5f, *lo + 0.5f};
  return {*lo, *hi};
}

float normalizeValue(const ValueRange& r, float v) { return 2.0f * (v - r.lo) / (r.hi - r.lo) - 1.0f; }
float denormalizeValue(const ValueRange& r, float n) { return r.lo + (n + 1.0f) * 0.5f * (r.hi - r.lo); }
float displayToValueScale(const ValueRange& r, bool normalized) { return normalized ? 0.5f * (r.hi - r.lo) : 1.0f; }

bool CurveEditorState::isHidden(CurveRef c) const { return std::find(hidden.begin(), hidden.end(), c) != hidden.end(); }
void CurveEditorState::toggleHidden(CurveRef c) {
  const auto it = std::find(hidden.begin(), hidden.end(), c);
  if (it == hidden.end()) hidden.push_back(c);
  else hidden.erase(it);
}
bool CurveEditorState::isSelected(const CurveKeyRef& k) const {
  return std::find(selected.begin(), selected.end(), k) != selected.end();
}

std::vector<int> shownChannels(const Clip& clip, const JointSelection& selection) {
  std::vector<int> out;
  for (size_t c = 0; c < clip.channels.size(); ++c)
    if (clip.channels[c].joint >= 0 && selection.isSelected(clip.channels[c].joint)) out.push_back(static_cast<int>(c));
  return out;
}

std::vector<ShownCurve> shownCurves(const Clip& clip, const JointSelection& selection, const CurveEditorState& state) {
  std::vector<ShownCurve> out;
  for (int c : shownChannels(clip, selection)) {
    const Channel& ch = clip.channels[c];
    const int perSegment = ch.keyCount() > 200 ? 1 : 12;
    for (int i = 0; i < curveCount(ch, state.rotationView); ++i) {
      ShownCurve s;
      s.ref = {c, i};
      s.points = curvePoints(ch, i, state.rotationView, state.eulerOrder, perSegment);
      s.range = curveRange(s.points);
      out.push_back(std::move(s));
    }
  }
  return out;
}

glm::vec2 keyPlotPoint(const ShownCurve& c, int key, bool normalized) {
  const float v = c.points.keyValues[size_t(key)];
  return {c.points.keyTimes[size_t(key)], normalized ? normalizeValue(c.range, v) : v};
}

std::vector<CurveKeyRef> allVisibleKeys(const std::vector<ShownCurve>& curves, const CurveEditorState& state) {
  std::vector<CurveKeyRef> out;
  for (const ShownCurve& c : curves) {
    if (state.isHidden(c.ref)) continue;
    for (size_t k = 0; k < c.points.keyTimes.size(); ++k) out.push_back({c.ref.channel, c.ref.component, int(k)});
  }
  return out;
}

std::vector<CurveKeyRef> keysInBox(const std::vector<ShownCurve>& curves, const CurveEditorState& state, glm::vec2 a,
                                   glm::vec2 b) {
  const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
  std::vector<CurveKeyRef> out;
  for (const ShownCurve& c : curves) {
    if (state.isHidden(c.ref)) continue;
    for (size_t k = 0; k < c.points.keyTimes.size(); ++k) {
      const glm::vec2 q = keyPlotPoint(c, int(k), state.normalized);
      const glm::vec2 p = curveToScreen(state.view, state.plot, q.x, q.y);
      if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y) out.push_back({c.ref.channel, c.ref.component, int(k)});
    }
  }
  return out;
}

void applyBoxSelection(CurveEditorState& state, const std::vector<CurveKeyRef>& boxed, bool extend) {
  if (!extend) state.selected.clear();
  for (const CurveKeyRef& k : boxed)
    if (!state.isSelected(k)) state.selected.push_back(k);
}

int curveCount(const Channel& ch, RotationView view) {
  if (ch.target == ChannelTarget::Rotation) return view == RotationView::Euler ? 3 : 4;
  return ch.valueSize();
}

std::string curveLabel(const Skeleton& skeleton, const Channel& ch, int component, RotationView view, EulerOrder order) {
  const std::string joint = ch.joint >= 0 && ch.joint < skeleton.size() ? skeleton.names[ch.joint] : ch.property;
  static const char* xyzw[] = {"X", "Y", "Z", "W"};
  const char* axis = xyzw[std::clamp(component, 0, 3)];
  switch (ch.target) {
    case ChannelTarget::Translation: return joint + " Location " + axis;
    case ChannelTarget::Scale: return joint + " Scale " + axis;
    case ChannelTarget::Euler: return joint + " Euler " + axis + " (" + toString(ch.eulerOrder) + ")";
    case ChannelTarget::Rotation:
      return view == RotationView::Euler ? joint + " Rotation " + axis + " (" + toString(order) + ")"
                                         : joint + " Quaternion " + axis;
    case ChannelTarget::Scalar: return joint.empty() ? std::string("Scalar") : joint;
  }
  return joint;
}

CurveView fitView(const std::vector<CurvePoints>& curves, bool normalized, float margin) {
  float t0 = INFINITY, t1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (const CurvePoints& c : curves) {
    if (c.times.empty()) continue;
    const ValueRange r = curveRange(c);
    for (size_t i = 0; i < c.times.size(); ++i) {
      const float v = normalized ? normalizeValue(r, c.values[i]) : c.values[i];
      t0 = std::min(t0, c.times[i]);
      t1 = std::max(t1, c.times[i]);
      v0 = std::min(v0, v);
      v1 = std::max(v1, v);
    }
  }
  if (!(t0 <= t1)) return CurveView{};  // nothing shown: the default view
  if (t1 - t0 < 1e-6f) t0 -= 0.5f, t1 += 0.5f;
  if (v1 - v0 < 1e-6f) v0 -= 0.5f, v1 += 0.5f;
  const float mt = (t1 - t0) * margin, mv = (v1 - v0) * margin;
  return {t0 - mt, t1 + mt, v0 - mv, v1 + mv};
}

void zoomView(CurveView& v, const PlotRect& r, glm::vec2 anchor, float factor, bool timeAxis, bool valueAxis) {
  const glm::vec2 a = screenToCurve(v, r, anchor);
  if (timeAxis) v.t0 = a.x + (v.t0 - a.x) / factor, v.t1 = a.x + (v.t1 - a.x) / factor;
  if (valueAxis) v.v0 = a.y + (v.v0 - a.y) / factor, v.v1 = a.y + (v.v1 - a.y) / factor;
}

void panView(CurveView& v, const PlotRect& r, glm::vec2 d) {
  const float dt = -d.x / r.w * (v.t1 - v.t0), dv = d.y / r.h * (v.v1 - v.v0);
  v.t0 += dt, v.t1 += dt, v.v0 += dv, v.v1 += dv;
}

float snapToFrame(const FrameGrid& grid, float time) { return grid.frameToTime(grid.nearestFrame(time)); }

float keyDisplayValue(const Channel& ch, int key, int component, RotationView view, EulerOrder order) {
  const glm::vec4& v = ch.values[key];
  if (ch.target == ChannelTarget::Rotation) {
    const glm::quat q = glm::normalize(toQuat(v));
    if (view == RotationView::Euler) return quatToEuler(q, order)[component] * kDegrees;
    return toVec(q)[component];
  }
  return v[component] * displayUnitScale(ch, view);
}

void setKeyDisplayValue(Channel& ch, int key, int component, RotationView view, EulerOrder order, float value) {
  glm::vec4& v = ch.values[key];
  value /= displayUnitScale(ch, view);  // degrees -> radians for angles
  if (ch.target != ChannelTarget::Rotation) {
    v[component] = value;
    return;
  }
  const glm::quat before = glm::normalize(toQuat(v));
  glm::quat q;
  if (view == RotationView::Euler) {
    // Only this angle changes; 2 pi steps of an unwrapped display value give the same rotation.
    glm::vec3 e = quatToEuler(before, order);
    e[component] = value;
    q = eulerToQuat(e, order);
    if (glm::dot(q, before) < 0.0f) q = -q;
  } else {
    glm::vec4 c = toVec(before);
    c[component] = value;
    // Renormalise; a component set past unit length leaves the others at zero.
    const float len = glm::length(c);
    q = len > 1e-6f ? toQuat(c / len) : before;
  }
  v = toVec(q);
}

std::vector<CurveKeyRef> moveCurveKeys(Clip& clip, const FrameGrid& grid, const std::vector<CurveKeyRef>& keys, const std::vector<float>& start,
                                       const std::vector<float>& scales, float dt, float dvDisplay, RotationView view,
                                       EulerOrder order) {
  std::vector<CurveKeyRef> out = keys;
  // Values first (indices are still the original ones), then times.
  for (size_t i = 0; i < keys.size(); ++i) {
    const CurveKeyRef& k = keys[i];
    if (k.channel < 0 || k.channel >= static_cast<int>(clip.channels.size())) continue;
    Channel& ch = clip.channels[k.channel];
    if (k.key < 0 || k.key >= ch.keyCount()) continue;
    const float scale = i < scales.size() ? scales[i] : 1.0f;
    setKeyDisplayValue(ch, k.key, k.component, view, order, start[i] + dvDisplay * scale);
  }
  if (dt == 0.0f) return out;
  // Move each channel's keys once, the ones furthest in the direction of motion first so
  // that a moved key never lands on one still waiting to move.
  std::vector<size_t> order_(keys.size());
  for (size_t i = 0; i < order_.size(); ++i) order_[i] = i;
  std::sort(order_.begin(), order_.end(), [&](size_t a, size_t b) {
    if (keys[a].channel != keys[b].channel) return keys[a].channel < keys[b].channel;
    return dt > 0 ? keys[a].key > keys[b].key : keys[a].key < keys[b].key;
  });
  std::vector<std::pair<int, int>> moved;  // (channel, original key) already moved
  std::vector<std::pair<std::pair<int, int>, int>> newIndex;
  for (size_t i : order_) {
    const CurveKeyRef& k = keys[i];
    if (k.channel < 0 || k.channel >= static_cast<int>(clip.channels.size())) continue;
    Channel& ch = clip.channels[k.channel];
    if (k.key < 0 || k.key >= ch.keyCount()) continue;
    const std::pair<int, int> id{k.channel, k.key};
    int index = -1;
    for (const auto& e : newIndex)
      if (e.first == id) index = e.second;
    if (index < 0) {
      index = moveKey(ch, k.key, snapToFrame(grid, ch.times[k.key] + dt));
      newIndex.push_back({id, index});
    }
    out[i].key = index;
  }
  return out;
}

bool interpolationSuits(Interpolation i, ChannelTarget target) {
  if (target == ChannelTarget::Rotation)
    return i == Interpolation::Step || i == Interpolation::Linear || i == Interpolation::Nlerp ||
           i == Interpolation::Squad || i == Interpolation::Hermite || i == Interpolation::Ease ||
           i == Interpolation::Bezier;
  return i != Interpolation::Nlerp && i != Interpolation::Squad;
}

int changeKeySettings(Clip& clip, const std::vector<CurveKeyRef>& keys, const std::function<void(KeySettings&)>& change) {
  int skipped = 0;
  std::vector<std::pair<int, int>> done;
  for (const CurveKeyRef& k : keys) {
    if (k.channel < 0 || k.channel >= static_cast<int>(clip.channels.size())) continue;
    Channel& ch = clip.channels[k.channel];
    if (k.key < 0 || k.key >= ch.keyCount()) continue;
    if (std::find(done.begin(), done.end(), std::make_pair(k.channel, k.key)) != done.end()) continue;
    done.push_back({k.channel, k.key});
    KeySettings s = ch.settings(k.key);
    change(s);
    if (!interpolationSuits(s.interpolation, ch.target)) {
      ++skipped;
      continue;
    }
    giveKeysTheirSettings(ch);
    ch.keys[k.key] = s;
  }
  return skipped;
}

glm::vec2 handleDeltaFromPixels(const CurveView& v, const PlotRect& r, glm::vec2 d) {
  return {d.x / r.w * (v.t1 - v.t0), -d.y / r.h * (v.v1 - v.v0)};
}

void dragBezierHandle(Channel& ch, int key, bool right, int component, float timeOffset, float valueOffset,
                      float framesPerSecond) {
  if (key < 0 || key >= ch.keyCount()) return;
  giveKeysTheirSettings(ch);
  // The handles as drawn (auto types computed) become the stored ones, so that turning an
  // auto handle into an aligned one keeps the curve's shape, as in Blender.
  const BezierHandles eff = effectiveHandles(ch, key);
  KeySettings& s = ch.keys[key];
  s.leftHandleTime = eff.leftTime, s.rightHandleTime = eff.rightTime;
  s.leftHandleValue = eff.leftValue, s.rightHandleValue = eff.rightValue;
  const float fps = framesPerSecond > 0.0f ? framesPerSecond : 1.0f;
  const float oldTime = right ? eff.rightTime : eff.leftTime;
  const float otherTime0 = right ? eff.leftTime : eff.rightTime;
  const float otherValue0 = (right ? eff.leftValue : eff.rightValue)[component];
  const float otherLength = std::hypot(otherTime0 * fps, otherValue0);
  timeOffset = right ? std::max(0.0f, timeOffset) : std::min(0.0f, timeOffset);
  // The other components keep their slopes under the shared time offset.
  glm::vec4 value = right ? eff.rightValue : eff.leftValue;
  if (oldTime != 0.0f) value *= timeOffset / oldTime;
  value[component] = valueOffset;
  setBezierHandle(ch, key, right, timeOffset, value);
  const HandleType self = right ? s.rightHandleType : s.leftHandleType;
  const HandleType other = right ? s.leftHandleType : s.rightHandleType;
  const float length = std::hypot(timeOffset * fps, valueOffset);
  if (self == HandleType::Aligned && other == HandleType::Aligned && length > 1e-9f && otherLength > 0.0f) {
    // Opposite direction through the key, the other handle's length kept (this component's plane).
    const float otherTime = -timeOffset * otherLength / length;
    if (timeOffset != 0.0f) {
      (right ? s.leftHandleTime : s.rightHandleTime) = otherTime;
      (right ? s.leftHandleValue : s.rightHandleValue) = value * (otherTime / timeOffset);
    } else {
      // A vertical handle: the other one points straight the other way.
      (right ? s.leftHandleTime : s.rightHandleTime) = 0.0f;
      glm::vec4& ov = right ? s.leftHandleValue : s.rightHandleValue;
      ov[component] = valueOffset > 0 ? -otherLength : otherLength;
    }
  }
}

namespace {

// Rotation keys in the Euler view: the Euler angles (radians) of the quaternion key plus a
// handle's value offset, unwrapped next to the key's own angles.
glm::vec3 handleEuler(const glm::quat& key, const glm::vec4& handle, EulerOrder order) {
  const glm::vec3 k = quatToEuler(key, order);
  glm::vec3 e = quatToEuler(safeNormalize(toQuat(toVec(key) + handle)), order);
  for (int i = 0; i < 3; ++i) e[i] = unwrapNear(e[i], k[i], 2.0f * kPi);
  return e;
}

}  // namespace

std::vector<CurveHandle> curveHandles(const Channel& ch, const CurveKeyRef& k, RotationView view, EulerOrder order) {
  std::vector<CurveHandle> out;
  const int n = ch.keyCount();
  if (k.key < 0 || k.key >= n) return out;
  const KeySettings s = ch.settings(k.key);
  const bool eulerRotation = isRotationEuler(ch, view);
  const float unit = displayUnitScale(ch, view);
  const bool bezier = s.interpolation == Interpolation::Bezier ||
                      (k.key > 0 && ch.settings(k.key - 1).interpolation == Interpolation::Bezier);
  if (bezier) {
    const BezierHandles h = effectiveHandles(ch, k.key);
    const glm::quat q = safeNormalize(toQuat(ch.values[k.key]));
    for (bool right : {false, true}) {
      const float time = right ? h.rightTime : h.leftTime;
      const glm::vec4& value = right ? h.rightValue : h.leftValue;
      if (time == 0.0f && value == glm::vec4(0.0f)) continue;  // a lone key's: nothing to draw
      float dv = value[k.component] * unit;
      if (eulerRotation) dv = (handleEuler(q, value, order)[k.component] - quatToEuler(q, order)[k.component]) * unit;
      out.push_back({k, right, false, {time, dv}});
    }
  }
  if (eulerRotation) return out;
  if (k.key > 0 && ch.settings(k.key - 1).interpolation == Interpolation::Hermite) {
    const float ht = -(ch.times[k.key] - ch.times[k.key - 1]) / 3.0f;
    out.push_back({k, false, true, {ht, s.inTangent[k.component] * ht * unit}});
  }
  if (k.key + 1 < n && s.interpolation == Interpolation::Hermite) {
    const float ht = (ch.times[k.key + 1] - ch.times[k.key]) / 3.0f;
    out.push_back({k, true, true, {ht, s.outTangent[k.component] * ht * unit}});
  }
  return out;
}

void dragCurveHandle(Channel& ch, const CurveHandle& h, glm::vec2 offset, RotationView view, EulerOrder order,
                     float framesPerSecond) {
  const int key = h.key.key, component = h.key.component;
  if (key < 0 || key >= ch.keyCount()) return;
  const float value = offset.y / displayUnitScale(ch, view);  // stored units (radians for angles)
  if (h.hermite) return setHermiteTangentFromHandle(ch, key, h.right, component, offset.x, value);
  if (!isRotationEuler(ch, view)) return dragBezierHandle(ch, key, h.right, component, offset.x, value, framesPerSecond);
  // Euler view of a quaternion curve: the handle's control point turned to the dragged angle.
  const BezierHandles eff = effectiveHandles(ch, key);
  const float oldTime = h.right ? eff.rightTime : eff.leftTime;
  const float time = h.right ? std::max(0.0f, offset.x) : std::min(0.0f, offset.x);
  glm::vec4 handle = h.right ? eff.rightValue : eff.leftValue;
  if (oldTime != 0.0f) handle *= time / oldTime;  // the other angles keep their slopes
  const glm::quat q = safeNormalize(toQuat(ch.values[key]));
  glm::vec3 e = handleEuler(q, handle, order);
  e[component] = quatToEuler(q, order)[component] + value;
  glm::quat p = eulerToQuat(e, order);
  if (glm::dot(p, q) < 0.0f) p = -p;
  // The control point on the tangent plane at the key (key + handle orthogonal to it); a
  // handle turned a half turn or more away is held just short of it.
  const float along = std::max(glm::dot(p, q), 0.05f);
  giveKeysTheirSettings(ch);
  // The handles as drawn (auto types computed) become the stored ones, as in dragBezierHandle.
  KeySettings& s = ch.keys[key];
  s.leftHandleTime = eff.leftTime, s.rightHandleTime = eff.rightTime;
  s.leftHandleValue = eff.leftValue, s.rightHandleValue = eff.rightValue;
  setBezierHandle(ch, key, h.right, time, toVec(p) / along - toVec(q));
}

void setHermiteTangentFromHandle(Channel& ch, int key, bool right, int component, float timeOffset, float valueOffset) {
  if (key < 0 || key >= ch.keyCount()) return;
  giveKeysTheirSettings(ch);
  // A handle pulled through the key onto the other side would flip the slope's meaning: clamp.
  const float t = right ? std::max(timeOffset, 1e-4f) : std::min(timeOffset, -1e-4f);
  (right ? ch.keys[key].outTangent : ch.keys[key].inTangent)[component] = valueOffset / t;
}

}  // namespace kinema
