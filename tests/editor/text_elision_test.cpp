// Long status-bar messages elided with "…" (text_elision.h) and every message kept in full in
// the log (message_log.h).
#include <gtest/gtest.h>

#include "editor/model/message_log.h"
#include "editor/model/text_elision.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// A monospace measure: 7 px per character (UTF-8 continuation bytes add nothing).
float mono(const std::string& s) {
  float w = 0;
  for (char c : s)
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) w += 7.0f;
  return w;
}

const std::string kEllipsis = "\xE2\x80\xA6";

TEST(TextElision, TextThatFitsIsLeftAlone) {
  EXPECT_EQ(elideText("Inserted keys on frame 20", 25 * 7, mono), "Inserted keys on frame 20");
}

TEST(TextElision, LongTextEndsWithAnEllipsisWithinTheWidth) {
  const std::string text = "Exported walk.glb: 3 clips, 27 joints; the BVH holds one clip, the others were left out";
  for (float width : {30.0f, 70.0f, 200.0f, 500.0f}) {
    const std::string shown = elideText(text, width, mono);
    EXPECT_LE(mono(shown), width) << shown;
    ASSERT_GE(shown.size(), kEllipsis.size());
    EXPECT_EQ(shown.substr(shown.size() - kEllipsis.size()), kEllipsis);
    // The longest start that fits: one more character would not.
    const size_t kept = shown.size() - kEllipsis.size();
    EXPECT_EQ(text.compare(0, kept, shown, 0, kept), 0);
    if (text[kept] != ' ') {
      EXPECT_GT(mono(text.substr(0, kept + 1) + kEllipsis), width) << shown;
    }
  }
  EXPECT_EQ(elideText(text, 70.0f, mono), "Exported" + kEllipsis);  // 9 characters fit; the space is dropped
}

TEST(TextElision, CutsBetweenCharactersAndDropsTrailingSpaces) {
  const std::string text = "Rotate 45\xC2\xB0 about X, then 90\xC2\xB0 about Y";  // degree signs: two bytes each
  for (float width = 7; width < 300; width += 7) {
    const std::string shown = elideText(text, width, mono);
    for (size_t i = 0; i + kEllipsis.size() < shown.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(shown[i]);
      if (c == 0xC2) {
        EXPECT_EQ(static_cast<unsigned char>(shown[i + 1]), 0xB0) << "cut inside a character";
      }
    }
    if (shown.size() > kEllipsis.size()) {
      EXPECT_NE(shown[shown.size() - kEllipsis.size() - 1], ' ');
    }
  }
  EXPECT_EQ(elideText(text, 3.0f, mono), "");  // not even the ellipsis fits
  EXPECT_EQ(elideText("abcdef", 35.0f, mono, "..."), "ab...");  // 2 + 3 characters = 35 px
}

TEST(MessageLog, EveryNewMessageOnceInFull) {
  MessageLog log;
  log.note("Inserted keys on frame 20", "10:00:00");
  log.note("Inserted keys on frame 20", "10:00:01");  // set again: one entry
  log.note("", "10:00:02");
  log.note("cannot open x.glb: not a glTF file", "10:00:03", true);
  ASSERT_EQ(log.entries().size(), 2u);
  EXPECT_EQ(log.entries()[0].time, "10:00:00");
  EXPECT_TRUE(log.entries()[1].error);
  log.observeStatus("cannot open x.glb: not a glTF file");  // the status bar showing the error: no new entry
  EXPECT_EQ(log.entries().size(), 2u);
  log.observeStatus("Undo");
  log.observeStatus("Undo");
  EXPECT_EQ(log.entries().size(), 3u);
  EXPECT_EQ(log.entries().back().time.size(), 8u);  // HH:MM:SS
}

TEST(MessageLog, TheOldestGoFirstPastTheLimit) {
  MessageLog log;
  for (size_t i = 0; i < MessageLog::kMaxEntries + 5; ++i) log.note("message " + std::to_string(i), "t");
  EXPECT_LE(log.entries().size(), MessageLog::kMaxEntries);
  EXPECT_EQ(log.entries().back().text, "message " + std::to_string(MessageLog::kMaxEntries + 4));
}

}  // namespace
}  // namespace kinema
