// File > Import Motion onto Character… in the model (issue 21): the CMU take's bone map onto
// the default character, the retargeted clip added as one new active clip (one undo step:
// undo removes it, redo brings it back), the same clip `kinema retarget` computes, and bad
// input refused with the document unchanged.
#include <gtest/gtest.h>

#include "editor/model/document.h"
#include "editor/model/document_files.h"
#include "editor/model/motion_import.h"
#include "retarget/retarget_clip.h"
#include "retarget/retarget_motion.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

std::string cmuTake() { return test::sharedDataDir() + "/bvh/cmu_01_01_first720.bvh"; }

TEST(MotionImport, CmuTakeOntoTheDefaultCharacterIsOneUndoableNewClip) {
  KINEMA_REQUIRE_SHARED_DATA();
  Document doc = newDocument();
  const size_t before = doc.scene().clips.size();
  const int activeBefore = doc.activeClip();

  Result<MotionImport> prepared = prepareMotionImport(doc, cmuTake());
  ASSERT_TRUE(prepared) << prepared.error();
  const MotionImport& m = prepared.value();
  EXPECT_EQ(m.mapBy, "names");
  EXPECT_EQ(doc.scene().clips.size(), before) << "preparing changes nothing";
  // Every row the map pairs names a joint on both sides; the hips and feet are mapped.
  int mapped = 0;
  for (const MotionImportRow& r : m.rows)
    if (r.source >= 0 && r.target >= 0) {
      ++mapped;
      EXPECT_EQ(m.map.sourceOf(r.target), r.source) << r.bone;
    }
  EXPECT_GE(mapped, 15);
  for (const char* bone : {"Hips", "LeftFoot", "RightFoot", "Head"}) {
    bool found = false;
    for (const MotionImportRow& r : m.rows)
      if (r.bone == bone) found = r.source >= 0 && r.target >= 0;
    EXPECT_TRUE(found) << bone;
  }
  EXPECT_EQ(m.unmappedSource.size() + m.map.pairs.size(), static_cast<size_t>(m.source.skeleton.size()));
  EXPECT_EQ(m.unmappedTarget.size() + m.map.pairs.size(), static_cast<size_t>(doc.skeleton().size()));

  ASSERT_EQ(applyMotionImport(doc, m), "");
  ASSERT_EQ(doc.scene().clips.size(), before + 1);
  const int added = static_cast<int>(before);
  EXPECT_EQ(doc.activeClip(), added);
  const Clip imported = doc.scene().clips[added];
  EXPECT_EQ(imported.name, m.source.clips[0].name);
  EXPECT_EQ(clipFrameCount(imported), clipFrameCount(m.source.clips[0]));
  EXPECT_FALSE(imported.channels.empty());
  EXPECT_TRUE(doc.dirty());

  // The same clip the shared computation (`kinema retarget`'s) gives.
  const Result<HumanoidReading> sh = findHumanoid(m.source.skeleton);
  const Result<HumanoidReading> th = findHumanoid(doc.skeleton());
  ASSERT_TRUE(sh && th);
  RetargetMotionInput in;
  in.source = &m.source.skeleton;
  in.clip = &m.source.clips[0];
  in.sourceHuman = &sh.value();
  in.target = &doc.skeleton();
  in.targetHuman = &th.value();
  in.map = &m.map;
  Result<RetargetedMotion> direct = retargetMotion(in);
  ASSERT_TRUE(direct) << direct.error();
  ASSERT_EQ(direct->clip.channels.size(), imported.channels.size());
  for (size_t c = 0; c < imported.channels.size(); ++c) {
    EXPECT_EQ(imported.channels[c].joint, direct->clip.channels[c].joint);
    EXPECT_EQ(imported.channels[c].values, direct->clip.channels[c].values);
  }

  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().clips.size(), before);
  EXPECT_EQ(doc.activeClip(), activeBefore);
  ASSERT_TRUE(doc.redo());
  ASSERT_EQ(doc.scene().clips.size(), before + 1);
  EXPECT_EQ(doc.activeClip(), added);
  EXPECT_EQ(doc.scene().clips[added].name, imported.name);
  EXPECT_EQ(doc.scene().clips[added].channels.size(), imported.channels.size());

  // A second import of the same take gets a fresh name (Blender's .001).
  ASSERT_EQ(applyMotionImport(doc, m), "");
  ASSERT_EQ(doc.scene().clips.size(), before + 2);
  EXPECT_EQ(doc.scene().clips.back().name, imported.name + ".001");
}

TEST(MotionImport, EditingARowChangesTheMapAndRefusesADuplicate) {
  KINEMA_REQUIRE_SHARED_DATA();
  Document doc = newDocument();
  Result<MotionImport> prepared = prepareMotionImport(doc, cmuTake());
  ASSERT_TRUE(prepared) << prepared.error();
  MotionImport& m = prepared.value();
  int head = -1, neck = -1;
  for (int r = 0; r < static_cast<int>(m.rows.size()); ++r) {
    if (m.rows[r].bone == "Head") head = r;
    if (m.rows[r].bone == "Neck") neck = r;
  }
  ASSERT_GE(head, 0);
  ASSERT_GE(neck, 0);
  ASSERT_GE(m.rows[neck].source, 0);
  const size_t pairs = m.map.pairs.size();
  EXPECT_NE(setMotionImportSource(m, doc.skeleton(), head, m.rows[neck].source), "") << "a joint drives one bone";
  ASSERT_EQ(setMotionImportSource(m, doc.skeleton(), head, -1), "");
  EXPECT_EQ(m.rows[head].source, -1);
  EXPECT_EQ(m.map.pairs.size(), pairs - 1);
  EXPECT_EQ(m.unmappedTarget.size() + m.map.pairs.size(), static_cast<size_t>(doc.skeleton().size()));
  EXPECT_EQ(applyMotionImport(doc, m), "") << "the map without the head still retargets";
}

TEST(MotionImport, BadInputChangesNothing) {
  const std::string dir = test::makeTempDir();
  Document doc = newDocument();
  const size_t before = doc.scene().clips.size();
  // Not a humanoid: a two-joint chain with a motion.
  test::writeFile(dir + "/stick.bvh",
                  "HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n JOINT B\n {\n"
                  "  OFFSET 0 1 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n  End Site\n  {\n   OFFSET 0 1 0\n  }\n"
                  " }\n}\nMOTION\nFrames: 2\nFrame Time: 0.0333333\n0 0 0 0 0 0\n10 0 0 0 0 0\n");
  Result<MotionImport> stick = prepareMotionImport(doc, dir + "/stick.bvh");
  ASSERT_FALSE(stick);
  EXPECT_NE(stick.error().find("stick.bvh"), std::string::npos) << stick.error();
  EXPECT_EQ(stick.error().find('\n'), std::string::npos) << "one line";
  Result<MotionImport> missing = prepareMotionImport(doc, dir + "/missing.bvh");
  ASSERT_FALSE(missing);
  EXPECT_EQ(doc.scene().clips.size(), before);
  EXPECT_FALSE(doc.dirty());
}

}  // namespace
}  // namespace kinema
