#pragma once
// Frame numbers: the one place that says which moment "frame N" of a clip is. Every view,
// subcommand and writer counts through a FrameGrid from frameGridOf (or Scene::frameGrid).

namespace kinema {

struct Clip;

// The document's frame rate when neither the file nor the clip gives one: Blender's default,
// and the rate of a new document. Frames per second.
constexpr double kDefaultFrameRate = 24.0;
// The frame rates the editor and the files accept (frames per second, inclusive).
constexpr double kMinFrameRate = 1.0;
constexpr double kMaxFrameRate = 1000.0;

// A clip's frame grid: frame N is at N * secondsPerFrame seconds, frame 0 at time 0.
struct FrameGrid {
  double secondsPerFrame = 1.0 / kDefaultFrameRate;  // > 0

  double framesPerSecond() const { return 1.0 / secondsPerFrame; }
  // Time of frame N (seconds), computed as frame-based files compute their keys' times, so
  // sampling at it returns that frame's values exactly.
  float frameToTime(long long frame) const;
  // The (fractional) frame at `time` seconds, and the nearest whole frame (0 for a
  // non-finite time; clamped to +-1e12 frames).
  double timeToFrame(double time) const;
  long long nearestFrame(double time) const;
};

// The grid a clip counts in: its own frame time (Clip::frameTime, BVH's Frame Time or an
// edited clip's rate) when it has one, else the document's rate (`documentFrameRate`, frames
// per second; a rate that is not finite and positive counts as kDefaultFrameRate).
FrameGrid frameGridOf(const Clip& clip, double documentFrameRate);
// The grid of a clip that carries its own rate (Clip::frameTime > 0): what the jobs below the
// scene layer count in (bakes, retargeting, contacts). Their scene-level callers give the clip
// the document's rate first (Scene::frameGrid); a clip without a rate yields an invalid grid
// (secondsPerFrame 0), which those jobs' validation refuses (hasOwnFrameRate).
FrameGrid ownFrameGrid(const Clip& clip);
bool hasOwnFrameRate(const Clip& clip);
// The grid of a document's rate alone (no clip, or a clip without its own rate).
FrameGrid documentFrameGrid(double documentFrameRate);

// True when every key of the clip lies on a frame of `grid` (within a thousandth of a frame
// and the float rounding of the key time).
bool keysOnGrid(const Clip& clip, const FrameGrid& grid);

// The frame time (seconds) of the grid every key of the clip lies on, or 0 when the keys lie
// on no grid of kMinFrameRate..kMaxFrameRate fps (or the clip has fewer than two key times).
// The grid of the smallest key interval when it is dense (10 fps or more: mocap, baked keys);
// for sparser keys, which lie on many grids, the smallest of 24, 25, 30, 48, 50, 60, 100 and
// 120 fps whose grid holds every key (keys every half second count at 24 fps), else the
// sparse grid itself. For files that keep no rate (glTF) and writers that need one (BVH).
double keyGridFrameTime(const Clip& clip);

}  // namespace kinema
