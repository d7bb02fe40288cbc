#include "io/bvh.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <unordered_set>

#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

const char* toString(BvhChannel channel) {
  switch (channel) {
    case BvhChannel::Xposition: return "Xposition";
    case BvhChannel::Yposition: return "Yposition";
    case BvhChannel::Zposition: return "Zposition";
    case BvhChannel::Xrotation: return "Xrotation";
    case BvhChannel::Yrotation: return "Yrotation";
    case BvhChannel::Zrotation: return "Zrotation";
  }
  return "Xrotation";
}

namespace {

struct Token {
  std::string text;
  int line;
};

bool iequals(const std::string& a, const char* b) {
  const size_t n = std::strlen(b);
  if (a.size() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

bool parseChannel(const std::string& s, BvhChannel& out) {
  static const struct {
    const char* name;
    BvhChannel channel;
  } kNames[] = {{"Xposition", BvhChannel::Xposition}, {"Yposition", BvhChannel::Yposition},
                {"Zposition", BvhChannel::Zposition}, {"Xrotation", BvhChannel::Xrotation},
                {"Yrotation", BvhChannel::Yrotation}, {"Zrotation", BvhChannel::Zrotation}};
  for (const auto& n : kNames)
    if (iequals(s, n.name)) {
      out = n.channel;
      return true;
    }
  return false;
}

// Parses one number the way BVH writers print them: optional sign, digits, optional
// fraction (".5" included), optional exponent. Rejects anything else and non-finite values.
bool parseNumber(const char* begin, const char* end, double& out) {
  if (begin < end && *begin == '+') {
    ++begin;
    if (begin < end && *begin == '-') return false;  // "+-5" is not a number
  }
  if (begin == end) return false;
  auto [ptr, ec] = std::from_chars(begin, end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

bool parseNumber(const std::string& s, double& out) { return parseNumber(s.data(), s.data() + s.size(), out); }

// A number that must also fit a float (offsets and motion values are stored as float).
bool parseFloat(const char* begin, const char* end, float& out) {
  double v;
  if (!parseNumber(begin, end, v) || std::abs(v) > static_cast<double>(std::numeric_limits<float>::max()))
    return false;
  out = static_cast<float>(v);
  return true;
}

class BvhParser {
 public:
  BvhParser(const std::string& text, const std::string& source, const InputLimits& limits)
      : source_(source), limits_(limits) {
    splitLines(text, lines_);
    // A UTF-8 byte-order mark (Windows editors write one) is not part of the text.
    if (!lines_.empty() && lines_[0].compare(0, 3, "\xEF\xBB\xBF") == 0) lines_[0].erase(0, 3);
    endsWithNewline_ = !text.empty() && (text.back() == '\n' || text.back() == '\r');
  }

  Result<BvhData> parse() {
    if (!parseHierarchy()) return Result<BvhData>::failure(error_);
    if (!parseMotion()) return Result<BvhData>::failure(error_);
    return std::move(data_);
  }

 private:
  bool fail(int line, const std::string& message) {
    error_ = oneLineMessage(source_ + ":" + std::to_string(line) + ": " + message);
    return false;
  }

  // Text from the file quoted in a message: a 50 MB token is not echoed whole.
  static std::string cut(const std::string& text) { return cutForMessage(text); }

  // Hierarchy tokens up to (not including) the MOTION line.
  void tokenizeHierarchy() {
    for (size_t l = 0; l < lines_.size(); ++l) {
      std::istringstream in(lines_[l]);
      std::string word;
      bool first = true;
      while (in >> word) {
        if (first && word == "MOTION") {
          motionLine_ = static_cast<int>(l);
          return;
        }
        first = false;
        tokens_.push_back({word, static_cast<int>(l) + 1});
      }
    }
  }

  // Where the text ends: the line after the last newline, or the last line when the file
  // does not end with a newline.
  int eofLine() const {
    return std::max(1, static_cast<int>(lines_.size()) + (endsWithNewline_ ? 1 : 0));
  }

  const Token* next() { return pos_ < tokens_.size() ? &tokens_[pos_++] : nullptr; }

  bool expectWord(const char* word, const char* context) {
    const Token* t = next();
    if (!t) return fail(endLine(), std::string("unexpected end of hierarchy, expected '") + word + "' " + context);
    if (t->text != word) return fail(t->line, std::string("expected '") + word + "' " + context + ", found '" + cut(t->text) + "'");
    return true;
  }

  int endLine() const { return motionLine_ >= 0 ? motionLine_ + 1 : eofLine(); }

  bool readOffset(glm::vec3& offset, const std::string& joint) {
    if (!expectWord("OFFSET", ("in joint '" + cut(joint) + "'").c_str())) return false;
    const int keywordLine = tokens_[pos_ - 1].line;
    for (int a = 0; a < 3; ++a) {
      const Token* t = next();
      if (!t) return fail(endLine(), "unexpected end of hierarchy in the OFFSET of '" + cut(joint) + "'");
      // Reported on the OFFSET line: a short OFFSET runs into the next line's keyword.
      if (!parseFloat(t->text.data(), t->text.data() + t->text.size(), offset[a]))
        return fail(keywordLine, "OFFSET of '" + cut(joint) + "': '" + cut(t->text) + "' is not a finite number in float range");
    }
    return true;
  }

  // The joint name: the rest of the keyword's line, without a trailing '{'.
  bool readName(int keywordLine, std::string& name) {
    name.clear();
    while (pos_ < tokens_.size() && tokens_[pos_].line == keywordLine && tokens_[pos_].text != "{") {
      if (!name.empty()) name += ' ';
      name += tokens_[pos_++].text;
    }
    if (name.empty()) return fail(keywordLine, "joint without a name");
    name = toUtf8(name);  // names from older exporters are often Latin-1
    return true;
  }

  // End Site names avoid every ROOT/JOINT name in the file, including later ones.
  std::string endSiteName(const std::string& parent) {
    const std::string wanted = parent + "_End";
    std::string name = wanted;
    for (int k = 2; names_.count(name) || jointNames_.count(name); ++k) name = wanted + "." + std::to_string(k);
    names_.insert(name);
    return name;
  }

  void collectJointNames() {
    for (size_t i = 0; i + 1 < tokens_.size(); ++i) {
      if (tokens_[i].text != "ROOT" && tokens_[i].text != "JOINT") continue;
      std::string name;
      for (size_t k = i + 1; k < tokens_.size() && tokens_[k].line == tokens_[i].line && tokens_[k].text != "{"; ++k)
        name += (name.empty() ? "" : " ") + tokens_[k].text;
      jointNames_.insert(toUtf8(name));
    }
  }

  bool parseHierarchy() {
    if (lines_.empty()) return fail(1, "empty file, expected HIERARCHY");
    tokenizeHierarchy();
    if (tokens_.empty() || tokens_[0].text != "HIERARCHY")
      return fail(tokens_.empty() ? 1 : tokens_[0].line, "expected HIERARCHY at the start of the file");
    pos_ = 1;
    collectJointNames();
    // An explicit stack instead of recursion: hostile files cannot overflow the C++ stack.
    std::vector<int> open;  // joints whose '}' is still due
    while (pos_ < tokens_.size()) {
      const Token& t = tokens_[pos_++];
      if (t.text == "}") {
        if (open.empty()) return fail(t.line, "'}' without a matching '{'");
        open.pop_back();
        continue;
      }
      const bool isRoot = t.text == "ROOT";
      const bool isJoint = t.text == "JOINT";
      const bool isEnd = iequals(t.text, "End");
      if (isRoot && !open.empty()) return fail(t.line, "ROOT inside another joint (missing '}'?)");
      if ((isJoint || isEnd) && open.empty())
        return fail(t.line, "'" + cut(t.text) + "' outside any ROOT (extra '}'?)");
      if (!isRoot && !isJoint && !isEnd) {
        if (t.text == "CHANNELS" || t.text == "OFFSET")
          return fail(t.line, t.text + " in the wrong place (missing '{' or '}'?)");
        return fail(t.line, "expected ROOT, JOINT, End Site or '}', found '" + cut(t.text) + "'");
      }
      if (!open.empty() && data_.joints[open.back()].endSite)
        return fail(t.line, "an End Site cannot have children (missing '}'?)");
      BvhJoint j;
      j.line = t.line;
      j.parent = open.empty() ? -1 : open.back();
      if (isEnd) {
        const Token* site = next();
        if (!site || !iequals(site->text, "Site")) return fail(t.line, "expected 'End Site'");
        j.endSite = true;
        j.name = endSiteName(data_.joints[j.parent].name);
        if (!expectWord("{", "after End Site")) return false;
        if (!readOffset(j.offset, j.name)) return false;
      } else {
        std::string name;
        if (!readName(t.line, name)) return false;
        if (names_.count(name)) return fail(t.line, "joint name '" + cut(name) + "' is used twice");
        names_.insert(name);
        j.name = name;
        if (!expectWord("{", ("after " + cut(t.text) + " " + cut(name)).c_str())) return false;
        if (!readOffset(j.offset, j.name)) return false;
        if (!readChannels(j)) return false;
      }
      if (static_cast<long long>(data_.joints.size()) >= limits_.maxJoints)
        return fail(t.line, "the hierarchy has " +
                                limitExceeded(static_cast<long long>(data_.joints.size()) + 1, limits_.maxJoints,
                                              "joints or more", "maxJoints"));
      data_.joints.push_back(std::move(j));
      open.push_back(static_cast<int>(data_.joints.size()) - 1);
    }
    if (!open.empty())
      return fail(endLine(), "'" + cut(data_.joints[open.back()].name) + "' is not closed (missing '}')");
    if (motionLine_ < 0) return fail(eofLine(), "no MOTION section");
    if (data_.joints.empty()) return fail(motionLine_ + 1, "no ROOT joint before MOTION");
    return true;
  }

  bool readChannels(BvhJoint& j) {
    const Token* t = next();
    if (!t) return fail(endLine(), "unexpected end of hierarchy, expected CHANNELS in '" + cut(j.name) + "'");
    if (t->text != "CHANNELS") return fail(t->line, "expected CHANNELS in '" + cut(j.name) + "', found '" + cut(t->text) + "'");
    const Token* n = next();
    double count;
    if (!n || !parseNumber(n->text, count) || count < 0 || count > 64 || count != std::floor(count))
      return fail(t->line, "CHANNELS of '" + cut(j.name) + "' needs a channel count");
    for (int c = 0; c < static_cast<int>(count); ++c) {
      const Token* ct = next();
      BvhChannel ch;
      // Reported on the CHANNELS line: a short list runs into the next line's keyword.
      if (!ct || !parseChannel(ct->text, ch))
        return fail(ct ? t->line : endLine(),
                    "CHANNELS of '" + cut(j.name) + "' says " + cut(n->text) + " channels but lists " + std::to_string(c) +
                        (ct ? " (found '" + cut(ct->text) + "')" : ""));
      j.channels.push_back(ch);
    }
    j.firstChannel = data_.channelCount;
    data_.channelCount += static_cast<int>(j.channels.size());
    return true;
  }

  // "Frames: 720" / "Frame Time: .0083333" (the number may also sit on the next token).
  bool readHeader(size_t& l, const char* label, double& value) {
    while (l < lines_.size() && isBlank(lines_[l])) ++l;
    if (l >= lines_.size()) return fail(eofLine(), std::string("expected '") + label + "' after MOTION");
    const std::string& s = lines_[l];
    const size_t start = s.find_first_not_of(" \t");
    const size_t n = std::strlen(label);
    if (s.compare(start, n, label) != 0)
      return fail(static_cast<int>(l) + 1, std::string("expected '") + label + "', found '" + cut(trim(s)) + "'");
    const std::string rest = trim(s.substr(start + n));
    if (!parseNumber(rest, value))
      return fail(static_cast<int>(l) + 1, std::string("'") + label + "' needs a number, found '" + cut(rest) + "'");
    ++l;
    return true;
  }

  bool parseMotion() {
    size_t l = static_cast<size_t>(motionLine_) + 1;
    double frames, frameTime;
    if (!readHeader(l, "Frames:", frames)) return false;
    if (frames < 0 || frames != std::floor(frames) || frames > 1e9)
      return fail(static_cast<int>(l), "Frames must be a whole number >= 0");
    const long long keys = static_cast<long long>(frames) * data_.channelCount;
    if (keys > limits_.maxKeys)
      return fail(static_cast<int>(l), "Frames x channels = " + limitExceeded(keys, limits_.maxKeys, "keys", "maxKeys"));
    if (!readHeader(l, "Frame Time:", frameTime)) return false;
    if (!(frameTime > 0)) return fail(static_cast<int>(l), "Frame Time must be positive");
    // Key times are floats: the last one, (Frames - 1) x Frame Time, must be finite too.
    if (frameTime * std::max(frames - 1.0, 1.0) > static_cast<double>(std::numeric_limits<float>::max()))
      return fail(static_cast<int>(l), "Frame Time x Frames is beyond the float range of key times");
    data_.frameCount = static_cast<int>(frames);
    data_.frameTime = frameTime;
    const size_t cols = static_cast<size_t>(data_.channelCount);

    // Reserve only what the file can hold, whatever Frames claims.
    data_.motion.reserve(std::min<size_t>(static_cast<size_t>(frames), lines_.size()) * cols);
    int frame = 0;
    for (; l < lines_.size() && frame < data_.frameCount; ++l) {
      const std::string& s = lines_[l];
      if (isBlank(s)) continue;
      size_t got = 0;
      const char* p = s.data();
      const char* end = p + s.size();
      while (true) {
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        if (p == end) break;
        const char* q = p;
        while (q < end && *q != ' ' && *q != '\t') ++q;
        float v;
        if (!parseFloat(p, q, v))
          return fail(static_cast<int>(l) + 1, "'" + cut(std::string(p, q)) + "' is not a finite number in float range (frame " +
                                                   std::to_string(frame) + ", value " + std::to_string(got + 1) + ")");
        if (got < cols) data_.motion.push_back(v);
        ++got;
        p = q;
      }
      if (got != cols)
        return fail(static_cast<int>(l) + 1, "frame " + std::to_string(frame) + " has " + std::to_string(got) +
                                                 " values, the hierarchy declares " + std::to_string(cols) + " channels");
      ++frame;
    }
    if (frame < data_.frameCount)
      return fail(eofLine(), "Frames says " + std::to_string(data_.frameCount) + " but the file has " +
                                 std::to_string(frame) + " motion lines (truncated?)");
    return true;
  }

  std::string source_;
  InputLimits limits_;
  std::vector<std::string> lines_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  int motionLine_ = -1;  // 0-based
  bool endsWithNewline_ = false;
  std::unordered_set<std::string> names_;       // names given so far
  std::unordered_set<std::string> jointNames_;  // every ROOT/JOINT name in the file
  std::string error_;
  BvhData data_;
};

}  // namespace

Result<BvhData> parseBvh(const std::string& text, const std::string& source, const InputLimits& limits) {
  return BvhParser(text, source, limits).parse();
}

Result<BvhData> loadBvh(const std::string& path, const InputLimits& limits) {
  std::string text;
  std::string error = readTextFile(path, text, limits.maxFileBytes);
  if (!error.empty()) return Result<BvhData>::failure(error);
  return parseBvh(text, path, limits);
}

void convertZUpToYUp(BvhData& data) {
  std::vector<char> negate(static_cast<size_t>(data.channelCount), 0);
  for (BvhJoint& j : data.joints) {
    j.offset = glm::vec3(j.offset.x, j.offset.z, -j.offset.y);
    for (size_t c = 0; c < j.channels.size(); ++c) {
      BvhChannel& ch = j.channels[c];
      const size_t column = static_cast<size_t>(j.firstChannel) + c;
      switch (ch) {
        case BvhChannel::Yposition: ch = BvhChannel::Zposition; break;
        case BvhChannel::Zposition: ch = BvhChannel::Yposition; break;
        case BvhChannel::Yrotation: ch = BvhChannel::Zrotation; break;
        case BvhChannel::Zrotation: ch = BvhChannel::Yrotation; break;
        default: continue;
      }
      // The old Y becomes -Z (positions and rotation angles alike).
      if ((ch == BvhChannel::Zposition || ch == BvhChannel::Zrotation) && column < negate.size()) negate[column] = 1;
    }
  }
  if (data.channelCount <= 0) return;
  const size_t columns = static_cast<size_t>(data.channelCount);
  for (size_t i = 0; i < data.motion.size(); ++i)
    if (negate[i % columns]) data.motion[i] = -data.motion[i];
}

Skeleton BvhData::skeleton() const {
  Skeleton s;
  for (const BvhJoint& j : joints) s.addJoint(j.name, j.parent, Transform::fromTranslation(j.offset));
  return s;
}

namespace {

// Local transform of joint j from one motion row.
Transform jointLocal(const BvhJoint& j, const float* row) {
  Transform t = Transform::fromTranslation(j.offset);
  glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
  for (size_t c = 0; c < j.channels.size(); ++c) {
    const float v = row[j.firstChannel + static_cast<int>(c)];
    switch (j.channels[c]) {
      case BvhChannel::Xposition: t.translation.x = v; break;
      case BvhChannel::Yposition: t.translation.y = v; break;
      case BvhChannel::Zposition: t.translation.z = v; break;
      case BvhChannel::Xrotation: r = r * glm::angleAxis(glm::radians(v), glm::vec3(1, 0, 0)); break;
      case BvhChannel::Yrotation: r = r * glm::angleAxis(glm::radians(v), glm::vec3(0, 1, 0)); break;
      case BvhChannel::Zrotation: r = r * glm::angleAxis(glm::radians(v), glm::vec3(0, 0, 1)); break;
    }
  }
  t.rotation = glm::normalize(r);
  return t;
}

bool hasPosition(const BvhJoint& j) {
  for (BvhChannel c : j.channels)
    if (c == BvhChannel::Xposition || c == BvhChannel::Yposition || c == BvhChannel::Zposition) return true;
  return false;
}

bool hasRotation(const BvhJoint& j) {
  for (BvhChannel c : j.channels)
    if (c == BvhChannel::Xrotation || c == BvhChannel::Yrotation || c == BvhChannel::Zrotation) return true;
  return false;
}

}  // namespace

Pose BvhData::framePose(int frame) const {
  Pose pose = Pose::rest(skeleton());
  if (frameCount == 0) return pose;
  frame = std::clamp(frame, 0, frameCount - 1);
  const float* row = motion.data() + static_cast<size_t>(frame) * channelCount;
  for (size_t i = 0; i < joints.size(); ++i)
    if (!joints[i].channels.empty()) pose.local[i] = jointLocal(joints[i], row);
  return pose;
}

double BvhData::keyFrameTime() const {
  const FrameGrid timing{frameTime};
  // A Frame Time so small that frames share a float time cannot be played at its rate.
  for (int f = 1; f < frameCount; ++f)
    if (!(timing.frameToTime(f) > timing.frameToTime(f - 1))) return 1.0 / kDefaultFrameRate;
  return frameTime;
}

Clip BvhData::clip() const {
  Clip clip;
  clip.name = "motion";
  clip.frameTime = keyFrameTime();
  if (frameCount == 0) return clip;
  std::vector<float> times(static_cast<size_t>(frameCount));
  for (int f = 0; f < frameCount; ++f) times[f] = FrameGrid{clip.frameTime}.frameToTime(f);
  for (size_t i = 0; i < joints.size(); ++i) {
    const BvhJoint& j = joints[i];
    Channel translation{static_cast<int>(i), ChannelTarget::Translation, Interpolation::Linear, times, {}};
    Channel rotation{static_cast<int>(i), ChannelTarget::Rotation, Interpolation::Linear, times, {}};
    const bool pos = hasPosition(j), rot = hasRotation(j);
    glm::quat previous(1.0f, 0.0f, 0.0f, 0.0f);
    for (int f = 0; f < frameCount; ++f) {
      const Transform t = jointLocal(j, motion.data() + static_cast<size_t>(f) * channelCount);
      if (pos) translation.values.emplace_back(t.translation, 0.0f);
      // Keep consecutive keys in one hemisphere so curves shown to users stay continuous.
      previous = sameHemisphere(t.rotation, previous);
      if (rot) rotation.values.emplace_back(previous.x, previous.y, previous.z, previous.w);
    }
    if (pos) clip.channels.push_back(std::move(translation));
    if (rot) clip.channels.push_back(std::move(rotation));
  }
  return clip;
}

}  // namespace kinema
