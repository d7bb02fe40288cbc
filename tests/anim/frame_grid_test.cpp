// One frame rate (issue 38): a clip's frame grid is its own rate, else the document's; files
// that keep no rate get the grid their keys lie on. Expected values are rates chosen by hand.
#include <gtest/gtest.h>

#include "anim/clip.h"
#include "anim/frame_grid.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// A clip with one translation channel keyed at `times`.
Clip keyedAt(const std::vector<float>& times) {
  Clip clip;
  std::vector<glm::vec4> values(times.size(), glm::vec4(0.0f));
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, times, values));
  return clip;
}

// Keys on frames 0..count-1 of `fps`, computed as a file writes them (float seconds).
Clip everyFrame(double fps, int count, int stride = 1) {
  std::vector<float> times;
  for (int f = 0; f < count; f += stride) times.push_back(static_cast<float>(f / fps));
  return keyedAt(times);
}

TEST(FrameGrid, FramesAndTimesOfAGrid) {
  const FrameGrid grid{1.0 / 120.0};
  EXPECT_DOUBLE_EQ(grid.framesPerSecond(), 120.0);
  EXPECT_FLOAT_EQ(grid.frameToTime(240), 2.0f);
  EXPECT_DOUBLE_EQ(grid.timeToFrame(0.5), 60.0);
  EXPECT_EQ(grid.nearestFrame(1.004), 120);  // 120.48
  EXPECT_EQ(grid.nearestFrame(std::nan("")), 0);
}

TEST(FrameGrid, AClipsOwnRateWinsOverTheDocuments) {
  Clip clip;
  EXPECT_DOUBLE_EQ(frameGridOf(clip, 30.0).secondsPerFrame, 1.0 / 30.0);
  EXPECT_DOUBLE_EQ(frameGridOf(clip, -5.0).secondsPerFrame, 1.0 / kDefaultFrameRate);
  clip.frameTime = 1.0 / 120.0;
  EXPECT_DOUBLE_EQ(frameGridOf(clip, 30.0).secondsPerFrame, 1.0 / 120.0);
  EXPECT_DOUBLE_EQ(ownFrameGrid(clip).secondsPerFrame, 1.0 / 120.0);
  EXPECT_DOUBLE_EQ(documentFrameGrid(25.0).framesPerSecond(), 25.0);
}

TEST(KeyGrid, DenseKeysGiveTheirOwnGrid) {
  EXPECT_EQ(keyGridFrameTime(everyFrame(30.0, 90)), 1.0 / 30.0);    // snapped to the common rate exactly
  EXPECT_EQ(keyGridFrameTime(everyFrame(120.0, 721)), 1.0 / 120.0);
  EXPECT_NEAR(keyGridFrameTime(everyFrame(20.0, 41)), 0.05, 1e-8);  // not a common rate: measured
  EXPECT_NEAR(keyGridFrameTime(everyFrame(29.97, 300)), 1.0 / 29.97, 1e-8);
  // A grid with frames left out is still its own rate when the keys are dense: every other
  // frame of 60 fps is 30 fps.
  EXPECT_EQ(keyGridFrameTime(everyFrame(60.0, 120, 2)), 1.0 / 30.0);
}

TEST(KeyGrid, SparseKeysCountAtTheSmallestCommonRateHoldingThem) {
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.0f, 0.5f, 1.0f, 2.5f})), 1.0 / 24.0);
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.0f, 0.4f, 1.2f})), 1.0 / 25.0);      // 0.4 s = 10 frames of 25, 9.6 of 24
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.0f, 1.0f / 3.0f})), 1.0 / 24.0);     // 8 frames of 24
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.0f, 0.7f, 1.3f})), 1.0 / 30.0);      // 21 and 39 frames of 30
}

TEST(KeyGrid, KeysOnNoGridOrTooFewHaveNone) {
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.0f, 0.1234f, 0.5f})), 0.0);
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.25f})), 0.0);
  EXPECT_EQ(keyGridFrameTime(Clip{}), 0.0);
  // Keys 1e-4 s apart: a 10,000 fps grid, beyond the 1000 fps the editor allows.
  EXPECT_EQ(keyGridFrameTime(keyedAt({0.0f, 0.0001f, 0.0002f, 0.00025f})), 0.0);
}

}  // namespace
}  // namespace kinema
