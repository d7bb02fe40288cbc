#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "anim/channel_modifier.h"
#include "anim/clip_source_map.h"
#include "anim/foot_contact_intervals.h"
#include "anim/frame_grid.h"
#include "core/pose.h"
#include "core/rotation.h"

namespace kinema {

// What a channel animates on its joint. Euler keys (x, y, z) are radians about X, Y and Z,
// combined in the channel's eulerOrder; Scalar channels animate a named property (values.x)
// that is not part of a Pose (sampleChannel reads them).
enum class ChannelTarget { Translation, Rotation, Scale, Euler, Scalar };

// How the segment that starts at a key is interpolated (set on that key).
//  Step        holds the key's value until the next key.
//  Linear      straight line; rotations: shortest-arc slerp.
//  Hermite     cubic Hermite with the keys' explicit outTangent / inTangent (value per
//              second); rotations: glTF CUBICSPLINE (component-wise, then normalised).
//  CatmullRom  automatic tangents (f[k+1]-f[k-1]) / (t[k+1]-t[k-1]); natural ends.
//  TCB         Kochanek-Bartels: Catmull-Rom shaped by each key's tension/continuity/bias.
//  Bezier      Blender-style handles (HandleType), time axis solved so f is a function of t;
//              rotations: Blender's quaternion F-curves (the four components as stored,
//              each a Bezier curve with its own handle values, then normalised).
//  Ease        easing preset (easing, easingMode) from the key's value to the next.
//  Nlerp       rotations only: normalised linear blend of the quaternions (shortest arc).
//  Squad       rotations only: Shoemake's spherical spline through the keys (C1 at keys).
enum class Interpolation { Step, Linear, Hermite, CatmullRom, TCB, Bezier, Ease, Nlerp, Squad };

enum class EasingFunction { Sine, Quad, Cubic, Quart, Quint, Expo, Circ, Back, Bounce, Elastic };
enum class EasingMode { In, Out, InOut };

// Blender's handle types (Graph Editor, V menu).
//  Free         left and right handles move independently.
//  Aligned      editing one handle turns the other to stay collinear (setBezierHandle).
//  Vector       the handle points at the neighbouring key, a third of the way there.
//  Auto         handles along the neighbours' chord, a third of each interval long.
//  AutoClamped  Auto, but flat at local extrema and never overshooting between keys.
enum class HandleType { Free, Aligned, Vector, Auto, AutoClamped };

const char* toString(ChannelTarget target);
const char* toString(Interpolation interpolation);
const char* toString(EasingFunction easing);
const char* toString(EasingMode mode);
const char* toString(HandleType type);
bool fromString(const std::string& s, ChannelTarget& out);
bool fromString(const std::string& s, Interpolation& out);
bool fromString(const std::string& s, EasingFunction& out);
bool fromString(const std::string& s, EasingMode& out);
bool fromString(const std::string& s, HandleType& out);

// Per-key settings: the interpolation of the segment that starts at the key, and the
// key's own tangents and handles (used by the segments on either side of it).
struct KeySettings {
  Interpolation interpolation = Interpolation::Linear;
  EasingFunction easing = EasingFunction::Sine;
  EasingMode easingMode = EasingMode::InOut;
  float tension = 0.0f, continuity = 0.0f, bias = 0.0f;  // TCB, usually in [-1, 1]
  glm::vec4 inTangent{0.0f}, outTangent{0.0f};           // Hermite: d value / d second
  HandleType leftHandleType = HandleType::AutoClamped, rightHandleType = HandleType::AutoClamped;
  // Bezier handles relative to the key: time offsets (left <= 0 <= right, seconds) and
  // value offsets. Only Free and Aligned handles are read from here; the other types are
  // computed from the neighbouring keys whenever the curve is evaluated.
  float leftHandleTime = 0.0f, rightHandleTime = 0.0f;
  glm::vec4 leftHandleValue{0.0f}, rightHandleValue{0.0f};

  bool operator==(const KeySettings& o) const;
  bool operator!=(const KeySettings& o) const { return !(*this == o); }
};

// One animated property of one joint, with its own key times.
struct Channel {
  Channel() = default;
  // The imported-motion form: one interpolation for every key (BVH, the first .kinema files).
  Channel(int joint_, ChannelTarget target_, Interpolation interpolation_, std::vector<float> times_,
          std::vector<glm::vec4> values_)
      : joint(joint_), target(target_), interpolation(interpolation_), times(std::move(times_)),
        values(std::move(values_)) {}

  int joint = -1;
  ChannelTarget target = ChannelTarget::Rotation;
  // Interpolation of every key while `keys` is empty (imported motion: BVH is Linear).
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;        // seconds, strictly increasing
  std::vector<glm::vec4> values;   // one per key: (x, y, z, -), a quaternion (x, y, z, w), (s, -, -, -)
  std::vector<KeySettings> keys;   // empty, or one per key
  EulerOrder eulerOrder = EulerOrder::XYZ;  // Euler channels
  std::string property;                     // Scalar channels: what the value means
  // Procedural modifiers on top of the keyed curve (noise, cycles, wave; anim/channel_modifier.h),
  // in stack order. sampleClip and the playback path apply them (sampleModifiedChannel);
  // sampleChannel and key editing see the keys alone. Empty for most channels.
  std::vector<ChannelModifier> modifiers;

  float startTime() const { return times.empty() ? 0.0f : times.front(); }
  float endTime() const { return times.empty() ? 0.0f : times.back(); }
  int keyCount() const { return static_cast<int>(times.size()); }
  // The settings of key k (from `keys`, or the channel-wide interpolation).
  KeySettings settings(int k) const;
  // Number of meaningful components of a value: 3, 4 (rotation) or 1 (scalar).
  int valueSize() const;
};

struct Clip {
  std::string name;
  std::vector<Channel> channels;
  // Seconds per frame for frame-based sources (BVH), edited clips and files that keep it; 0
  // when the clip has no rate of its own and counts at the document's (Scene::frameRate).
  // Count frames through frameGridOf (anim/frame_grid.h) or Scene::frameGrid, never here.
  double frameTime = 0.0;
  // Editor playback only: sampling always clamps.
  bool loop = false;
  // The playback range the editor's timeline shows and loops over (seconds), like
  // Blender's start/end frames; without one it is 0 .. duration(). Sampling ignores it.
  bool hasRange = false;
  float rangeStart = 0.0f;
  float rangeEnd = 0.0f;
  // When the feet are planted, per foot, in this clip's frames (detected on import, edited
  // on the timeline); empty for clips nobody detected contacts on. Sampling ignores them.
  FootContacts contacts = {};
  // The bone map a retargeted clip came through; empty for other clips. Sampling ignores it.
  ClipSourceMap sourceMap = {};
  // The scene's spring chains are baked into this clip's keys (sim/spring_bones.h): the
  // evaluation pipeline does not simulate them again when it plays.
  bool dynamicsBaked = false;

  float playStart() const { return hasRange ? rangeStart : 0.0f; }
  float playEnd() const { return hasRange ? rangeEnd : duration(); }

  // The last key time over all channels (clips start at time 0).
  float duration() const;

  // Empty when every channel names a joint of the skeleton (Scalar channels may use -1),
  // times are finite and strictly increasing, values and settings are finite (one per key)
  // and each key's interpolation suits the channel's target; the contacts and the source
  // map are valid (FootContacts::validate, ClipSourceMap::validate); each channel's modifier
  // stack is valid (validateModifierStack).
  std::string validate(const Skeleton& skeleton) const;
};

// Two key times of one channel closer than this (seconds) are the same key: inserting,
// moving, finding and deleting keys, and the dope sheet's key columns, all use it. A tenth
// of a frame at the editor's highest frame rate (1000 fps); far above the float rounding
// of a frame's time in clips up to 10 minutes long (6e-8 s per second of clip time), so
// keys set on one frame by different tools always meet.
constexpr float kKeyTimeTolerance = 1e-4f;
inline bool sameKeyTime(float a, float b) { return std::abs(a - b) <= kKeyTimeTolerance; }
// The index of the channel's key at `time` (within kKeyTimeTolerance; the nearest when
// several are), -1 when it has none there.
int findKey(const Channel& channel, float time);

// Key editing. Each keeps the channel sorted and valid and returns the key's new index.
// Inserting at the time of an existing key (findKey) replaces its value (and settings
// when given); the key keeps its time.
int insertKey(Channel& channel, float time, const glm::vec4& value);
int insertKey(Channel& channel, float time, const glm::vec4& value, const KeySettings& settings);
// Moving onto another key's time (findKey) replaces that key, at that key's time.
int moveKey(Channel& channel, int key, float newTime);
void deleteKey(Channel& channel, int key);
// Sets one Bezier handle (offsets relative to the key) the way Blender's Graph Editor
// does: an Auto/AutoClamped handle becomes Aligned, a Vector handle Free; when the other
// handle is Aligned it turns to stay collinear, keeping its own time extent.
void setBezierHandle(Channel& channel, int key, bool right, float timeOffset, const glm::vec4& valueOffset);
// Adds multiples of 2 pi to Euler keys so that each angle is within pi of the previous
// key's: interpolation then takes the short way round instead of spinning.
void unwrapEulerAngles(Channel& channel);

// Writes the clip's value at `time` into pose (which holds the rest pose or another
// base for joints the clip does not animate). Time is clamped to each channel's keys:
// before the first key it holds the first value, after the last key the last value.
// Rotations are normalised and interpolated along the shortest arc. Channel modifiers apply
// on top (sampleModifiedChannel; cycles and noise act at any time, the clamping above is
// that of the keyed curve underneath). Scalar channels are not part of a pose
// (sampleChannel in anim/sampling.h reads them).
void sampleClip(const Clip& clip, float time, Pose& pose);

}  // namespace kinema
