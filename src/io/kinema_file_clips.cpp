// The .kinema file's "clips" section: channels and their keys, modifier stacks, foot contacts
// and the retargeting's bone map.
#include "io/kinema_file_sections.h"

#include <climits>
#include <cstdint>
#include <cstring>
#include <unordered_set>

#include "anim/channel_modifiers.h"
#include "core/forward_kinematics.h"
#include "io/json_number.h"

namespace kinema::kinema_format {

namespace {

const char* const kInterpolationNames = "step, linear, hermite, catmull-rom, tcb, bezier, ease, nlerp, squad";

const char* const kHandleNames = "free, aligned, vector, auto, auto-clamped";

// Per-key settings: every member is optional and defaults to KeySettings' default, so a
// writer may leave out whatever equals the default.
bool readKeySettings(Reader& r, const Json& j, const std::string& p, int n, KeySettings& k) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "interpolation", false)) &&
      !readEnum(r, *v, p + ".interpolation", k.interpolation, kInterpolationNames))
    return false;
  if ((v = r.member(j, p, "easing", false)) &&
      !readEnum(r, *v, p + ".easing", k.easing, "sine, quad, cubic, quart, quint, expo, circ, back, bounce, elastic"))
    return false;
  if ((v = r.member(j, p, "easing_mode", false)) && !readEnum(r, *v, p + ".easing_mode", k.easingMode, "in, out, in-out"))
    return false;
  if ((v = r.member(j, p, "tension", false)) && !readFloat(r, *v, p + ".tension", k.tension)) return false;
  if ((v = r.member(j, p, "continuity", false)) && !readFloat(r, *v, p + ".continuity", k.continuity)) return false;
  if ((v = r.member(j, p, "bias", false)) && !readFloat(r, *v, p + ".bias", k.bias)) return false;
  if ((v = r.member(j, p, "in_tangent", false)) && !r.floats(*v, p + ".in_tangent", n, &k.inTangent.x)) return false;
  if ((v = r.member(j, p, "out_tangent", false)) && !r.floats(*v, p + ".out_tangent", n, &k.outTangent.x)) return false;
  if ((v = r.member(j, p, "left_handle_type", false)) &&
      !readEnum(r, *v, p + ".left_handle_type", k.leftHandleType, kHandleNames))
    return false;
  if ((v = r.member(j, p, "right_handle_type", false)) &&
      !readEnum(r, *v, p + ".right_handle_type", k.rightHandleType, kHandleNames))
    return false;
  if ((v = r.member(j, p, "left_handle_time", false)) && !readFloat(r, *v, p + ".left_handle_time", k.leftHandleTime))
    return false;
  if (k.leftHandleTime > 0) return r.fail(p + ".left_handle_time", "must not be positive (seconds before the key)");
  if ((v = r.member(j, p, "right_handle_time", false)) &&
      !readFloat(r, *v, p + ".right_handle_time", k.rightHandleTime))
    return false;
  if (k.rightHandleTime < 0) return r.fail(p + ".right_handle_time", "must not be negative (seconds after the key)");
  if ((v = r.member(j, p, "left_handle_value", false)) && !r.floats(*v, p + ".left_handle_value", n, &k.leftHandleValue.x))
    return false;
  if ((v = r.member(j, p, "right_handle_value", false)) &&
      !r.floats(*v, p + ".right_handle_value", n, &k.rightHandleValue.x))
    return false;
  return true;
}

bool isRotationMode(Interpolation i) { return i == Interpolation::Nlerp || i == Interpolation::Squad; }

bool onlyVectorMode(Interpolation i) { return i == Interpolation::CatmullRom || i == Interpolation::TCB; }

bool checkMode(Reader& r, const std::string& path, Interpolation i, ChannelTarget t) {
  if (t == ChannelTarget::Rotation && onlyVectorMode(i))
    return r.fail(path, std::string("'") + toString(i) +
                            "' does not apply to rotation (use bezier, linear, nlerp, squad, hermite, ease or step)");
  if (t != ChannelTarget::Rotation && isRotationMode(i))
    return r.fail(path, std::string("'") + toString(i) + "' applies to rotation channels only");
  return true;
}

// channels[k].modifiers: the channel's modifier stack (anim/channel_modifier.h), in order.
// Every parameter is optional and defaults to the modifier's default; a wave without
// "rest_position" takes the joint's rest position from the file's skeleton.
const char* const kComponentLetters = "xyzw";

bool readComponents(Reader& r, const Json& j, const std::string& path, uint32_t& mask) {
  std::string text;
  if (!r.string(j, path, text)) return false;
  mask = 0;
  for (char c : text) {
    const char* at = c ? std::strchr(kComponentLetters, c) : nullptr;
    if (!at || (mask & (1u << (at - kComponentLetters))))
      return r.fail(path, "'" + cutForMessage(text) + "' is not a set of distinct letters from x, y, z, w");
    mask |= 1u << (at - kComponentLetters);
  }
  if (!mask) return r.fail(path, "names no component (letters from x, y, z, w)");
  return true;
}

bool readBoundedInt(Reader& r, const Json& j, const std::string& path, long long lo, long long hi, long long& out) {
  if (!r.integer(j, path, out)) return false;
  if (out < lo || out > hi)
    return r.fail(path, std::to_string(out) + " is out of range (" + std::to_string(lo) + " to " + std::to_string(hi) + ")");
  return true;
}

bool readModifier(Reader& r, const Json& j, const std::string& p, const Skeleton& s, int joint, ChannelModifier& m) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if (!(v = r.member(j, p, "type", true)) || !readEnum(r, *v, p + ".type", m.kind, "noise, cycles, wave")) return false;
  if ((v = r.member(j, p, "enabled", false))) {
    if (!v->is_boolean()) return r.fail(p + ".enabled", "expected true or false, found " + std::string(v->type_name()));
    m.enabled = v->get<bool>();
  }
  if ((v = r.member(j, p, "components", false)) && !readComponents(r, *v, p + ".components", m.components)) return false;
  long long n = 0;
  switch (m.kind) {
    case ChannelModifierKind::Noise:
      if ((v = r.member(j, p, "strength", false)) && !readFloat(r, *v, p + ".strength", m.noise.strength)) return false;
      if (m.noise.strength < 0) return r.fail(p + ".strength", "must not be negative");
      if ((v = r.member(j, p, "scale", false)) && !readFloat(r, *v, p + ".scale", m.noise.scale)) return false;
      if (!(m.noise.scale > 0)) return r.fail(p + ".scale", "must be positive (seconds per noise cell)");
      if ((v = r.member(j, p, "phase", false)) && !readFloat(r, *v, p + ".phase", m.noise.phase)) return false;
      if ((v = r.member(j, p, "octaves", false))) {
        if (!readBoundedInt(r, *v, p + ".octaves", 1, 8, n)) return false;
        m.noise.octaves = static_cast<int>(n);
      }
      if ((v = r.member(j, p, "roughness", false)) && !readFloat(r, *v, p + ".roughness", m.noise.roughness)) return false;
      if (!(m.noise.roughness >= 0 && m.noise.roughness <= 1)) return r.fail(p + ".roughness", "must be in [0, 1]");
      if ((v = r.member(j, p, "seed", false))) {
        if (!readBoundedInt(r, *v, p + ".seed", 0, UINT32_MAX, n)) return false;
        m.noise.seed = static_cast<uint32_t>(n);
      }
      break;
    case ChannelModifierKind::Cycles: {
      const char* const modes = "hold, repeat, repeat_offset, mirror";
      if ((v = r.member(j, p, "before", false)) && !readEnum(r, *v, p + ".before", m.cycles.before, modes)) return false;
      if ((v = r.member(j, p, "after", false)) && !readEnum(r, *v, p + ".after", m.cycles.after, modes)) return false;
      if ((v = r.member(j, p, "before_count", false))) {
        if (!readBoundedInt(r, *v, p + ".before_count", 0, INT_MAX, n)) return false;
        m.cycles.beforeCount = static_cast<int>(n);
      }
      if ((v = r.member(j, p, "after_count", false))) {
        if (!readBoundedInt(r, *v, p + ".after_count", 0, INT_MAX, n)) return false;
        m.cycles.afterCount = static_cast<int>(n);
      }
      break;
    }
    case ChannelModifierKind::Wave:
      if ((v = r.member(j, p, "amplitude", false)) && !readFloat(r, *v, p + ".amplitude", m.wave.amplitude)) return false;
      if ((v = r.member(j, p, "omega", false)) && !readFloat(r, *v, p + ".omega", m.wave.omega)) return false;
      if ((v = r.member(j, p, "k", false)) && !r.floats(*v, p + ".k", 3, &m.wave.k.x)) return false;
      if ((v = r.member(j, p, "phi", false)) && !readFloat(r, *v, p + ".phi", m.wave.phi)) return false;
      if ((v = r.member(j, p, "rest_position", false))) {
        if (!r.floats(*v, p + ".rest_position", 3, &m.wave.position.x)) return false;
      } else if (joint >= 0 && joint < s.size()) {
        m.wave.position = glm::vec3(computeWorld(s, Pose::rest(s))[joint][3]);
      }
      break;
  }
  // Anything the checks above let through (none today) is still caught here, with the path.
  if (std::string bad = m.validate(); !bad.empty()) return r.fail(p, bad);
  return true;
}

bool readModifiers(Reader& r, const Json& j, const std::string& p, const Skeleton& s, Channel& ch) {
  if (!j.is_array()) return r.fail(p, "expected an array of modifier objects");
  ch.modifiers.resize(j.size());
  for (size_t i = 0; i < j.size(); ++i)
    if (!readModifier(r, j[i], p + "[" + std::to_string(i) + "]", s, ch.joint, ch.modifiers[i])) return false;
  if (std::string bad = validateModifierStack(ch.modifiers); !bad.empty()) return r.fail(p, bad);
  return true;
}

bool readChannel(Reader& r, const Json& j, const std::string& p, const Skeleton& s, Channel& ch) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  std::string text;
  if (!(v = r.member(j, p, "target", true)) ||
      !readEnum(r, *v, p + ".target", ch.target, "translation, rotation, scale, euler, scalar"))
    return false;
  // Scalar channels may belong to no joint.
  const bool scalar = ch.target == ChannelTarget::Scalar;
  if ((v = r.member(j, p, "joint", !scalar))) {
    if (!r.string(*v, p + ".joint", text)) return false;
    ch.joint = r.joint(s, text);
    if (ch.joint < 0) return r.fail(p + ".joint", "no joint named '" + cutForMessage(text) + "'");
  } else if (!scalar) {
    return false;
  }
  if ((v = r.member(j, p, "property", false)) && !r.string(*v, p + ".property", ch.property)) return false;
  if ((v = r.member(j, p, "euler_order", false))) {
    if (!r.string(*v, p + ".euler_order", text)) return false;
    const std::optional<EulerOrder> order = eulerOrderFromString(text);
    if (!order) return r.fail(p + ".euler_order", "'" + cutForMessage(text) + "' is not one of XYZ, XZY, YXZ, YZX, ZXY, ZYX");
    ch.eulerOrder = *order;
  }
  if ((v = r.member(j, p, "interpolation", false))) {
    if (!readEnum(r, *v, p + ".interpolation", ch.interpolation, kInterpolationNames)) return false;
    if (!checkMode(r, p + ".interpolation", ch.interpolation, ch.target)) return false;
  }
  const Json* times = r.member(j, p, "times", true);
  const Json* values = times ? r.member(j, p, "values", true) : nullptr;
  if (!values) return false;
  if (!times->is_array() || times->empty()) return r.fail(p + ".times", "expected a non-empty array of numbers");
  if (!values->is_array() || values->size() != times->size())
    return r.fail(p + ".values", "expected an array with one value per key time (" + std::to_string(times->size()) + ")");
  const int n = ch.valueSize();
  for (size_t k = 0; k < times->size(); ++k) {
    const std::string tp = p + ".times[" + std::to_string(k) + "]";
    double t = 0.0;
    if (!r.number((*times)[k], tp, t)) return false;
    if (std::abs(t) >= kFloatOverflow) return r.fail(tp, "number out of float range");
    if (k > 0 && !(static_cast<float>(t) > ch.times.back())) return r.fail(tp, "key times must increase");
    ch.times.push_back(static_cast<float>(t));
    glm::vec4 value(0.0f);
    if (!r.floats((*values)[k], p + ".values[" + std::to_string(k) + "]", n, &value.x)) return false;
    if (ch.target == ChannelTarget::Rotation) {
      // Checked before normalising: glm::normalize turns a zero quaternion into identity.
      if (value == glm::vec4(0.0f)) return r.fail(p + ".values[" + std::to_string(k) + "]", "zero quaternion");
      const glm::quat q = normalizeIfNeeded(glm::quat(value.w, value.x, value.y, value.z));
      value = glm::vec4(q.x, q.y, q.z, q.w);
    }
    ch.values.push_back(value);
  }
  if ((v = r.member(j, p, "keys", false))) {
    if (!v->is_array() || v->size() != times->size())
      return r.fail(p + ".keys", "expected an array with one object per key time (" + std::to_string(times->size()) + ")");
    KeySettings base;
    base.interpolation = ch.interpolation;
    ch.keys.assign(times->size(), base);
    for (size_t k = 0; k < v->size(); ++k) {
      const std::string kp = p + ".keys[" + std::to_string(k) + "]";
      if (!readKeySettings(r, (*v)[k], kp, n, ch.keys[k])) return false;
      if (!checkMode(r, kp + ".interpolation", ch.keys[k].interpolation, ch.target)) return false;
    }
  }
  if ((v = r.member(j, p, "modifiers", false)) && !readModifiers(r, *v, p + ".modifiers", s, ch)) return false;
  return true;
}

// clips[c].foot_contacts: {"left": [[first, last], ...], "right": [...]} in frames, each list
// in order without overlaps (FootContacts::validate).
bool readFootContacts(Reader& r, const Json& j, const std::string& p, FootContacts& out) {
  if (!j.is_object()) return r.fail(p, "expected an object with \"left\" and \"right\" lists");
  for (int f = 0; f < 2; ++f) {
    const char* side = toString(static_cast<Foot>(f));
    const Json* list = r.member(j, p, side, false);
    if (!list) continue;
    const std::string lp = p + "." + side;
    if (!list->is_array()) return r.fail(lp, "expected an array of [first, last] frame pairs");
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string ip = lp + "[" + std::to_string(i) + "]";
      const Json& pair = (*list)[i];
      if (!pair.is_array() || pair.size() != 2) return r.fail(ip, "expected [first, last] (two frame numbers)");
      long long frame[2];
      for (int k = 0; k < 2; ++k) {
        if (!r.integer(pair[k], ip + "[" + std::to_string(k) + "]", frame[k])) return false;
        if (frame[k] < 0 || frame[k] > INT_MAX)
          return r.fail(ip + "[" + std::to_string(k) + "]", "frame " + std::to_string(frame[k]) + " is outside 0.." +
                                                                 std::to_string(INT_MAX));
      }
      if (frame[1] < frame[0]) return r.fail(ip, "ends (frame " + std::to_string(frame[1]) + ") before it starts (frame " +
                                                     std::to_string(frame[0]) + ")");
      std::vector<ContactInterval>& foot = out.feet[f];
      if (!foot.empty() && frame[0] <= foot.back().last)
        return r.fail(ip, "starts at frame " + std::to_string(frame[0]) + ", not after the previous contact ends (frame " +
                              std::to_string(foot.back().last) + ")");
      foot.push_back(ContactInterval{static_cast<int>(frame[0]), static_cast<int>(frame[1])});
    }
  }
  return true;
}

// clips[c].bone_map: {"file": PATH, "clip": I, "pairs": [[source name, target joint], ...]}.
bool readSourceMap(Reader& r, const Json& j, const std::string& p, const Skeleton& s, ClipSourceMap& out) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "file", false)) && !r.string(*v, p + ".file", out.file)) return false;
  if ((v = r.member(j, p, "clip", false))) {
    long long clip = 0;
    if (!r.integer(*v, p + ".clip", clip)) return false;
    if (clip < 0 || clip > INT_MAX) return r.fail(p + ".clip", "clip " + std::to_string(clip) + " is outside 0.." + std::to_string(INT_MAX));
    out.clip = static_cast<int>(clip);
  }
  const Json* pairs = r.member(j, p, "pairs", true);
  if (!pairs) return false;
  if (!pairs->is_array() || pairs->empty())
    return r.fail(p + ".pairs", "expected a non-empty array of [source joint, target joint] pairs");
  std::unordered_set<std::string> sources;
  std::unordered_set<int> targets;
  for (size_t i = 0; i < pairs->size(); ++i) {
    const std::string ip = p + ".pairs[" + std::to_string(i) + "]";
    const Json& pair = (*pairs)[i];
    if (!pair.is_array() || pair.size() != 2) return r.fail(ip, "expected [source joint, target joint] (two names)");
    SourceMapPair sp;
    std::string target;
    if (!r.string(pair[0], ip + "[0]", sp.source) || !r.string(pair[1], ip + "[1]", target)) return false;
    if (sp.source.empty()) return r.fail(ip + "[0]", "empty source joint name");
    sp.target = r.joint(s, target);
    if (sp.target < 0) return r.fail(ip + "[1]", "no joint named '" + cutForMessage(target) + "'");
    // Sets, not a scan of the earlier pairs: a file may map a 200,000-joint skeleton.
    if (!sources.insert(sp.source).second)
      return r.fail(ip + "[0]", "source joint '" + cutForMessage(sp.source) + "' is mapped twice");
    if (!targets.insert(sp.target).second) return r.fail(ip + "[1]", "joint '" + cutForMessage(target) + "' is mapped twice");
    out.pairs.push_back(std::move(sp));
  }
  return true;
}

// A channel's modifier stack: every parameter of each modifier's kind is written, so the
// file says exactly what plays; "enabled" only when false, "components" only when not xyz.
Json modifiersJson(const std::vector<ChannelModifier>& stack) {
  Json list = Json::array();
  for (const ChannelModifier& m : stack) {
    Json o = Json::object();
    o["type"] = toString(m.kind);
    if (!m.enabled) o["enabled"] = false;
    if (m.components != ChannelModifier().components) {
      std::string letters;
      for (int c = 0; c < 4; ++c)
        if (m.components & (1u << c)) letters += kComponentLetters[c];
      o["components"] = letters;
    }
    switch (m.kind) {
      case ChannelModifierKind::Noise:
        o["strength"] = jsonFloat(m.noise.strength);
        o["scale"] = jsonFloat(m.noise.scale);
        o["phase"] = jsonFloat(m.noise.phase);
        o["octaves"] = m.noise.octaves;
        o["roughness"] = jsonFloat(m.noise.roughness);
        o["seed"] = m.noise.seed;
        break;
      case ChannelModifierKind::Cycles:
        o["before"] = toString(m.cycles.before);
        o["after"] = toString(m.cycles.after);
        o["before_count"] = m.cycles.beforeCount;
        o["after_count"] = m.cycles.afterCount;
        break;
      case ChannelModifierKind::Wave:
        o["amplitude"] = jsonFloat(m.wave.amplitude);
        o["omega"] = jsonFloat(m.wave.omega);
        o["k"] = vec(&m.wave.k.x, 3);
        o["phi"] = jsonFloat(m.wave.phi);
        o["rest_position"] = vec(&m.wave.position.x, 3);
        break;
    }
    list.push_back(std::move(o));
  }
  return list;
}

// A channel; per-key settings list only what differs from KeySettings' defaults (which
// the reader fills in), so simple keys stay small and every setting round-trips exactly.
Json channelJson(const Channel& ch, const Skeleton& s) {
  const int n = ch.valueSize();
  Json k;
  if (ch.joint >= 0) k["joint"] = s.names[ch.joint];
  k["target"] = toString(ch.target);
  if (!ch.property.empty()) k["property"] = ch.property;
  if (ch.target == ChannelTarget::Euler) k["euler_order"] = toString(ch.eulerOrder);
  k["interpolation"] = toString(ch.interpolation);
  Json times = Json::array(), values = Json::array();
  for (float t : ch.times) times.push_back(jsonFloat(t));
  for (const glm::vec4& v : ch.values) values.push_back(vec(&v.x, n));
  k["times"] = std::move(times);
  k["values"] = std::move(values);
  if (!ch.keys.empty()) {
    KeySettings d;
    d.interpolation = ch.interpolation;
    Json keys = Json::array();
    for (const KeySettings& ks : ch.keys) {
      Json o = Json::object();
      if (ks.interpolation != d.interpolation) o["interpolation"] = toString(ks.interpolation);
      if (ks.easing != d.easing) o["easing"] = toString(ks.easing);
      if (ks.easingMode != d.easingMode) o["easing_mode"] = toString(ks.easingMode);
      if (ks.tension != d.tension) o["tension"] = jsonFloat(ks.tension);
      if (ks.continuity != d.continuity) o["continuity"] = jsonFloat(ks.continuity);
      if (ks.bias != d.bias) o["bias"] = jsonFloat(ks.bias);
      if (ks.inTangent != d.inTangent) o["in_tangent"] = vec(&ks.inTangent.x, n);
      if (ks.outTangent != d.outTangent) o["out_tangent"] = vec(&ks.outTangent.x, n);
      if (ks.leftHandleType != d.leftHandleType) o["left_handle_type"] = toString(ks.leftHandleType);
      if (ks.rightHandleType != d.rightHandleType) o["right_handle_type"] = toString(ks.rightHandleType);
      if (ks.leftHandleTime != d.leftHandleTime) o["left_handle_time"] = jsonFloat(ks.leftHandleTime);
      if (ks.rightHandleTime != d.rightHandleTime) o["right_handle_time"] = jsonFloat(ks.rightHandleTime);
      if (ks.leftHandleValue != d.leftHandleValue) o["left_handle_value"] = vec(&ks.leftHandleValue.x, n);
      if (ks.rightHandleValue != d.rightHandleValue) o["right_handle_value"] = vec(&ks.rightHandleValue.x, n);
      keys.push_back(std::move(o));
    }
    k["keys"] = std::move(keys);
  }
  // Only channels that carry modifiers get the key, so files without them are unchanged.
  if (!ch.modifiers.empty()) k["modifiers"] = modifiersJson(ch.modifiers);
  return k;
}

}  // namespace

bool readClips(Reader& r, const Json& root, Scene& scene) {
  const Json* clips = r.member(root, "", "clips", false);
  if (!clips) return true;
  if (!clips->is_array()) return r.fail("clips", "expected an array");
  for (size_t c = 0; c < clips->size(); ++c) {
    const std::string p = "clips[" + std::to_string(c) + "]";
    const Json& j = (*clips)[c];
    if (!j.is_object()) return r.fail(p, "expected an object");
    Clip clip;
    const Json* v;
    if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", clip.name)) return false;
    if ((v = r.member(j, p, "frame_time", false))) {
      if (!r.number(*v, p + ".frame_time", clip.frameTime)) return false;
      if (clip.frameTime < 0) return r.fail(p + ".frame_time", "must not be negative");
    }
    if ((v = r.member(j, p, "dynamics_baked", false))) {
      if (!v->is_boolean())
        return r.fail(p + ".dynamics_baked", "expected true or false, found " + std::string(v->type_name()));
      clip.dynamicsBaked = v->get<bool>();
    }
    if ((v = r.member(j, p, "loop", false))) {
      if (!v->is_boolean()) return r.fail(p + ".loop", "expected true or false, found " + std::string(v->type_name()));
      clip.loop = v->get<bool>();
    }
    if ((v = r.member(j, p, "range", false))) {
      float range[2];
      if (!r.floats(*v, p + ".range", 2, range)) return false;
      if (range[0] > range[1]) return r.fail(p + ".range", "start comes after end");
      clip.hasRange = true;
      clip.rangeStart = range[0];
      clip.rangeEnd = range[1];
    }
    const Json* channels = r.member(j, p, "channels", true);
    if (!channels) return false;
    if (!channels->is_array()) return r.fail(p + ".channels", "expected an array");
    long long keys = 0;  // counted before any channel is read
    for (const Json& c : *channels)
      if (const Json* t = c.is_object() && c.contains("times") ? &c["times"] : nullptr; t && t->is_array())
        keys += static_cast<long long>(t->size());
    if (keys > r.limits.maxKeys)
      return r.fail(p + ".channels", limitExceeded(keys, r.limits.maxKeys, "keys", "maxKeys"));
    for (size_t k = 0; k < channels->size(); ++k) {
      Channel ch;
      if (!readChannel(r, (*channels)[k], p + ".channels[" + std::to_string(k) + "]", scene.skeleton, ch))
        return false;
      clip.channels.push_back(std::move(ch));
    }
    if ((v = r.member(j, p, "foot_contacts", false)) && !readFootContacts(r, *v, p + ".foot_contacts", clip.contacts))
      return false;
    if ((v = r.member(j, p, "bone_map", false)) &&
        !readSourceMap(r, *v, p + ".bone_map", scene.skeleton, clip.sourceMap))
      return false;
    scene.clips.push_back(std::move(clip));
  }
  return true;
}

Json clipsToJson(const Scene& scene) {
  const Skeleton& s = scene.skeleton;
  Json clips = Json::array();
  for (const Clip& clip : scene.clips) {
    Json c;
    c["name"] = clip.name;
    if (clip.frameTime > 0) c["frame_time"] = clip.frameTime;
    if (clip.loop) c["loop"] = true;
    if (clip.dynamicsBaked) c["dynamics_baked"] = true;
    if (clip.hasRange) {
      const float range[2] = {clip.rangeStart, clip.rangeEnd};
      c["range"] = vec(range, 2);
    }
    Json channels = Json::array();
    for (const Channel& ch : clip.channels) channels.push_back(channelJson(ch, s));
    c["channels"] = std::move(channels);
    // Optional: what the retargeting and the timeline's contact edits left on the clip.
    if (!clip.contacts.empty()) {
      Json contacts = Json::object();
      for (int f = 0; f < 2; ++f) {
        Json list = Json::array();
        for (const ContactInterval& ci : clip.contacts.feet[f]) list.push_back(Json::array({ci.first, ci.last}));
        contacts[toString(static_cast<Foot>(f))] = std::move(list);
      }
      c["foot_contacts"] = std::move(contacts);
    }
    if (!clip.sourceMap.empty()) {
      Json pairs = Json::array();
      for (const SourceMapPair& sp : clip.sourceMap.pairs) pairs.push_back(Json::array({sp.source, s.names[sp.target]}));
      c["bone_map"] = {{"file", clip.sourceMap.file}, {"clip", clip.sourceMap.clip}, {"pairs", std::move(pairs)}};
    }
    clips.push_back(std::move(c));
  }
  return clips;
}

}  // namespace kinema::kinema_format
