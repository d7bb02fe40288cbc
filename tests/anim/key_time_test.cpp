// One key-time tolerance and one findKey (anim/clip.h, issue 17): inserting, moving and
// finding keys treat times within kKeyTimeTolerance as the same key. Before, insertKey and
// moveKey compared exactly, keying.cpp used 1e-4 s and the dope sheet 1e-5 s, so a key set
// a float's width off a frame sat beside the key there instead of replacing it.
#include <gtest/gtest.h>

#include "anim/clip.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Channel threeKeys() {
  return Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 0.5f, 1.0f},
                 {glm::vec4(0), glm::vec4(1, 0, 0, 0), glm::vec4(2, 0, 0, 0)});
}

TEST(KeyTime, FindKeyFindsTheNearestKeyWithinTheTolerance) {
  const Channel ch = threeKeys();
  EXPECT_EQ(findKey(ch, 0.5f), 1);
  EXPECT_EQ(findKey(ch, 0.5f + 0.6f * kKeyTimeTolerance), 1);
  EXPECT_EQ(findKey(ch, 0.5f - 0.6f * kKeyTimeTolerance), 1);
  EXPECT_EQ(findKey(ch, 0.5f + 2.0f * kKeyTimeTolerance), -1);
  EXPECT_EQ(findKey(ch, 1.0f + 0.5f * kKeyTimeTolerance), 2);  // past the last key
  EXPECT_EQ(findKey(ch, -0.5f * kKeyTimeTolerance), 0);         // before the first
  EXPECT_EQ(findKey(Channel{}, 0.0f), -1);
  // Two keys both within the tolerance: the nearer one.
  Channel close(0, ChannelTarget::Translation, Interpolation::Linear, {1.0f, 1.0f + 0.8f * kKeyTimeTolerance},
                {glm::vec4(0), glm::vec4(1, 0, 0, 0)});
  EXPECT_EQ(findKey(close, 1.0f + 0.7f * kKeyTimeTolerance), 1);
  EXPECT_EQ(findKey(close, 1.0f + 0.1f * kKeyTimeTolerance), 0);
  EXPECT_TRUE(sameKeyTime(2.0f, 2.0f + 0.9f * kKeyTimeTolerance));
  EXPECT_FALSE(sameKeyTime(2.0f, 2.0f + 1.5f * kKeyTimeTolerance));
}

// Regression: the old exact comparison added a fourth key 5e-5 s after the middle one.
TEST(KeyTime, InsertingAFloatsWidthOffAKeyReplacesItAtItsTime) {
  Channel ch = threeKeys();
  const float nearly = 0.5f + 0.5f * kKeyTimeTolerance;
  EXPECT_EQ(insertKey(ch, nearly, glm::vec4(7, 0, 0, 0)), 1);
  ASSERT_EQ(ch.keyCount(), 3);
  EXPECT_EQ(ch.times[1], 0.5f);  // the key keeps its time
  EXPECT_EQ(ch.values[1].x, 7.0f);
  KeySettings step;
  step.interpolation = Interpolation::Step;
  EXPECT_EQ(insertKey(ch, 0.5f - 0.5f * kKeyTimeTolerance, glm::vec4(8, 0, 0, 0), step), 1);
  ASSERT_EQ(ch.keyCount(), 3);
  EXPECT_EQ(ch.settings(1).interpolation, Interpolation::Step);
}

// Regression: moving a key onto a float's width of another kept both.
TEST(KeyTime, MovingOntoAnotherKeysTimeReplacesIt) {
  Channel ch = threeKeys();
  EXPECT_EQ(moveKey(ch, 0, 1.0f - 0.5f * kKeyTimeTolerance), 1);
  ASSERT_EQ(ch.keyCount(), 2);
  EXPECT_EQ(ch.times[1], 1.0f);
  EXPECT_EQ(ch.values[1].x, 0.0f);  // the moved key's value
  // With per-key settings too.
  Channel keyed = threeKeys();
  keyed.keys.assign(3, KeySettings{});
  keyed.keys[2].interpolation = Interpolation::Step;
  EXPECT_EQ(moveKey(keyed, 2, 0.5f + 0.5f * kKeyTimeTolerance), 1);
  ASSERT_EQ(keyed.keyCount(), 2);
  EXPECT_EQ(keyed.times[1], 0.5f);
  EXPECT_EQ(keyed.settings(1).interpolation, Interpolation::Step);
}

}  // namespace
}  // namespace kinema
