#include "render/curve_plot.h"

#include <algorithm>
#include <cmath>

#include "anim/arc_length.h"
#include "anim/bezier_handles.h"
#include "anim/easing.h"
#include "anim/sampling.h"

#include "render/raster_draw.h"

namespace kinema {

using raster::dot;
using raster::line;
using raster::rect;
using raster::text;
using raster::textWidth;

Image plotPanels(const std::vector<PlotPanel>& panels, int columns, int pw, int ph) {
  const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
  Image img(columns * pw, rows * ph);
  std::fill(img.rgba.begin(), img.rgba.end(), std::uint8_t{255});
  const Rgb grid{225, 225, 225}, axis{150, 150, 150}, ink{30, 30, 30}, keyColor{220, 60, 30}, handle{120, 120, 120};
  for (size_t i = 0; i < panels.size(); ++i) {
    const PlotPanel& p = panels[i];
    const int ox = static_cast<int>(i % columns) * pw, oy = static_cast<int>(i / columns) * ph;
    // Plot area inside the panel, leaving room for the title and a margin.
    const int left = ox + 14, right = ox + pw - 10, top = oy + 30, bottom = oy + ph - 14;
    const glm::ivec4 clip(ox + 1, oy + 1, ox + pw - 1, oy + ph - 1);
    auto toPixel = [&](glm::vec2 d) {
      const glm::vec2 f = (d - p.min) / (p.max - p.min);
      return glm::vec2(left + f.x * (right - left), bottom - f.y * (bottom - top));
    };
    rect(img, ox, oy, ox + pw, oy + 1, axis);
    rect(img, ox, oy, ox + 1, oy + ph, axis);
    for (int g = 0; g <= 4; ++g) {
      const float fx = left + (right - left) * g / 4.0f, fy = top + (bottom - top) * g / 4.0f;
      line(img, {fx, static_cast<float>(top)}, {fx, static_cast<float>(bottom)}, 1.0f, grid, clip);
      line(img, {static_cast<float>(left), fy}, {static_cast<float>(right), fy}, 1.0f, grid, clip);
    }
    if (p.min.y < 0 && p.max.y > 0) line(img, toPixel({p.min.x, 0}), toPixel({p.max.x, 0}), 1.0f, axis, clip);
    text(img, ox + 8, oy + 6, p.title, ink, 2);
    for (const auto& h : p.handles) {
      line(img, toPixel(h[0]), toPixel(h[1]), 1.0f, handle, clip);
      dot(img, toPixel(h[1]), 2.5f, handle);
    }
    for (const PlotCurve& c : p.curves)
      for (size_t k = 1; k < c.points.size(); ++k)
        line(img, toPixel(c.points[k - 1]), toPixel(c.points[k]), 2.0f, c.color, clip);
    // Legend on a white box, so curves passing under it do not garble the labels.
    int labels = 0, widest = 0;
    for (const PlotCurve& c : p.curves)
      if (!c.label.empty()) {
        ++labels;
        widest = std::max(widest, textWidth(c.label));
      }
    if (labels > 0) {
      const int boxTop = p.legendAtBottom ? bottom - 11 * labels - 6 : top + 2;
      rect(img, right - widest - 8, boxTop, right, boxTop + 11 * labels + 4, Rgb{255, 255, 255});
      int legendY = boxTop + 3;
      for (const PlotCurve& c : p.curves)
        if (!c.label.empty()) {
          text(img, right - textWidth(c.label) - 3, legendY, c.label, c.color);
          legendY += 11;
        }
    }
    for (const glm::vec2& k : p.keys) dot(img, toPixel(k), 4.0f, keyColor);
  }
  return img;
}

namespace {

const Rgb kBlue{40, 90, 200}, kGreen{30, 150, 70}, kPurple{150, 60, 180}, kOrange{230, 130, 20};

const std::vector<float> kTimes = {0, 1, 1.5f, 3, 4};
const std::vector<float> kValues = {0, 2, 1.4f, 1.4f, 0.4f};

Channel keys(Interpolation mode) {
  Channel c;
  c.target = ChannelTarget::Scalar;
  c.interpolation = mode;
  c.times = kTimes;
  for (float v : kValues) c.values.emplace_back(v, 0, 0, 0);
  KeySettings s;
  s.interpolation = mode;
  c.keys.assign(kTimes.size(), s);
  return c;
}

PlotCurve curve(const Channel& c, const std::string& label, Rgb color) {
  PlotCurve pc{label, color, {}};
  for (int i = 0; i <= 800; ++i) {
    const float t = -0.25f + 4.5f * i / 800.0f;
    pc.points.emplace_back(t, sampleChannel(c, t).x);
  }
  return pc;
}

PlotPanel panel(const std::string& title, std::vector<PlotCurve> curves) {
  PlotPanel p;
  p.title = title;
  p.curves = std::move(curves);
  for (size_t k = 0; k < kTimes.size(); ++k) p.keys.emplace_back(kTimes[k], kValues[k]);
  p.min = {-0.25f, -0.6f};
  p.max = {4.25f, 2.6f};
  return p;
}

void addHandles(PlotPanel& p, const Channel& c) {
  for (int k = 0; k < c.keyCount(); ++k) {
    const BezierHandles h = effectiveHandles(c, k);
    const glm::vec2 key(c.times[k], c.values[k].x);
    if (k > 0) p.handles.push_back({key, key + glm::vec2(h.leftTime, h.leftValue.x)});
    if (k + 1 < c.keyCount()) p.handles.push_back({key, key + glm::vec2(h.rightTime, h.rightValue.x)});
  }
}

Channel bezier(HandleType type) {
  Channel c = keys(Interpolation::Bezier);
  for (KeySettings& k : c.keys) k.leftHandleType = k.rightHandleType = type;
  return c;
}

Channel tcb(float KeySettings::*param, float value) {
  Channel c = keys(Interpolation::TCB);
  for (KeySettings& k : c.keys) k.*param = value;
  return c;
}

PlotPanel easingPanel(EasingFunction f) {
  PlotPanel p;
  p.title = std::string("ease: ") + toString(f);
  const EasingMode modes[] = {EasingMode::In, EasingMode::Out, EasingMode::InOut};
  const Rgb colors[] = {kBlue, kGreen, kPurple};
  for (int m = 0; m < 3; ++m) {
    PlotCurve c{toString(modes[m]), colors[m], {}};
    for (int i = 0; i <= 400; ++i) c.points.emplace_back(i / 400.0f, ease(f, modes[m], i / 400.0f));
    p.curves.push_back(c);
  }
  p.keys = {{0, 0}, {1, 1}};
  p.legendAtBottom = true;
  p.min = {-0.05f, -0.45f};
  p.max = {1.05f, 1.45f};
  return p;
}

// Rotation modes: angle of the sampled rotation from the first key, over time.
PlotPanel rotationPanel() {
  Channel c;
  c.target = ChannelTarget::Rotation;
  c.times = kTimes;
  const float angles[] = {0.0f, 1.6f, 1.0f, 2.4f, 0.6f};
  const glm::vec3 axes[] = {{0, 1, 0}, {0, 1, 0.3f}, {1, 1, 0}, {0.2f, 1, 0}, {0, 1, 1}};
  for (int k = 0; k < 5; ++k) {
    const glm::quat q = axisAngle(axes[k], angles[k]);
    c.values.emplace_back(q.x, q.y, q.z, q.w);
  }
  PlotPanel p;
  p.title = "rotation: angle from key 0";
  const Interpolation modes[] = {Interpolation::Linear, Interpolation::Nlerp, Interpolation::Squad};
  const char* names[] = {"slerp", "nlerp", "squad"};
  const Rgb colors[] = {kBlue, kOrange, kPurple};
  const glm::quat q0 = axisAngle(axes[0], angles[0]);
  for (int m = 0; m < 3; ++m) {
    c.interpolation = modes[m];
    PlotCurve pc{names[m], colors[m], {}};
    for (int i = 0; i <= 800; ++i) {
      const float t = -0.25f + 4.5f * i / 800.0f;
      const glm::vec4 v = sampleChannel(c, t);
      const float d = std::min(1.0f, std::abs(glm::dot(glm::quat(v.w, v.x, v.y, v.z), q0)));
      pc.points.emplace_back(t, 2.0f * std::acos(d));
    }
    p.curves.push_back(pc);
  }
  for (int k = 0; k < 5; ++k) {
    const glm::vec4& v = c.values[k];
    p.keys.emplace_back(kTimes[k], 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(glm::quat(v.w, v.x, v.y, v.z), q0)))));
  }
  p.min = {-0.25f, -0.2f};
  p.max = {4.25f, 3.0f};
  return p;
}

// Motion control: distance along a Catmull-Rom path over time for each s(t).
PlotPanel motionPanel() {
  Channel path;
  path.target = ChannelTarget::Translation;
  path.interpolation = Interpolation::CatmullRom;
  path.times = {0, 1, 1.5f, 3, 4};
  path.values = {{0, 0, 0, 0}, {2, 1, 0, 0}, {3, 3, 0, 0}, {1, 4, 0, 0}, {0, 2, 0, 0}};
  const ArcLengthTable table = buildArcLengthTable(path, 256);
  Channel velocity;
  velocity.target = ChannelTarget::Scalar;
  velocity.interpolation = Interpolation::Linear;
  velocity.times = {0, 1, 3, 4};
  const double L = table.length();
  // A ramp up, a plateau and a ramp down whose area is the path length.
  const float vmax = static_cast<float>(L / 3.0);
  velocity.values = {{0, 0, 0, 0}, {vmax, 0, 0, 0}, {vmax, 0, 0, 0}, {0, 0, 0, 0}};
  PlotPanel p;
  p.title = "motion control: s(t)";
  p.legendAtBottom = true;
  const DistanceProfile::Kind kinds[] = {DistanceProfile::Kind::ConstantSpeed, DistanceProfile::Kind::SineEase,
                                         DistanceProfile::Kind::ParabolicEase, DistanceProfile::Kind::VelocityCurve};
  const char* names[] = {"constant", "sine ease", "parabolic", "v(t) curve"};
  const Rgb colors[] = {kBlue, kGreen, kOrange, kPurple};
  for (int m = 0; m < 4; ++m) {
    DistanceProfile prof;
    prof.kind = kinds[m];
    prof.duration = 4.0;
    prof.distance = L;
    prof.velocity = &velocity;
    prepareDistanceProfile(prof);
    PlotCurve pc{names[m], colors[m], {}};
    for (int i = 0; i <= 400; ++i) {
      const double t = 4.0 * i / 400.0;
      pc.points.emplace_back(static_cast<float>(t), static_cast<float>(distanceAt(prof, t) / L));
    }
    p.curves.push_back(pc);
  }
  p.keys = {{0, 0}, {4, 1}};
  p.min = {-0.2f, -0.1f};
  p.max = {4.2f, 1.1f};
  return p;
}

}  // namespace

std::vector<PlotPanel> interpolationModePanels() {
  std::vector<PlotPanel> panels;
  panels.push_back(panel("step", {curve(keys(Interpolation::Step), "", kBlue)}));
  panels.push_back(panel("linear", {curve(keys(Interpolation::Linear), "", kBlue)}));
  {
    Channel h = keys(Interpolation::Hermite);
    const float out[] = {3, -1, 0, -1, 0}, in[] = {0, 2, -2, 1, -1};
    for (size_t k = 0; k < h.keys.size(); ++k) {
      h.keys[k].outTangent.x = out[k];
      h.keys[k].inTangent.x = in[k];
    }
    PlotPanel p = panel("hermite (explicit tangents)", {curve(h, "", kBlue)});
    for (int k = 0; k < 5; ++k) {
      const glm::vec2 key(kTimes[k], kValues[k]);
      p.handles.push_back({key, key + 0.3f * glm::vec2(1, out[k])});
      p.handles.push_back({key, key - 0.3f * glm::vec2(1, in[k])});
    }
    panels.push_back(p);
  }
  panels.push_back(panel("catmull-rom", {curve(keys(Interpolation::CatmullRom), "", kBlue)}));
  panels.push_back(panel("tcb: tension", {curve(tcb(&KeySettings::tension, 0.6f), "t=+0.6", kBlue),
                                          curve(tcb(&KeySettings::tension, -0.6f), "t=-0.6", kOrange)}));
  panels.push_back(panel("tcb: continuity", {curve(tcb(&KeySettings::continuity, 0.6f), "c=+0.6", kBlue),
                                             curve(tcb(&KeySettings::continuity, -0.6f), "c=-0.6", kOrange)}));
  panels.push_back(panel("tcb: bias", {curve(tcb(&KeySettings::bias, 0.6f), "b=+0.6", kBlue),
                                       curve(tcb(&KeySettings::bias, -0.6f), "b=-0.6", kOrange)}));
  {
    PlotPanel p = panel("bezier: auto", {curve(bezier(HandleType::Auto), "", kBlue)});
    addHandles(p, bezier(HandleType::Auto));
    panels.push_back(p);
  }
  {
    PlotPanel p = panel("bezier: auto-clamped", {curve(bezier(HandleType::AutoClamped), "", kBlue)});
    addHandles(p, bezier(HandleType::AutoClamped));
    panels.push_back(p);
  }
  {
    PlotPanel p = panel("bezier: vector", {curve(bezier(HandleType::Vector), "", kBlue)});
    addHandles(p, bezier(HandleType::Vector));
    panels.push_back(p);
  }
  {
    // Key 1's right handle dragged up: aligned turns the left one with it, free does not.
    Channel a = bezier(HandleType::Aligned), f = bezier(HandleType::Free);
    for (Channel* c : {&a, &f}) {
      for (int k = 0; k < c->keyCount(); ++k) {
        const BezierHandles h = effectiveHandles(bezier(HandleType::AutoClamped), k);
        c->keys[k].leftHandleTime = h.leftTime;
        c->keys[k].rightHandleTime = h.rightTime;
        c->keys[k].leftHandleValue = h.leftValue;
        c->keys[k].rightHandleValue = h.rightValue;
      }
      setBezierHandle(*c, 1, true, 0.3f, glm::vec4(0.5f, 0, 0, 0));
    }
    PlotPanel p = panel("bezier: aligned / free", {curve(a, "aligned", kBlue), curve(f, "free", kOrange)});
    addHandles(p, a);
    panels.push_back(p);
  }
  {
    Channel e = keys(Interpolation::Ease);
    const EasingFunction fs[] = {EasingFunction::Sine, EasingFunction::Back, EasingFunction::Bounce,
                                 EasingFunction::Elastic, EasingFunction::Cubic};
    const EasingMode ms[] = {EasingMode::InOut, EasingMode::Out, EasingMode::Out, EasingMode::Out, EasingMode::In};
    for (int k = 0; k < 5; ++k) {
      e.keys[k].easing = fs[k];
      e.keys[k].easingMode = ms[k];
    }
    panels.push_back(panel("ease per segment", {curve(e, "", kBlue)}));
  }
  for (EasingFunction f : {EasingFunction::Sine, EasingFunction::Quad, EasingFunction::Cubic, EasingFunction::Quart,
                           EasingFunction::Quint, EasingFunction::Expo, EasingFunction::Circ, EasingFunction::Back,
                           EasingFunction::Bounce, EasingFunction::Elastic})
    panels.push_back(easingPanel(f));
  panels.push_back(rotationPanel());
  panels.push_back(motionPanel());
  return panels;
}

}  // namespace kinema
