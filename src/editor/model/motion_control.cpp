#include "editor/model/motion_control.h"

#include <cmath>

#include "anim/arc_length.h"
#include "editor/model/document.h"
#include "editor/model/edit_labels.h"
#include "editor/model/onion_skin.h"

namespace kinema {

namespace {
DistanceProfile profileFor(MotionControlProfile p, double duration, double distance) {
  DistanceProfile d;
  d.kind = p == MotionControlProfile::ConstantSpeed ? DistanceProfile::Kind::ConstantSpeed
           : p == MotionControlProfile::SineEase    ? DistanceProfile::Kind::SineEase
                                                    : DistanceProfile::Kind::ParabolicEase;
  d.duration = duration;
  d.distance = distance;
  return d;
}
}  // namespace

const char* toString(MotionControlProfile profile) {
  switch (profile) {
    case MotionControlProfile::ConstantSpeed: return "constant-speed";
    case MotionControlProfile::SineEase: return "sine-ease";
    case MotionControlProfile::ParabolicEase: return "parabolic-ease";
  }
  return "constant-speed";
}

int translationChannelIndex(const Clip& clip, int joint) {
  for (size_t c = 0; c < clip.channels.size(); ++c)
    if (clip.channels[c].joint == joint && clip.channels[c].target == ChannelTarget::Translation)
      return static_cast<int>(c);
  return -1;
}

std::string MotionControlJob::validate() const {
  if (!path) return "no translation channel";
  if (path->target != ChannelTarget::Translation) return "motion control needs a translation channel";
  if (path->keyCount() < 2) return "motion control needs a translation channel with at least two keys";
  if (!(frameTime > 0.0) || !std::isfinite(frameTime)) return "the frame time must be a positive number";
  if ((path->endTime() - path->startTime()) / frameTime > 1e6) return "the path spans more than a million frames";
  return {};
}

bool MotionControlJob::run(std::vector<float>& times, std::vector<glm::vec3>& positions) const {
  times.clear();
  positions.clear();
  if (!validate().empty()) return false;
  const ArcLengthTable table = buildArcLengthTable(*path);
  const double t0 = path->startTime(), t1 = path->endTime();
  const DistanceProfile profile = profileFor(this->profile, t1 - t0, table.length());
  // Frame times on the clip's grid from the first key; the last key's time closes the range.
  const long long first = static_cast<long long>(std::ceil(t0 / frameTime - 1e-6));
  times.push_back(static_cast<float>(t0));
  for (long long f = first;; ++f) {
    const double t = static_cast<double>(f) * frameTime;
    if (t >= t1 - 1e-6 * frameTime) break;
    if (t > t0 + 1e-6 * frameTime) times.push_back(static_cast<float>(t));
  }
  times.push_back(static_cast<float>(t1));
  for (float t : times) positions.push_back(positionAtTime(table, profile, static_cast<double>(t) - t0));
  return true;
}

bool MotionControlJob::bake(Channel& out) const {
  std::vector<float> times;
  std::vector<glm::vec3> positions;
  if (!run(times, positions)) return false;
  Channel c(path->joint, ChannelTarget::Translation, Interpolation::Linear, times, {});
  for (const glm::vec3& p : positions) c.values.push_back(glm::vec4(p, 0.0f));
  out = std::move(c);
  return true;
}

std::vector<glm::vec3> equalTimeTicks(const Channel& path, MotionControlProfile profile, int count) {
  std::vector<glm::vec3> out;
  if (path.keyCount() < 2 || count < 1) return out;
  const ArcLengthTable table = buildArcLengthTable(path);
  const double duration = path.endTime() - path.startTime();
  const DistanceProfile p = profileFor(profile, duration, table.length());
  for (int i = 0; i <= count; ++i) out.push_back(positionAtTime(table, p, duration * i / count));
  return out;
}

std::string applyMotionControl(Document& doc, int clip, int joint, MotionControlProfile profile) {
  if (clip < 0 || clip >= static_cast<int>(doc.scene().clips.size())) return "Motion control: the file has no clip";
  const Clip& c = doc.scene().clips[clip];
  const int index = translationChannelIndex(c, joint);
  if (index < 0) return "Motion control: the selected joint has no translation keys";
  MotionControlJob job;
  job.path = &c.channels[index];
  job.profile = profile;
  job.frameTime = doc.scene().frameGrid(clip).secondsPerFrame;
  const std::string error = job.validate();
  if (!error.empty()) return "Motion control: " + error;
  Channel baked;
  job.bake(baked);
  return doc.edit("Apply " + std::string(toString(profile)) + " motion control to " + jointsPhrase(doc.skeleton(), {joint}),
                  [&](DocumentEdit& e) -> std::string {
    e.clips[clip].channels[index] = std::move(baked);
    return {};
  });
}

}  // namespace kinema
