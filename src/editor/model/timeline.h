#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"

namespace kinema {

struct EditorState;

// The timeline model (Blender's timeline): the current frame of EditorState::time, the
// frame range and rate of the edited clip (EditorState::clip; saved in .kinema as the clip's
// hasRange/rangeStart/rangeEnd and frameTime), play/pause, step, jump and scrub. Without a
// clip it shows Blender's defaults (frames 1..250 at 24 fps) so a user can start keying;
// the first key creates the clip ("Action", keying.h). Frame N is at time N seconds per
// frame of Scene::frameGrid: the clip's own rate, else the document's (Scene::frameRate), the
// grid the dope sheet, curve editor and onion skin count in too.
// Changing the frame poses the document from the clip with Document::setAnimatedPose: not
// an undo step, joints the clip does not animate keep their pose.

// The frame grid the timeline counts in (Scene::frameGrid, the grid every panel shares): the
// edited clip's, or without one the document's rate, the rate of the "Action" the first key
// creates (keying.h), so frame numbers stay when it appears.
FrameGrid timelineGrid(const EditorState& state);
double timelineFrameTime(const EditorState& state);  // seconds per frame of timelineGrid
double timelineFps(const EditorState& state);
long long frameAtTime(const EditorState& state, double time);  // the nearest frame
double timeOfFrame(const EditorState& state, long long frame);
long long currentFrame(const EditorState& state);
long long rangeStartFrame(const EditorState& state);
long long rangeEndFrame(const EditorState& state);

// Poses the document from the edited clip at the playhead (EditorState::time) with
// Document::setAnimatedPose: joints the clip does not animate keep their pose (Blender
// re-evaluates the action over the pose); not an undo step, not a change to save. Nothing
// without a clip or during a drag. Every view that moves the playhead or edits the clip's
// keys calls this, so the pose shown is always the clip's at the playhead.
void poseAtPlayhead(EditorState& state);
// Moves the playhead to `frame` (also the auto-key time) and poses the document from the
// clip there (while not playing). Frames outside the range are allowed, as in Blender.
void goToFrame(EditorState& state, long long frame);
// A new or opened document: stopped, on its active clip (Document::activeClip), with the
// playhead where the file saved it (Document::savedPlayhead, .kinema "playhead") or, for files without one (glTF, BVH,
// older .kinema), on the edited clip's start frame (frame 1 without a clip); then the
// document is posed from the clip there (poseAtPlayhead), so the first frame drawn shows
// the pose at the playhead, not the rest pose.
void resetTimeline(EditorState& state);
void stepFrame(EditorState& state, int delta);  // Left / Right: one frame, no wrap
void jumpToStart(EditorState& state);           // Shift+Left
void jumpToEnd(EditorState& state);             // Shift+Right
// Space: play from the current frame; pausing lands on the nearest frame and poses the
// document there.
void togglePlayback(EditorState& state);
// Playback: advances by dt seconds within the range, wrapping when looping, else stopping
// at the end.
void advanceTimeline(EditorState& state, double dt);
// Copies the playhead's time (EditorState::time) into the document
// (Document::setPlayheadTime): what auto-key keys at and a save writes. Every function here
// that moves the playhead calls it, and so does evaluateEditorPose each frame.
void syncDocumentPlayhead(EditorState& state);
// EditorState::clip follows the document's active clip (Document::activeClip) after an
// edit, undo or redo changed it or the clip list (Document::clipListRevision): the frame
// number stays (Blender keeps the current frame when the action changes), the dope sheet's
// and curve editor's key selections (keys of the other clip) are cleared, and the document
// is posed from the clip there. Nothing when the document's clips did not change since the
// last call. The clip list's commands, undo, redo and evaluateEditorPose call it.
void followDocumentClip(EditorState& state);

// The frame range is part of the clip (an undo step; a clip is created when the scene has
// none). The rate (the timeline's fps field) is the edited clip's own when it has one (BVH,
// a rate set on it before); otherwise the document's (Scene::frameRate, Blender's scene
// rate), which every clip without its own counts at: their ranges keep their frame numbers.
// Keys keep their times either way. Errors are one line for the status bar.
std::string setFrameRange(EditorState& state, long long start, long long end);
std::string setFrameRate(EditorState& state, double fps);
// True when the timeline's rate is the document's (the edited clip has none of its own).
bool timelineRateIsTheDocuments(const EditorState& state);

// The keying commands at the playhead with the document's key preferences (doc.autoKey.
// preferences), one undo step each; a status line back ("" when nothing to say).
std::string keySelectedJoints(EditorState& state);        // I
std::string keyAllJoints(EditorState& state);             // Animation > Insert keys on all joints
std::string deleteSelectedJointKeys(EditorState& state);  // Alt+I

// The frame ruler in the timeline strip (window pixels): frames first..last spread over
// its width, so scrubbing and the keyframe diamonds agree with the dump's numbers.
struct TimelineRuler {
  float x = 0, y = 0, w = 1, h = 1;
  long long first = 0, last = 1;
  float xOfFrame(long long frame) const;
  long long frameAtX(float px) const;  // nearest frame, clamped to first..last
};
constexpr float kTimelineRulerHeight = 19.0f;  // under the row of buttons (the strip is 40 px)
constexpr float kTimelineRulerMargin = 12.0f;  // left and right, so the end frames' diamonds fit
// `x, y, w, h`: the timeline strip (EditorState::layout.timeline, model/editor_layout.h), window pixels.
TimelineRuler timelineRuler(const EditorState& state, float x, float y, float w, float h);
// Frames holding a key of a selected joint (one diamond each), in the edited clip.
std::vector<long long> selectedKeyFrames(const EditorState& state);

}  // namespace kinema
