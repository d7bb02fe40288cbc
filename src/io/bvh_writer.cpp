#include "io/bvh_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "anim/pose_source.h"
#include "evaluation/scene_evaluation_job.h"
#include "io/atomic_write.h"

namespace kinema {

namespace {

constexpr double kRadToDeg = 57.29577951308232;
constexpr double kMaxFrames = 1e7;
// Indentation stops growing at this depth: BVH is whitespace separated, and a file may
// nest 200,000 joints, whose full indentation would be quadratic in size.
constexpr int kMaxIndentDepth = 24;

void appendNumber(std::string& out, double v) {
  char buf[48];
  if (std::abs(v) < 5e-7) v = 0.0;  // no "-0.000000"
  std::snprintf(buf, sizeof buf, "%.6f", v);
  out += buf;
}

// The three axis letters of an order, in multiplication order (BVH channel order).
const char* axes(EulerOrder order) { return toString(order); }

bool unitScale(const glm::vec3& s) { return glm::all(glm::lessThan(glm::abs(s - 1.0f), glm::vec3(1e-5f))); }

// "3 joints: 'a', 'b', 'c'" (the first few named), for report lines.
std::string jointList(const Skeleton& sk, const std::vector<int>& joints) {
  std::string out = std::to_string(joints.size()) + (joints.size() == 1 ? " joint: " : " joints: ");
  for (size_t i = 0; i < joints.size() && i < 4; ++i) out += (i ? ", '" : "'") + sk.names[joints[i]] + "'";
  if (joints.size() > 4) out += ", ...";
  return out;
}

// A name BVH can carry: no whitespace (the format is whitespace separated).
std::string bvhName(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '{' || c == '}') c = '_';
  return out;
}

}  // namespace

double bvhFrameTime(const Clip* clip, const BvhWriteOptions& options, bool* uniform) {
  if (uniform) *uniform = true;
  if (options.frameRate > 0.0) return 1.0 / options.frameRate;
  const double fallback = documentFrameGrid(options.documentFrameRate).secondsPerFrame;
  if (!clip) return fallback;
  if (clip->frameTime > 0.0) return clip->frameTime;
  // A clip without a rate of its own counts at the document's: written at it when its keys
  // lie on that grid, else on the grid they do lie on.
  if (keysOnGrid(*clip, documentFrameGrid(options.documentFrameRate))) return fallback;
  if (const double grid = keyGridFrameTime(*clip); grid > 0.0) return grid;
  // A clip of one key time lies on every grid; keys off any grid are resampled.
  if (uniform) *uniform = clip->duration() <= 0.0f;
  return fallback;
}

Result<std::string> bvhText(const Skeleton& sk, const Clip* clip, const BvhWriteOptions& options,
                            std::vector<std::string>* report) {
  auto note = [&](const std::string& line) {
    if (report) report->push_back(line);
  };
  std::string bad = sk.validate();
  if (bad.empty() && sk.empty()) bad = "the skeleton has no joints";
  if (bad.empty() && clip) bad = clip->validate(sk);
  if (!bad.empty()) return Result<std::string>::failure("cannot write BVH: " + bad);
  if (!(options.frameRate >= 0.0) || !std::isfinite(options.frameRate))
    return Result<std::string>::failure("cannot write BVH: the frame rate must be a positive number");

  const int n = sk.size();
  std::vector<std::vector<int>> children(n);
  for (int j = 0; j < n; ++j)
    if (sk.parents[j] >= 0) children[sk.parents[j]].push_back(j);
  std::vector<bool> translated(n, false), rotated(n, false);
  std::vector<int> scaledJoints, zeroEndSites, addedEndSites, renamed;
  if (clip)
    for (const Channel& ch : clip->channels) {
      if (ch.joint < 0 || ch.times.empty()) continue;
      if (ch.target == ChannelTarget::Translation) translated[ch.joint] = true;
      if (ch.target == ChannelTarget::Rotation || ch.target == ChannelTarget::Euler) rotated[ch.joint] = true;
      if (ch.target == ChannelTarget::Scale)
        for (const glm::vec4& v : ch.values)
          if (!unitScale(glm::vec3(v))) {
            scaledJoints.push_back(ch.joint);
            break;
          }
      if (ch.target == ChannelTarget::Scalar) note("scalar channel '" + ch.property + "' dropped (BVH has none)");
    }
  std::vector<bool> endSite(n, false), positions(n, false);
  for (int j = 0; j < n; ++j) {
    const int p = sk.parents[j];
    endSite[j] = p >= 0 && children[j].empty() && !translated[j] && !rotated[j] && sk.names[j] == sk.names[p] + "_End";
    positions[j] = p < 0 || translated[j];
    if (!unitScale(sk.rest[j].scale) && !endSite[j]) scaledJoints.push_back(j);
    if (bvhName(sk.names[j]) != sk.names[j]) renamed.push_back(j);
  }
  std::sort(scaledJoints.begin(), scaledJoints.end());
  scaledJoints.erase(std::unique(scaledJoints.begin(), scaledJoints.end()), scaledJoints.end());
  if (!scaledJoints.empty()) note("scale dropped (BVH has none): " + jointList(sk, scaledJoints));
  if (!renamed.empty()) note("whitespace and braces in names written as '_': " + jointList(sk, renamed));

  // HIERARCHY, depth first with an explicit stack (a file controls the depth).
  std::string out = "HIERARCHY\n";
  std::vector<int> columnsOf;  // joints with channels, in motion-column order
  std::vector<std::pair<int, int>> stack;  // (joint, depth)
  for (int j = n - 1; j >= 0; --j)
    if (sk.parents[j] < 0) stack.push_back({j, 0});
  int openDepth = 0;  // number of open braces
  auto indent = [&](int d) { out.append(static_cast<size_t>(std::min(d, kMaxIndentDepth)) * 2, ' '); };
  auto close = [&](int toDepth) {
    while (openDepth > toDepth) {
      --openDepth;
      indent(openDepth);
      out += "}\n";
    }
  };
  const std::string order = axes(options.order);
  while (!stack.empty()) {
    const auto [j, depth] = stack.back();
    stack.pop_back();
    close(depth);
    const glm::vec3 offset = sk.rest[j].translation;
    indent(depth);
    if (endSite[j]) {
      out += "End Site\n";
    } else {
      out += sk.parents[j] < 0 ? "ROOT " : "JOINT ";
      out += bvhName(sk.names[j]) + "\n";
    }
    indent(depth);
    out += "{\n";
    ++openDepth;
    indent(depth + 1);
    out += "OFFSET ";
    appendNumber(out, offset.x);
    out += ' ';
    appendNumber(out, offset.y);
    out += ' ';
    appendNumber(out, offset.z);
    out += '\n';
    if (endSite[j]) continue;
    indent(depth + 1);
    out += positions[j] ? "CHANNELS 6 Xposition Yposition Zposition" : "CHANNELS 3";
    for (char axis : order) out += std::string(" ") + axis + "rotation";
    out += '\n';
    columnsOf.push_back(j);
    if (children[j].empty()) {
      // BVH joints end in an End Site. It continues the bone from the parent with the
      // bone's own length (in the joint's frame, rest rotation included), so Blender
      // gets a real tail instead of inventing one for a zero-length bone.
      const glm::vec3 tail = sk.parents[j] >= 0 ? glm::inverse(glm::normalize(sk.rest[j].rotation)) * offset
                                                : glm::vec3(0.0f);
      indent(depth + 1);
      out += "End Site\n";
      indent(depth + 1);
      out += "{\n";
      indent(depth + 2);
      out += "OFFSET ";
      appendNumber(out, tail.x);
      out += ' ';
      appendNumber(out, tail.y);
      out += ' ';
      appendNumber(out, tail.z);
      out += '\n';
      indent(depth + 1);
      out += "}\n";
      (glm::length(tail) > 0.0f ? addedEndSites : zeroEndSites).push_back(j);
    }
    for (auto c = children[j].rbegin(); c != children[j].rend(); ++c) stack.push_back({*c, depth + 1});
  }
  close(0);
  if (!addedEndSites.empty())
    note("leaves given an End Site as long as their bone (read back, each adds a '<name>_End' joint): " +
         jointList(sk, addedEndSites));
  if (!zeroEndSites.empty())
    note("leaves without a bone length (roots, zero offsets) given a zero-length End Site (read back, each adds "
         "a '<name>_End' joint): " + jointList(sk, zeroEndSites));

  // MOTION: one line per frame, each joint's local pose sampled at the frame's time.
  bool uniform = true;
  const double frameTime = bvhFrameTime(clip, options, &uniform);
  if (!uniform) note("key times are not on one frame grid: sampled at the document's " + std::to_string(std::lround(1.0 / frameTime)) + " fps");
  const FrameGrid timing{frameTime};
  const double duration = clip ? clip->duration() : 0.0;
  const double frameCount = std::floor(duration / frameTime + 1e-4) + 1;
  // A file controls the duration: refuse what would be gigabytes of text.
  if (!(frameCount <= kMaxFrames)) {
    // In double: the count may be far beyond any integer (key times near 3e38).
    char text[160];
    std::snprintf(text, sizeof text, "cannot write BVH: a clip of %.4g s at %.4g s per frame needs %.4g frames, more than %.0f",
                  duration, frameTime, frameCount, kMaxFrames);
    return Result<std::string>::failure(text);
  }
  const long long frames = static_cast<long long>(frameCount);
  if (clip && std::abs(double(timing.frameToTime(frames - 1)) - duration) > 1e-4 * frameTime + 1e-6)
    note("the clip's end (" + std::to_string(duration) + " s) is not on a frame: the last frame is at " +
         std::to_string(timing.frameToTime(frames - 1)) + " s");
  out += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: ";
  char ft[48];
  std::snprintf(ft, sizeof ft, "%.9g", frameTime);
  out += ft;
  out += '\n';

  // Frames that fall on keys sample at the key's own time: a grid found from float key
  // times is off by an ulp here and there, enough to move a fast joint by 1e-4.
  std::map<long long, float> keyAtFrame;
  if (clip && uniform)
    for (const Channel& ch : clip->channels)
      for (float t : ch.times) {
        const double n = t / frameTime;
        if (std::abs(n - std::round(n)) < 1e-3) keyAtFrame[std::llround(n)] = t;
      }
  auto timeOfFrame = [&](long long f) {
    const auto it = keyAtFrame.find(f);
    return it != keyAtFrame.end() ? it->second : timing.frameToTime(f);
  };
  Pose pose = Pose::rest(sk);
  EvaluationContext context;  // the scene's dynamics step forward through the frames once
  const bool evaluated = options.scene && &options.scene->skeleton == &sk && clip &&
                         options.clipIndex >= 0 && options.clipIndex < static_cast<int>(options.scene->clips.size()) &&
                         &options.scene->clips[options.clipIndex] == clip;
  std::optional<ClipPoses> keysAlone;  // a clip given without its scene
  if (clip && !evaluated) keysAlone.emplace(sk, *clip);
  std::vector<glm::vec3> previous(n, glm::vec3(0.0f));
  for (long long f = 0; f < frames; ++f) {
    pose.local = sk.rest;
    if (evaluated) {
      // Every stage of the scene's evaluation (evaluation/scene_evaluation_job.h): BVH holds
      // only frames, so IK targets and dynamic chains are baked into them too.
      SceneEvaluationJob job;
      job.scene = options.scene;
      job.clip = options.clipIndex;
      job.time = timeOfFrame(f);
      job.stages = options.stages;
      job.context = &context;
      job.pose = &pose;
      job.run();
    } else if (keysAlone) {
      keysAlone->poseAt(timeOfFrame(f), pose);
    }
    bool first = true;
    for (int j : columnsOf) {
      const Transform& t = pose.local[j];
      if (positions[j])
        for (int i = 0; i < 3; ++i) {
          if (!first) out += ' ';
          first = false;
          appendNumber(out, t.translation[i]);
        }
      glm::vec3 e = quatToEuler(t.rotation, options.order) * float(kRadToDeg);
      // Each angle within 180 degrees of the last frame's: curves stay continuous.
      for (int i = 0; i < 3 && f > 0; ++i) e[i] += 360.0f * std::round((previous[j][i] - e[i]) / 360.0f);
      previous[j] = e;
      for (char axis : order) {
        if (!first) out += ' ';
        first = false;
        appendNumber(out, e[axis - 'X']);
      }
    }
    out += '\n';
    if (options.progress && (f % 200 == 199 || f + 1 == frames)) options.progress(f + 1, frames);
  }
  return out;
}

std::string saveBvh(const std::string& path, const Skeleton& skeleton, const Clip* clip,
                    const BvhWriteOptions& options, std::vector<std::string>* report) {
  Result<std::string> text = bvhText(skeleton, clip, options, report);
  if (!text) return path + ": " + text.error();
  return writeFileAtomically(path, text.value());
}

}  // namespace kinema
