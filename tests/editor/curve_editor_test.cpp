// The curve editor's model (src/editor/curve_editor.h): channel views (Euler angles of a
// quaternion channel against a decomposition written here from the rotation matrix,
// quaternion components), fit / normalize / zoom / pan maps, handle dragging maths
// (Blender's aligned rule: the other handle stays collinear and keeps its length), key
// settings on selected keys, and undo / redo of those edits through the Document.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "anim/sampling.h"
#include "editor/model/curve_editor.h"
#include "anim/insert_keyframe.h"
#include "editor/model/document.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;  // the Euler view shows angles in degrees

// R = Rx(x) Ry(y) Rz(z) built from axis-angle quaternions (double precision, glm only).
glm::dquat xyzQuat(double x, double y, double z) {
  return glm::angleAxis(x, glm::dvec3(1, 0, 0)) * glm::angleAxis(y, glm::dvec3(0, 1, 0)) *
         glm::angleAxis(z, glm::dvec3(0, 0, 1));
}
// Inverse for the XYZ order from the matrix of R = Rx Ry Rz:
//   r02 = sin y, r12 = -sin x cos y, r22 = cos x cos y, r01 = -cos y sin z, r00 = cos y cos z.
glm::dvec3 xyzAngles(const glm::dquat& q) {
  const glm::dmat3 m = glm::mat3_cast(q);  // m[col][row]
  const double r02 = m[2][0], r12 = m[2][1], r22 = m[2][2], r01 = m[1][0], r00 = m[0][0];
  return {std::atan2(-r12, r22), std::asin(std::clamp(r02, -1.0, 1.0)), std::atan2(-r01, r00)};
}
glm::vec4 vec(const glm::dquat& q) { return glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w)); }

Channel rotationChannel(std::vector<float> times, std::vector<glm::dquat> qs) {
  std::vector<glm::vec4> values;
  for (const glm::dquat& q : qs) values.push_back(vec(q));
  return Channel(0, ChannelTarget::Rotation, Interpolation::Linear, std::move(times), std::move(values));
}

Channel translationChannel() {
  // Keys at frames 0, 10, 20, 30 of a 30 fps clip: y = 0, 1, 3, 2 (x = 10 y, z = -y).
  std::vector<glm::vec4> v;
  for (float y : {0.0f, 1.0f, 3.0f, 2.0f}) v.push_back({10 * y, y, -y, 0});
  return Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f / 3, 2.0f / 3, 1.0f}, v);
}

TEST(CurveEditor, EulerViewOfAQuaternionChannelEqualsTheIndependentDecomposition) {
  const glm::dquat a = xyzQuat(0.3, -0.4, 0.5), b = xyzQuat(1.0, 0.2, -0.7);
  const Channel ch = rotationChannel({0.0f, 1.0f}, {a, b});
  // Two samples per segment: the middle point is the slerp at u = 1/2.
  const glm::dvec3 mid = xyzAngles(glm::slerp(a, b, 0.5));
  const double expectedKeys[2][3] = {{0.3, -0.4, 0.5}, {1.0, 0.2, -0.7}};
  for (int c = 0; c < 3; ++c) {
    const CurvePoints p = curvePoints(ch, c, RotationView::Euler, EulerOrder::XYZ, 2);
    ASSERT_EQ(p.keyValues.size(), 2u);
    ASSERT_EQ(p.times.size(), 3u);
    EXPECT_NEAR(p.keyValues[0], expectedKeys[0][c] * kDeg, 1e-3) << "component " << c;
    EXPECT_NEAR(p.keyValues[1], expectedKeys[1][c] * kDeg, 1e-3) << "component " << c;
    EXPECT_FLOAT_EQ(p.times[1], 0.5f);
    EXPECT_NEAR(p.values[1], mid[c] * kDeg, 1e-3) << "component " << c;
    EXPECT_NEAR(keyDisplayValue(ch, 1, c, RotationView::Euler, EulerOrder::XYZ), expectedKeys[1][c] * kDeg, 1e-3);
  }
}

TEST(CurveEditor, EulerViewUnwrapsAnglesAlongTheCurve) {
  // About Z: 0, 170, 190 degrees. The plain decomposition of 190 is -170; the view shows 190.
  const double d = kPi / 180;
  const Channel ch = rotationChannel({0.0f, 1.0f, 2.0f}, {xyzQuat(0, 0, 0), xyzQuat(0, 0, 170 * d), xyzQuat(0, 0, 190 * d)});
  const CurvePoints p = curvePoints(ch, 2, RotationView::Euler, EulerOrder::XYZ, 8);
  EXPECT_NEAR(p.keyValues[0], 0.0, 1e-3);
  EXPECT_NEAR(p.keyValues[1], 170.0, 1e-3);
  EXPECT_NEAR(p.keyValues[2], 190.0, 1e-3);
  for (size_t i = 1; i < p.values.size(); ++i) EXPECT_LT(std::abs(p.values[i] - p.values[i - 1]), 45.0) << i;
}

TEST(CurveEditor, QuaternionComponentViewAndRenormalisingEdits) {
  const glm::dquat a = xyzQuat(0.3, -0.4, 0.5);
  Channel ch = rotationChannel({0.0f, 1.0f}, {a, glm::dquat(1, 0, 0, 0)});
  EXPECT_EQ(curveCount(ch, RotationView::Quaternion), 4);
  EXPECT_EQ(curveCount(ch, RotationView::Euler), 3);
  const double expected[4] = {a.x, a.y, a.z, a.w};
  for (int c = 0; c < 4; ++c)
    EXPECT_NEAR(curvePoints(ch, c, RotationView::Quaternion, EulerOrder::XYZ).keyValues[0], expected[c], 1e-6);
  // Identity with x set to 1: (1, 0, 0, 1) / sqrt 2.
  setKeyDisplayValue(ch, 1, 0, RotationView::Quaternion, EulerOrder::XYZ, 1.0f);
  const float h = float(1 / std::sqrt(2.0));
  EXPECT_NEAR(ch.values[1].x, h, 1e-6);
  EXPECT_NEAR(ch.values[1].w, h, 1e-6);
  EXPECT_NEAR(ch.values[1].y, 0, 1e-6);
}

TEST(CurveEditor, EulerViewEditsConvertBackToTheQuaternion) {
  Channel ch = rotationChannel({0.0f, 1.0f}, {xyzQuat(0.3, -0.4, 0.5), xyzQuat(0, 0, 0)});
  setKeyDisplayValue(ch, 0, 2, RotationView::Euler, EulerOrder::XYZ, float(0.9 * kDeg));  // typed in degrees
  const glm::dquat expected = xyzQuat(0.3, -0.4, 0.9);
  const glm::dquat got(ch.values[0].w, ch.values[0].x, ch.values[0].y, ch.values[0].z);
  EXPECT_NEAR(std::abs(glm::dot(got, expected)), 1.0, 1e-6);
  EXPECT_GT(glm::dot(got, xyzQuat(0.3, -0.4, 0.5)), 0.0);  // kept in the key's hemisphere
}

TEST(CurveEditor, FitNormalizeZoomAndPanMaps) {
  CurvePoints a, b;
  a.times = {0.0f, 2.0f};
  a.values = {1.0f, 3.0f};
  b.times = {1.0f, 4.0f};
  b.values = {-5.0f, 5.0f};
  // All points: t in [0, 4], v in [-5, 5]; 10 % margins.
  const CurveView v = fitView({a, b}, false, 0.1f);
  EXPECT_FLOAT_EQ(v.t0, -0.4f);
  EXPECT_FLOAT_EQ(v.t1, 4.4f);
  EXPECT_FLOAT_EQ(v.v0, -6.0f);
  EXPECT_FLOAT_EQ(v.v1, 6.0f);
  // Normalized: each curve's range onto [-1, 1].
  const ValueRange ra = curveRange(a);
  EXPECT_FLOAT_EQ(normalizeValue(ra, 1.0f), -1.0f);
  EXPECT_FLOAT_EQ(normalizeValue(ra, 3.0f), 1.0f);
  EXPECT_FLOAT_EQ(normalizeValue(ra, 2.5f), 0.5f);
  EXPECT_FLOAT_EQ(denormalizeValue(ra, 0.5f), 2.5f);
  EXPECT_FLOAT_EQ(displayToValueScale(ra, true), 1.0f);
  EXPECT_FLOAT_EQ(displayToValueScale(curveRange(b), true), 5.0f);
  const CurveView n = fitView({a, b}, true, 0.1f);
  EXPECT_FLOAT_EQ(n.v0, -1.2f);
  EXPECT_FLOAT_EQ(n.v1, 1.2f);
  // Plot 400 x 200 px at (10, 20) showing t 0..4, v -1..1.
  const PlotRect r{10, 20, 400, 200};
  CurveView z{0, 4, -1, 1};
  const glm::vec2 p = curveToScreen(z, r, 1.0f, 0.5f);
  EXPECT_FLOAT_EQ(p.x, 110.0f);
  EXPECT_FLOAT_EQ(p.y, 70.0f);
  const glm::vec2 back = screenToCurve(z, r, p);
  EXPECT_FLOAT_EQ(back.x, 1.0f);
  EXPECT_FLOAT_EQ(back.y, 0.5f);
  // Zoom x2 about that pixel: it stays over (1, 0.5), the extents halve.
  zoomView(z, r, p, 2.0f, true, true);
  EXPECT_FLOAT_EQ(z.t1 - z.t0, 2.0f);
  EXPECT_FLOAT_EQ(z.v1 - z.v0, 1.0f);
  EXPECT_NEAR(screenToCurve(z, r, p).x, 1.0f, 1e-6);
  EXPECT_NEAR(screenToCurve(z, r, p).y, 0.5f, 1e-6);
  // One axis only (Ctrl+wheel): values untouched.
  CurveView t = z;
  zoomView(t, r, p, 2.0f, true, false);
  EXPECT_FLOAT_EQ(t.t1 - t.t0, 1.0f);
  EXPECT_FLOAT_EQ(t.v0, z.v0);
  EXPECT_FLOAT_EQ(t.v1, z.v1);
  // Pan right 100 px (a quarter of the width) and down 50 px: the plane follows the mouse.
  CurveView q{0, 4, -1, 1};
  panView(q, r, {100, 50});
  EXPECT_FLOAT_EQ(q.t0, -1.0f);
  EXPECT_FLOAT_EQ(q.t1, 3.0f);
  EXPECT_FLOAT_EQ(q.v0, -0.5f);
  EXPECT_FLOAT_EQ(q.v1, 1.5f);
}

TEST(CurveEditor, PixelDeltaToHandleOffset) {
  // 200 x 100 px showing 2 s and 10 units: 100 px per second, 10 px per unit (y down).
  const glm::vec2 d = handleDeltaFromPixels({0, 2, 0, 10}, {0, 0, 200, 100}, {50, -20});
  EXPECT_FLOAT_EQ(d.x, 0.5f);
  EXPECT_FLOAT_EQ(d.y, 2.0f);
}

Channel bezierChannel(HandleType type) {
  Channel ch = translationChannel();
  ch.keys.resize(4);
  for (KeySettings& s : ch.keys) {
    s.interpolation = Interpolation::Bezier;
    s.leftHandleType = s.rightHandleType = type;
  }
  KeySettings& k = ch.keys[1];
  k.leftHandleTime = -0.1f;
  k.leftHandleValue = {-1.0f, 0.2f, 0.3f, 0};
  k.rightHandleTime = 0.05f;
  k.rightHandleValue = {0.5f, -0.1f, -0.15f, 0};
  return ch;
}

TEST(CurveEditor, DraggingAnAlignedHandleTurnsTheOtherCollinearKeepingItsLength) {
  Channel ch = bezierChannel(HandleType::Aligned);
  const float fps = 30;
  // Left handle of component 1 (y) in the frames x value plane: (-3 frames, 0.2).
  const double length0 = std::hypot(-0.1 * fps, 0.2);
  dragBezierHandle(ch, 1, true, 1, 0.2f, 0.6f, fps);
  const KeySettings& s = ch.keys[1];
  EXPECT_EQ(s.leftHandleType, HandleType::Aligned);
  EXPECT_EQ(s.rightHandleType, HandleType::Aligned);
  EXPECT_FLOAT_EQ(s.rightHandleTime, 0.2f);
  EXPECT_FLOAT_EQ(s.rightHandleValue.y, 0.6f);
  // Other components keep their slopes: x was 0.5 over 0.05 s (10 per second).
  EXPECT_NEAR(s.rightHandleValue.x / s.rightHandleTime, 10.0, 1e-4);
  // Collinear and opposite: left = -k * right in the (frames, value) plane, same length as before.
  const double lt = s.leftHandleTime * fps, lv = s.leftHandleValue.y, rt = 0.2 * fps, rv = 0.6;
  EXPECT_NEAR(lt * rv - lv * rt, 0.0, 1e-5);
  EXPECT_LT(lt, 0.0);
  EXPECT_LT(lv, 0.0);
  EXPECT_NEAR(std::hypot(lt, lv), length0, 1e-5);
  // And the curve still passes through the key with the new handle (the engine evaluates it).
  EXPECT_NEAR(sampleChannel(ch, ch.times[1]).y, 1.0, 1e-6);
}

TEST(CurveEditor, DraggingAFreeHandleLeavesTheOtherAlone) {
  Channel ch = bezierChannel(HandleType::Free);
  dragBezierHandle(ch, 1, true, 1, 0.2f, 0.6f, 30);
  EXPECT_FLOAT_EQ(ch.keys[1].leftHandleTime, -0.1f);
  EXPECT_FLOAT_EQ(ch.keys[1].leftHandleValue.y, 0.2f);
  EXPECT_FLOAT_EQ(ch.keys[1].rightHandleValue.y, 0.6f);
}

TEST(CurveEditor, DraggingAnAutoHandleMakesBothAlignedFromTheDrawnShape) {
  Channel ch = bezierChannel(HandleType::AutoClamped);
  dragBezierHandle(ch, 1, false, 1, -0.15f, -0.5f, 30);
  const KeySettings& s = ch.keys[1];
  EXPECT_EQ(s.leftHandleType, HandleType::Aligned);
  EXPECT_EQ(s.rightHandleType, HandleType::Aligned);
  EXPECT_FLOAT_EQ(s.leftHandleTime, -0.15f);
  EXPECT_FLOAT_EQ(s.leftHandleValue.y, -0.5f);
  // Right turned collinear (slope 0.5/0.15 per second), length of the auto-clamped handle kept:
  // key 1 (y = 1) between 0 and 3 is not an extremum; auto handle = a third of the interval
  // (10/3 frames) along the neighbours' chord slope (3 - 0) / (2/3 s) = 4.5 per second.
  const double autoT = 10.0 / 3, autoV = 4.5 / 30 * autoT;
  EXPECT_NEAR(s.rightHandleValue.y / s.rightHandleTime, 0.5 / 0.15, 1e-3);
  EXPECT_NEAR(std::hypot(s.rightHandleTime * 30.0, double(s.rightHandleValue.y)), std::hypot(autoT, autoV), 1e-3);
}

TEST(CurveEditor, HermiteHandleSetsTheSlope) {
  Channel ch = translationChannel();
  setHermiteTangentFromHandle(ch, 1, true, 1, 0.25f, 0.5f);
  setHermiteTangentFromHandle(ch, 2, false, 0, -0.5f, 0.25f);
  EXPECT_FLOAT_EQ(ch.keys[1].outTangent.y, 2.0f);
  EXPECT_FLOAT_EQ(ch.keys[2].inTangent.x, -0.5f);
}

TEST(CurveEditor, TcbWithTensionOneOnSelectedKeysIsAHermiteWithZeroTangents) {
  Clip clip;
  clip.frameTime = 1.0 / 30;
  clip.channels.push_back(translationChannel());
  clip.channels.push_back(rotationChannel({0.0f, 1.0f}, {xyzQuat(0, 0, 0), xyzQuat(0, 0, 1)}));
  // Keys 1 and 2 (interior) of the translation, y curve and x curve of key 1 (the same key),
  // and a rotation key (TCB does not apply to rotations: left alone).
  const std::vector<CurveKeyRef> keys = {{0, 1, 1}, {0, 0, 1}, {0, 1, 2}, {1, 0, 0}};
  const int skipped = changeKeySettings(clip, keys, [](KeySettings& s) {
    s.interpolation = Interpolation::TCB;
    s.tension = 1.0f;
  });
  EXPECT_EQ(skipped, 1);
  EXPECT_TRUE(clip.channels[1].keys.empty());
  const Channel& ch = clip.channels[0];
  ASSERT_EQ(ch.keys.size(), 4u);
  EXPECT_EQ(ch.keys[0].interpolation, Interpolation::Linear);
  EXPECT_EQ(ch.keys[1].interpolation, Interpolation::TCB);
  EXPECT_EQ(ch.keys[1].tension, 1.0f);
  EXPECT_EQ(ch.keys[2].tension, 1.0f);
  // Segment 1 -> 2 (y from 1 to 3 over 1/3 s) at u = 1/4: 1 + 2 (3u^2 - 2u^3) = 1 + 2 * 5/32.
  const float t = 1.0f / 3 + 0.25f / 3;
  EXPECT_NEAR(sampleChannel(ch, t).y, 1.0 + 2.0 * 5.0 / 32.0, 1e-5);
  EXPECT_TRUE(clip.validate([] {
                Skeleton s;
                s.addJoint("root", -1, Transform());
                return s;
              }()).empty());
}

TEST(CurveEditor, StepAndLinearOnSelectedKeys) {
  Clip clip;
  clip.channels.push_back(translationChannel());
  changeKeySettings(clip, {{0, 1, 1}}, [](KeySettings& s) { s.interpolation = Interpolation::Step; });
  const float t = 0.5f;  // in segment 1 -> 2
  EXPECT_FLOAT_EQ(sampleChannel(clip.channels[0], t).y, 1.0f);
  changeKeySettings(clip, {{0, 1, 1}}, [](KeySettings& s) { s.interpolation = Interpolation::Linear; });
  EXPECT_NEAR(sampleChannel(clip.channels[0], t).y, 2.0f, 1e-5);
}

TEST(CurveEditor, ShownChannelsAreThoseOfTheSelectedJoints) {
  Clip clip;
  clip.channels.push_back(translationChannel());  // joint 0
  Channel other = translationChannel();
  other.joint = 1;
  clip.channels.push_back(other);
  JointSelection sel;
  sel.click(1);
  EXPECT_EQ(shownChannels(clip, sel), std::vector<int>{1});
  sel.shiftClick(0);
  EXPECT_EQ(shownChannels(clip, sel), (std::vector<int>{0, 1}));
}

TEST(CurveEditor, NlerpAndSquadApplyToRotationKeysOnly) {
  Clip clip;
  clip.channels.push_back(translationChannel());
  clip.channels.push_back(rotationChannel({0.0f, 1.0f}, {xyzQuat(0, 0, 0), xyzQuat(0, 0, 1)}));
  const int skipped = changeKeySettings(clip, {{0, 0, 0}, {1, 3, 0}}, [](KeySettings& s) {
    s.interpolation = Interpolation::Squad;
  });
  EXPECT_EQ(skipped, 1);
  EXPECT_TRUE(clip.channels[0].keys.empty());
  ASSERT_EQ(clip.channels[1].keys.size(), 2u);
  EXPECT_EQ(clip.channels[1].keys[0].interpolation, Interpolation::Squad);
  EXPECT_EQ(clip.channels[1].keys[1].interpolation, Interpolation::Linear);  // the channel's, kept
}

TEST(CurveEditor, DraggingARotationKeyInTheEulerViewTurnsOnlyThatAngle) {
  // Key 1 at XYZ angles (0.2, 0.1, 0.4) rad; its Z curve dragged up by 0.3 rad (in degrees) in the view.
  Clip clip;
  clip.frameTime = 1.0 / 30;
  clip.channels.push_back(rotationChannel({0.0f, 1.0f}, {xyzQuat(0, 0, 0), xyzQuat(0.2, 0.1, 0.4)}));
  moveCurveKeys(clip, ownFrameGrid(clip), {{0, 2, 1}}, {float(0.4 * kDeg)}, {1.0f}, 0.0f, float(0.3 * kDeg), RotationView::Euler,
                EulerOrder::XYZ);
  const glm::vec4 v = clip.channels[0].values[1];
  EXPECT_NEAR(std::abs(glm::dot(glm::dquat(v.w, v.x, v.y, v.z), xyzQuat(0.2, 0.1, 0.7))), 1.0, 1e-6);
  EXPECT_NEAR(glm::length(v), 1.0, 1e-6);
  // In the normalized view a display step is scaled by half the curve's range (here 2).
  Clip t;
  t.frameTime = 1.0 / 30;
  t.channels.push_back(translationChannel());
  moveCurveKeys(t, ownFrameGrid(t), {{0, 1, 1}}, {1.0f}, {2.0f}, 0.0f, 0.25f, RotationView::Euler, EulerOrder::XYZ);
  EXPECT_FLOAT_EQ(t.channels[0].values[1].y, 1.5f);
}

Scene keyedScene() {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform());
  Clip clip;
  clip.frameTime = 1.0 / 30;
  clip.channels.push_back(translationChannel());
  scene.clips.push_back(clip);
  return scene;
}

void expectSameChannel(const Channel& a, const Channel& b) {
  EXPECT_EQ(a.times, b.times);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.keys, b.keys);
}

TEST(CurveEditor, KeyEditsAreUndoStepsRestoredExactly) {
  Document doc(keyedScene());
  const Channel original = doc.scene().clips[0].channels[0];
  ASSERT_EQ(doc.edit("Key TCB", [](DocumentEdit& e) {
    changeKeySettings(e.clips[0], {{0, 1, 1}}, [](KeySettings& s) {
      s.interpolation = Interpolation::TCB;
      s.tension = 1.0f;
      s.bias = -0.25f;
    });
    return std::string();
  }), "");
  const Channel edited = doc.scene().clips[0].channels[0];
  // A key drag: several updates, one step; time snapped to frames (0.12 s -> frame 4 away).
  ASSERT_EQ(doc.beginDrag("Move keys"), "");
  for (float dt : {0.05f, 0.12f}) {
    doc.updateDrag([&](DocumentEdit& e) {
      moveCurveKeys(e.clips[0], ownFrameGrid(e.clips[0]), {{0, 1, 2}}, {3.0f}, {1.0f}, dt, 0.5f, RotationView::Euler, EulerOrder::XYZ);
      return std::string();
    });
  }
  doc.commitDrag();
  const Channel moved = doc.scene().clips[0].channels[0];
  EXPECT_FLOAT_EQ(moved.times[2], ownFrameGrid(doc.scene().clips[0]).frameToTime(24));
  EXPECT_FLOAT_EQ(moved.values[2].y, 3.5f);
  EXPECT_EQ(doc.historyPosition(), 2);
  ASSERT_TRUE(doc.undo());
  expectSameChannel(doc.scene().clips[0].channels[0], edited);
  ASSERT_TRUE(doc.undo());
  expectSameChannel(doc.scene().clips[0].channels[0], original);
  ASSERT_TRUE(doc.redo());
  expectSameChannel(doc.scene().clips[0].channels[0], edited);
  ASSERT_TRUE(doc.redo());
  expectSameChannel(doc.scene().clips[0].channels[0], moved);
}

TEST(CurveEditor, MovingAKeyPastItsNeighbourKeepsTheSelectionOnIt) {
  Clip clip;
  clip.frameTime = 1.0 / 30;
  clip.channels.push_back(translationChannel());
  // Key 1 (frame 10) moved 15 frames right: lands at frame 25, between keys 2 and 3.
  const std::vector<CurveKeyRef> out =
      moveCurveKeys(clip, ownFrameGrid(clip), {{0, 1, 1}}, {1.0f}, {1.0f}, 0.5f, 0.0f, RotationView::Euler, EulerOrder::XYZ);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].key, 2);
  EXPECT_FLOAT_EQ(clip.channels[0].times[2], ownFrameGrid(clip).frameToTime(25));
  EXPECT_FLOAT_EQ(clip.channels[0].values[2].y, 1.0f);
}


// The numbers: a rotation of -1.0796 rad about X is -61.86 degrees in the curve
// editor (as in the properties panel); typing degrees stores the radian value.
TEST(CurveEditorDegrees, AnglesAreShownAndTypedInDegrees) {
  Channel rot = rotationChannel({0.0f, 1.0f}, {xyzQuat(-1.0796, 0, 0), xyzQuat(0, 0, 0)});
  EXPECT_NEAR(keyDisplayValue(rot, 0, 0, RotationView::Euler, EulerOrder::XYZ), -61.857, 1e-3);
  EXPECT_NEAR(curvePoints(rot, 0, RotationView::Euler, EulerOrder::XYZ).keyValues[0], -61.857, 1e-3);
  EXPECT_FLOAT_EQ(displayUnitScale(rot, RotationView::Euler), float(kDeg));
  EXPECT_STREQ(displayUnitName(rot, RotationView::Euler), "deg");
  // The quaternion view stays unitless.
  EXPECT_EQ(displayUnitScale(rot, RotationView::Quaternion), 1.0f);
  EXPECT_STREQ(displayUnitName(rot, RotationView::Quaternion), "");
  EXPECT_NEAR(keyDisplayValue(rot, 0, 0, RotationView::Quaternion, EulerOrder::XYZ), std::sin(-1.0796 / 2), 1e-6);
  // 45 typed into the X field of key 1: a rotation of pi/4 about X.
  setKeyDisplayValue(rot, 1, 0, RotationView::Euler, EulerOrder::XYZ, 45.0f);
  EXPECT_NEAR(std::abs(glm::dot(glm::dquat(rot.values[1].w, rot.values[1].x, rot.values[1].y, rot.values[1].z),
                                xyzQuat(kPi / 4, 0, 0))),
              1.0, 1e-6);
  // Euler channels (radians stored) show degrees too; locations stay as stored.
  Channel euler(0, ChannelTarget::Euler, Interpolation::Linear, {0.0f}, {{0.5f, 0, 0, 0}});
  EXPECT_NEAR(keyDisplayValue(euler, 0, 0, RotationView::Quaternion, EulerOrder::XYZ), 0.5 * kDeg, 1e-4);
  setKeyDisplayValue(euler, 0, 1, RotationView::Euler, EulerOrder::XYZ, 90.0f);
  EXPECT_NEAR(euler.values[0].y, kPi / 2, 1e-6);
  Channel loc = translationChannel();
  EXPECT_EQ(displayUnitScale(loc, RotationView::Euler), 1.0f);
  EXPECT_FLOAT_EQ(keyDisplayValue(loc, 1, 1, RotationView::Euler, EulerOrder::XYZ), 1.0f);
}

// A rotation keyed twice with the defaults (insertKeyframe: Bezier, auto-clamped) eases in
// and out. Closed form: the two end keys' handles are flat and a third of the interval
// long, so each quaternion component is a + (b - a) s(u), s = 3u^2 - 2u^3, normalised;
// about one axis the angle is 2 atan2 of the blended (sin, cos) of the half angles.
TEST(CurveEditorDefaults, ANewRotationKeyEasesInAndOutInThePlotAndInPlayback) {
  Skeleton skeleton;
  skeleton.addJoint("root", -1, Transform());
  Clip clip;
  clip.frameTime = 1.0 / 24;
  const double a0 = 0.0, a1 = kPi / 2;  // 0 -> 90 degrees about Z
  for (int k = 0; k < 2; ++k) {
    Pose pose = Pose::rest(skeleton);
    pose.local[0].rotation = glm::angleAxis(float(k == 0 ? a0 : a1), glm::vec3(0, 0, 1));
    InsertKeyframeJob job;
    job.joints = {0};
    job.time = k == 0 ? 0.0f : 1.0f;
    ASSERT_EQ(insertKeyframe(clip, job, pose), 2);
  }
  ASSERT_EQ(clip.validate(skeleton), "");
  const Channel* rot = nullptr;
  for (const Channel& c : clip.channels)
    if (c.target == ChannelTarget::Rotation) rot = &c;
  ASSERT_NE(rot, nullptr);
  EXPECT_EQ(rot->settings(0).interpolation, Interpolation::Bezier);
  auto eased = [&](double u) {
    const double s = 3 * u * u - 2 * u * u * u;
    return 2 * std::atan2(s * std::sin(a1 / 2), (1 - s) + s * std::cos(a1 / 2)) * kDeg;
  };
  // 4 samples a segment: the plotted points at u = 1/4, 1/2, 3/4.
  const CurvePoints z = curvePoints(*rot, 2, RotationView::Euler, EulerOrder::XYZ, 4);
  ASSERT_EQ(z.times.size(), 5u);
  for (int i = 1; i < 4; ++i) {
    const double u = i / 4.0;
    EXPECT_NEAR(z.values[size_t(i)], eased(u), 1e-3) << u;
    EXPECT_NEAR(curveValueAt(*rot, 2, RotationView::Euler, EulerOrder::XYZ, z, float(u)), eased(u), 1e-3) << u;
    // Playback follows the plotted curve.
    Pose pose = Pose::rest(skeleton);
    sampleClip(clip, float(u), pose);
    EXPECT_NEAR(2 * std::atan2(pose.local[0].rotation.z, pose.local[0].rotation.w) * kDeg, z.values[size_t(i)], 1e-3);
  }
  EXPECT_LT(z.values[1], 90.0 * 0.25 - 5.0) << "a quarter in, the ease lags the straight line";
  EXPECT_NEAR(z.values[2], 45.0, 1e-3) << "symmetric about the middle";
  EXPECT_GT(z.values[3], 90.0 * 0.75 + 5.0);
  // Zero slope at both keys: the first 1% of the interval moves far less than 1% of the angle.
  const float start = curveValueAt(*rot, 2, RotationView::Euler, EulerOrder::XYZ, z, 0.01f);
  const float end = curveValueAt(*rot, 2, RotationView::Euler, EulerOrder::XYZ, z, 0.99f);
  EXPECT_LT(start, 0.9 * 0.05);
  EXPECT_GT(end, 90.0 - 0.9 * 0.05);
}

// Both handles of a Bezier key are shown, also the outer ones of the end keys (mirrored)
// and a left handle whose segment is not Bezier.
TEST(CurveEditorHandles, ABezierKeyShowsBothHandles) {
  Channel ch = translationChannel();
  ch.keys.resize(4);
  for (KeySettings& k : ch.keys) k.interpolation = Interpolation::Bezier;
  ch.keys[0].interpolation = Interpolation::Linear;  // key 1's left side is a linear segment
  for (int k : {1, 2, 3}) {
    const std::vector<CurveHandle> h = curveHandles(ch, {0, 1, k}, RotationView::Euler, EulerOrder::XYZ);
    ASSERT_EQ(h.size(), 2u) << k;
    EXPECT_FALSE(h[0].right);
    EXPECT_TRUE(h[1].right);
    EXPECT_LT(h[0].offset.x, 0.0f);
    EXPECT_GT(h[1].offset.x, 0.0f);
  }
  // Key 3 is the last: its right handle mirrors the left one (flat: auto-clamped end).
  const std::vector<CurveHandle> last = curveHandles(ch, {0, 1, 3}, RotationView::Euler, EulerOrder::XYZ);
  EXPECT_FLOAT_EQ(last[1].offset.x, -last[0].offset.x);
  EXPECT_EQ(last[1].offset.y, 0.0f);
  // Key 0 is Linear with a Bezier neighbour after it only: no handles.
  EXPECT_TRUE(curveHandles(ch, {0, 1, 0}, RotationView::Euler, EulerOrder::XYZ).empty());
  // The left handle of key 1 (an unused side) drags like any other: it becomes aligned.
  dragCurveHandle(ch, curveHandles(ch, {0, 1, 1}, RotationView::Euler, EulerOrder::XYZ)[0], {-0.1f, -0.5f},
                  RotationView::Euler, EulerOrder::XYZ, 30.0f);
  EXPECT_EQ(ch.keys[1].leftHandleType, HandleType::Aligned);
  EXPECT_FLOAT_EQ(ch.keys[1].leftHandleTime, -0.1f);
  EXPECT_FLOAT_EQ(ch.keys[1].leftHandleValue.y, -0.5f);
}

// In the Euler view a rotation key's handle shows (in degrees) where its control point
// turns the joint; dragging it there and reading it back gives the dragged angle, and
// the plotted curve leaves the key in the handle's direction.
TEST(CurveEditorHandles, RotationHandlesInTheEulerViewRoundTripInDegrees) {
  Channel ch = rotationChannel({0.0f, 1.0f, 2.0f}, {xyzQuat(0, 0, 0), xyzQuat(0.2, 0.1, 0.6), xyzQuat(0.3, 0.1, 1.2)});
  ch.interpolation = Interpolation::Bezier;
  const CurveKeyRef key{0, 2, 1};
  std::vector<CurveHandle> h = curveHandles(ch, key, RotationView::Euler, EulerOrder::XYZ);
  ASSERT_EQ(h.size(), 2u);
  // Right handle of key 1 to (0.25 s, +20 degrees) on the Z curve.
  dragCurveHandle(ch, h[1], {0.25f, 20.0f}, RotationView::Euler, EulerOrder::XYZ, 24.0f);
  EXPECT_EQ(ch.keys[1].rightHandleType, HandleType::Aligned);
  h = curveHandles(ch, key, RotationView::Euler, EulerOrder::XYZ);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_NEAR(h[1].offset.x, 0.25, 1e-6);
  EXPECT_NEAR(h[1].offset.y, 20.0, 1e-2);
  // The X and Y angles of the control point were kept.
  const CurveHandle hx = curveHandles(ch, {0, 0, 1}, RotationView::Euler, EulerOrder::XYZ)[1];
  EXPECT_NEAR(hx.offset.x, 0.25, 1e-6);
  // Aligned: the left handle turned to stay collinear in quaternion space, so the curve is
  // smooth through the key: the slopes just before and after it agree.
  const CurvePoints p = curvePoints(ch, 2, RotationView::Euler, EulerOrder::XYZ);
  const float e = 1e-3f;
  const double before = (curveValueAt(ch, 2, RotationView::Euler, EulerOrder::XYZ, p, 1.0f) -
                         curveValueAt(ch, 2, RotationView::Euler, EulerOrder::XYZ, p, 1.0f - e)) / e;
  const double after = (curveValueAt(ch, 2, RotationView::Euler, EulerOrder::XYZ, p, 1.0f + e) -
                        curveValueAt(ch, 2, RotationView::Euler, EulerOrder::XYZ, p, 1.0f)) / e;
  EXPECT_NEAR(before, after, 0.05 * std::abs(after) + 1.0);
  // Tangent direction: a Bezier with its handle a third of the segment long leaves the key
  // at the handle's slope (first order in the handle; 20 degrees over 0.25 s = 80 deg/s).
  EXPECT_NEAR(after, 80.0, 8.0);
}

// New channels carry one interpolation for all keys (Channel::interpolation, `keys` empty):
// editing one key's settings or handle gives every key its own copy of the channel's, so
// the others stay Bezier (they were reset to the default Linear before).
TEST(CurveEditorHandles, EditingOneKeyOfAChannelWideBezierKeepsTheOthersBezier) {
  Clip clip;
  clip.channels.push_back(translationChannel());
  clip.channels[0].interpolation = Interpolation::Bezier;
  changeKeySettings(clip, {{0, 1, 1}}, [](KeySettings& s) { s.interpolation = Interpolation::Step; });
  ASSERT_EQ(clip.channels[0].keys.size(), 4u);
  EXPECT_EQ(clip.channels[0].keys[0].interpolation, Interpolation::Bezier);
  EXPECT_EQ(clip.channels[0].keys[1].interpolation, Interpolation::Step);
  EXPECT_EQ(clip.channels[0].keys[2].interpolation, Interpolation::Bezier);
  Channel ch = translationChannel();
  ch.interpolation = Interpolation::Bezier;
  dragBezierHandle(ch, 1, true, 1, 0.1f, 0.2f, 30.0f);
  for (int k : {0, 2, 3}) EXPECT_EQ(ch.keys[size_t(k)].interpolation, Interpolation::Bezier) << k;
}

// A selects every key of the visible curves; a box selects those whose dots lie inside it.
TEST(CurveEditorSelection, SelectAllAndBoxSelect) {
  Clip clip;
  clip.frameTime = 1.0 / 30;
  clip.channels.push_back(translationChannel());  // keys at t = 0, 1/3, 2/3, 1: x = 10y, y = 0 1 3 2, z = -y
  JointSelection sel;
  sel.click(0);
  CurveEditorState ce;
  std::vector<ShownCurve> curves = shownCurves(clip, sel, ce);
  ASSERT_EQ(curves.size(), 3u);
  EXPECT_EQ(allVisibleKeys(curves, ce).size(), 12u);
  ce.toggleHidden({0, 0});
  const std::vector<CurveKeyRef> all = allVisibleKeys(curves, ce);
  EXPECT_EQ(all.size(), 8u) << "hidden curves' keys are not selected";
  for (const CurveKeyRef& k : all) EXPECT_NE(k.component, 0);
  // View: time 0..1 across 100 px, values -5..35 up 400 px (10 px per unit).
  ce.view = {0.0f, 1.0f, -5.0f, 35.0f};
  ce.plot = {0.0f, 0.0f, 100.0f, 400.0f};
  // The key of y at t = 1/3 (value 1) is at (33.3, 340); z's there (value -1) at (33.3, 360).
  EXPECT_EQ(keysInBox(curves, ce, {25, 335}, {40, 345}), (std::vector<CurveKeyRef>{{0, 1, 1}}));
  EXPECT_EQ(keysInBox(curves, ce, {40, 365}, {25, 335}), (std::vector<CurveKeyRef>{{0, 1, 1}, {0, 2, 1}}))
      << "either corner first";
  // x's key there (value 10, y = 250) is inside this box but its curve is hidden.
  EXPECT_TRUE(keysInBox(curves, ce, {25, 245}, {40, 255}).empty());
  ce.selected = {{0, 1, 3}};
  applyBoxSelection(ce, {{0, 1, 1}}, true);
  EXPECT_EQ(ce.selected, (std::vector<CurveKeyRef>{{0, 1, 3}, {0, 1, 1}})) << "Shift adds";
  applyBoxSelection(ce, {{0, 2, 1}}, false);
  EXPECT_EQ(ce.selected, (std::vector<CurveKeyRef>{{0, 2, 1}})) << "a plain box replaces";
  // The normalized view boxes the dots where they are drawn: y (range 0..3) at 1 -> -1/3.
  ce.normalized = true;
  ce.view = {0.0f, 1.0f, -1.0f, 1.0f};  // 200 px per unit: -1/3 at y = 266.7
  EXPECT_EQ(keysInBox(curves, ce, {30, 260}, {36, 272}), (std::vector<CurveKeyRef>{{0, 1, 1}}));
}

}  // namespace
}  // namespace kinema
