#include "editor/model/timeline.h"

#include <algorithm>
#include <cstdio>
#include <cmath>

#include "editor/model/editor_state.h"
#include "editor/model/keying.h"
#include "evaluation/scene_evaluation_job.h"

namespace kinema {

namespace {

const Clip* editedClip(const EditorState& s) { return s.hasMotion() ? &s.doc.scene().clips[s.clip] : nullptr; }

// The played clip as a PlaybackClip, rebuilt when the document changed since it was built.
const PlaybackClip& playbackClip(EditorState& s, const Clip& clip, int joints) {
  EditorState::PlaybackSampler& p = s.playbackSampler;
  const long long clipList = s.doc.clipListRevision(), changes = s.doc.changeCount();
  if (p.clipIndex != s.clip || p.joints != joints || p.clipListRevision != clipList || p.changeCount != changes) {
    p.clip = PlaybackClip::build(clip, joints);
    p.clipIndex = s.clip, p.joints = joints, p.clipListRevision = clipList, p.changeCount = changes;
  }
  return p.clip;
}

}  // namespace

void poseAtPlayhead(EditorState& s) {
  const Clip* clip = editedClip(s);
  if (!clip) return;
  // The evaluation pipeline over the working pose (joints the clip does not animate keep it).
  // Playing: stage 1 in its sampling form, built once (same values to 1e-6); a single frame
  // (scrub, step, pause, edit) samples the clip directly rather than build it. Dynamic
  // chains swing behind the clip, simulated frame by frame from the range's start.
  Pose pose;
  SceneEvaluationJob job;
  job.scene = &s.doc.scene();
  job.clip = s.clip;
  job.time = s.time;
  job.base = &s.doc.pose();
  // The document keeps its targets apart from scene().ik: a copy with them only when it has
  // some (no allocation a frame otherwise).
  IkRig rig;
  if (!s.doc.ikTargets().empty()) {
    rig = s.doc.savedRig();
    job.rig = &rig;
  }
  job.stages.dynamics = s.liveSprings.enabled;
  job.dynamicsStartFrame = rangeStartFrame(s);
  job.revision = s.doc.changeCount();
  job.context = &s.liveSprings.context;
  if (s.playing) {
    job.playback = &playbackClip(s, *clip, s.doc.pose().size());
    job.playbackContext = &s.playbackSampler.context;
  }
  job.pose = &pose;
  if (!job.run()) return;
  s.doc.setAnimatedPose(pose);
  s.animatedPoseRevision = s.doc.poseRevision();
}

FrameGrid timelineGrid(const EditorState& s) { return s.doc.scene().frameGrid(s.hasMotion() ? s.clip : -1); }

double timelineFrameTime(const EditorState& s) { return timelineGrid(s).secondsPerFrame; }
double timelineFps(const EditorState& s) { return timelineGrid(s).framesPerSecond(); }
long long frameAtTime(const EditorState& s, double time) { return timelineGrid(s).nearestFrame(time); }
double timeOfFrame(const EditorState& s, long long frame) { return timelineGrid(s).frameToTime(frame); }

long long currentFrame(const EditorState& s) { return frameAtTime(s, s.time); }

long long rangeStartFrame(const EditorState& s) {
  const Clip* clip = editedClip(s);
  return clip ? frameAtTime(s, clip->playStart()) : kNewClipStartFrame;
}

long long rangeEndFrame(const EditorState& s) {
  const Clip* clip = editedClip(s);
  if (!clip) return kNewClipEndFrame;
  return std::max(frameAtTime(s, clip->playEnd()), rangeStartFrame(s));
}

void syncDocumentPlayhead(EditorState& s) { s.doc.setPlayheadTime(s.time); }

void followDocumentClip(EditorState& s) {
  if (s.followedClipList == s.doc.clipListRevision()) return;
  s.followedClipList = s.doc.clipListRevision();
  const long long frame = currentFrame(s);  // on the grid of the clip shown until now
  s.clip = s.doc.activeClip();
  s.time = timeOfFrame(s, frame);
  s.dopeSheet.selection.clear();
  s.curveEditor.selected.clear();
  syncDocumentPlayhead(s);
  poseAtPlayhead(s);
}

void goToFrame(EditorState& s, long long frame) {
  s.time = timeOfFrame(s, frame);
  syncDocumentPlayhead(s);
  if (!s.playing) poseAtPlayhead(s);
}

void resetTimeline(EditorState& s) {
  s.playing = s.wasPlaying = s.sampleClip = false;
  const std::optional<ScenePlayhead>& saved = s.doc.savedPlayhead();
  s.clip = s.doc.activeClip();
  s.followedClipList = s.doc.clipListRevision();
  if (saved && std::isfinite(saved->time)) s.time = saved->time;
  else s.time = timeOfFrame(s, rangeStartFrame(s));
  syncDocumentPlayhead(s);
  poseAtPlayhead(s);
}

void stepFrame(EditorState& s, int delta) { goToFrame(s, currentFrame(s) + delta); }
void jumpToStart(EditorState& s) { goToFrame(s, rangeStartFrame(s)); }
void jumpToEnd(EditorState& s) { goToFrame(s, rangeEndFrame(s)); }

void togglePlayback(EditorState& s) {
  s.playing = !s.playing;
  if (!s.playing) goToFrame(s, currentFrame(s));
}

void advanceTimeline(EditorState& s, double dt) {
  if (!s.playing) return;
  const double start = timeOfFrame(s, rangeStartFrame(s)), end = timeOfFrame(s, rangeEndFrame(s));
  s.time += dt;
  if (s.time < start) s.time = start;
  if (s.time > end) {
    if (s.loop && end > start) {
      s.time = start + std::fmod(s.time - start, end - start);
    } else {
      s.time = end;
      s.playing = false;  // evaluateEditorPose poses the document at the end frame
    }
  }
  syncDocumentPlayhead(s);
}

std::string setFrameRange(EditorState& s, long long start, long long end) {
  if (start > end) return "the start frame must not be after the end frame";
  if (std::llabs(start) > 100000000LL || std::llabs(end) > 100000000LL) return "frames must be within +-100000000";
  const FrameGrid grid = timelineGrid(s);
  const float startTime = grid.frameToTime(start), endTime = grid.frameToTime(end);
  int clip = s.clip;
  const std::string error = s.doc.edit("Set frame range to " + std::to_string(start) + "-" + std::to_string(end), [&](DocumentEdit& e) {
    if (clip < 0 || clip >= static_cast<int>(e.clips.size())) {
      e.clips.push_back(newActionClip(grid));
      clip = e.activeClip = static_cast<int>(e.clips.size()) - 1;
    }
    Clip& c = e.clips[clip];
    c.hasRange = true;
    c.rangeStart = startTime;
    c.rangeEnd = endTime;
    return std::string();
  });
  if (error.empty()) s.clip = clip;
  syncDocumentPlayhead(s);
  return error;
}

bool timelineRateIsTheDocuments(const EditorState& s) {
  return !s.hasMotion() || !hasOwnFrameRate(s.doc.scene().clips[s.clip]);
}

std::string setFrameRate(EditorState& s, double fps) {
  if (!std::isfinite(fps) || fps < kMinFrameRate || fps > kMaxFrameRate) return "the frame rate must be 1 to 1000 frames per second";
  const long long frame = currentFrame(s);
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  if (timelineRateIsTheDocuments(s)) {
    // The document's rate: clips without their own keep their ranges' frame numbers.
    const FrameGrid before = documentFrameGrid(s.doc.scene().frameRate), after = documentFrameGrid(fps);
    const std::string error = s.doc.edit(std::string("Set document frame rate to ") + rate + " fps", [&](DocumentEdit& e) {
      e.frameRate = fps;
      for (Clip& c : e.clips) {
        if (hasOwnFrameRate(c)) continue;
        c.contacts = contactsOnGrid(c.contacts, before, after);  // the planted feet keep their moments
        if (!c.hasRange) continue;
        c.rangeStart = after.frameToTime(before.nearestFrame(c.rangeStart));
        c.rangeEnd = after.frameToTime(before.nearestFrame(c.rangeEnd));
      }
      return std::string();
    });
    if (!error.empty()) return error;
    goToFrame(s, frame);
    return {};
  }
  // The clip's own rate. The range keeps its frame numbers; keys keep their times (seconds),
  // as in Blender without "time stretching".
  const long long start = rangeStartFrame(s), end = rangeEndFrame(s);
  const int clip = s.clip;
  const std::string error = s.doc.edit(std::string("Set frame rate to ") + rate + " fps", [&](DocumentEdit& e) {
    Clip& c = e.clips[clip];
    const FrameGrid before = ownFrameGrid(c);
    c.frameTime = 1.0 / fps;
    c.contacts = contactsOnGrid(c.contacts, before, ownFrameGrid(c));  // the planted feet keep their moments
    c.hasRange = true;
    c.rangeStart = ownFrameGrid(c).frameToTime(start);
    c.rangeEnd = ownFrameGrid(c).frameToTime(end);
    return std::string();
  });
  if (!error.empty()) return error;
  goToFrame(s, frame);
  return {};
}

std::string keySelectedJoints(EditorState& s) {
  const std::string error = insertKeys(s.doc, s.clip, static_cast<float>(s.time), s.doc.selection.joints(),
                                       s.doc.autoKey.preferences);
  syncDocumentPlayhead(s);
  return error.empty() ? "Inserted keys on frame " + std::to_string(currentFrame(s)) : error;
}

std::string keyAllJoints(EditorState& s) {
  const std::string error = insertKeysOnAllJoints(s.doc, s.clip, static_cast<float>(s.time), s.doc.autoKey.preferences);
  syncDocumentPlayhead(s);
  return error.empty() ? "Inserted keys on all joints on frame " + std::to_string(currentFrame(s)) : error;
}

std::string deleteSelectedJointKeys(EditorState& s) {
  const std::string error = deleteKeys(s.doc, s.clip, static_cast<float>(s.time), s.doc.selection.joints());
  return error.empty() ? "Deleted keys on frame " + std::to_string(currentFrame(s)) : error;
}

float TimelineRuler::xOfFrame(long long frame) const {
  const double span = static_cast<double>(std::max(last - first, 1LL));
  return static_cast<float>(x + kTimelineRulerMargin + (frame - first) / span * (w - 2 * kTimelineRulerMargin));
}

long long TimelineRuler::frameAtX(float px) const {
  const double span = static_cast<double>(std::max(last - first, 1LL)), inner = std::max(w - 2 * kTimelineRulerMargin, 1.0f);
  const double f = first + (px - x - kTimelineRulerMargin) / inner * span;
  return std::clamp(static_cast<long long>(std::llround(std::isfinite(f) ? f : 0.0)), first, last);
}

TimelineRuler timelineRuler(const EditorState& s, float x, float y, float w, float h) {
  TimelineRuler r;
  r.x = x + 4;
  r.w = std::max(w - 8, 1.0f);
  const float k = h / kTimelineHeight;  // the strip grows with the UI scale: so does the ruler
  r.h = kTimelineRulerHeight * k;
  r.y = y + h - r.h - 2 * k;
  r.first = rangeStartFrame(s);
  r.last = std::max(rangeEndFrame(s), r.first + 1);
  return r;
}

std::vector<long long> selectedKeyFrames(const EditorState& s) {
  std::vector<long long> frames;
  const Clip* clip = editedClip(s);
  if (!clip) return frames;
  for (float t : jointKeyTimes(*clip, s.doc.selection.joints())) frames.push_back(frameAtTime(s, t));
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

}  // namespace kinema
