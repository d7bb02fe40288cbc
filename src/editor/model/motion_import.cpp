// File > Import Motion onto Character… without a window: read the motion file, find the bone
// map, and add the retargeted clip as one undo step (motion_import.h).
#include "editor/model/motion_import.h"

#include <algorithm>

#include "editor/model/clip_list.h"
#include "editor/model/document.h"
#include "evaluation/scene_poses.h"
#include "io/scene_files.h"
#include "retarget/motion_cleanup.h"
#include "retarget/retarget_motion.h"

namespace kinema {

namespace {

const std::string kTargetLabel = "the open character";

}  // namespace

void refreshMotionImportRows(MotionImport& m, const Skeleton& target) {
  m.rows.clear();
  for (int i = 0; i < kHumanoidBoneCount; ++i) {
    const int s = m.sourceHuman.bones.joint[i];
    const int t = m.targetHuman.bones.joint[i];
    if (s < 0 && t < 0) continue;
    MotionImportRow row;
    row.bone = toString(humanoidBone(i));
    row.target = t;
    row.source = t >= 0 ? m.map.sourceOf(t) : s;
    m.rows.push_back(row);
  }
  m.unmappedSource.clear();
  m.unmappedTarget.clear();
  for (int j = 0; j < m.source.skeleton.size(); ++j)
    if (m.map.targetOf(j) < 0) m.unmappedSource.push_back(j);
  for (int j = 0; j < target.size(); ++j)
    if (m.map.sourceOf(j) < 0) m.unmappedTarget.push_back(j);
}

Result<MotionImport> prepareMotionImport(const Document& doc, const std::string& path, const InputLimits& limits,
                                         UpAxis bvhUp) {
  using R = Result<MotionImport>;
  Result<Scene> loaded = loadScene(path, limits, bvhUp);
  if (!loaded) return R::failure(loaded.error());
  MotionImport m;
  m.path = path;
  m.source = std::move(loaded.value());
  if (m.source.clips.empty()) return R::failure(path + ": has no clip to retarget (no motion)");
  const Skeleton& target = doc.skeleton();
  if (target.size() == 0) return R::failure("the open document has no skeleton to put the motion onto");
  const Result<HumanoidReading> sourceHuman = findHumanoid(m.source.skeleton);
  const Result<HumanoidReading> targetHuman = findHumanoid(target);
  Result<AutomaticBoneMap> automatic = automaticBoneMap(sourceHuman, targetHuman, path, kTargetLabel);
  if (!automatic) return R::failure(automatic.error());
  m.sourceHuman = sourceHuman.value();
  m.targetHuman = targetHuman.value();
  m.map = std::move(automatic->map);
  m.mapBy = automatic->mapBy;
  if (const std::string bad = m.map.validate(m.source.skeleton, target); !bad.empty())
    return R::failure(path + " onto " + kTargetLabel + ": " + bad);
  refreshMotionImportRows(m, target);
  return m;
}

Result<MotionImport> prepareMotionImportOfClip(const Document& doc, int clip, const InputLimits& limits, UpAxis bvhUp) {
  using R = Result<MotionImport>;
  if (clip < 0 || clip >= static_cast<int>(doc.scene().clips.size())) return R::failure("the document has no such clip");
  const Clip& c = doc.scene().clips[clip];
  if (c.sourceMap.empty() || c.sourceMap.file.empty())
    return R::failure("clip '" + c.name + "' keeps no bone map (it was not imported onto this character)");
  Result<MotionImport> m = prepareMotionImport(doc, c.sourceMap.file, limits, bvhUp);
  if (!m) return m;
  if (c.sourceMap.clip >= static_cast<int>(m->source.clips.size()))
    return R::failure(c.sourceMap.file + ": has no clip " + std::to_string(c.sourceMap.clip) + " any more");
  Result<BoneMap> kept = fromClipSourceMap(c.sourceMap, m->source.skeleton, doc.skeleton());
  if (!kept) return R::failure(c.sourceMap.file + ": " + kept.error());
  m->map = std::move(kept.value());
  m->mapBy = "saved with the clip";
  m->clip = c.sourceMap.clip;
  m->replaceClip = clip;
  refreshMotionImportRows(m.value(), doc.skeleton());
  return m;
}

std::string setMotionImportSource(MotionImport& m, const Skeleton& target, int row, int sourceJoint) {
  if (row < 0 || row >= static_cast<int>(m.rows.size())) return "no such bone row";
  const int t = m.rows[row].target;
  if (t < 0) return "the open character has no " + m.rows[row].bone + " to drive";
  if (sourceJoint >= m.source.skeleton.size()) return "no such source joint";
  if (sourceJoint >= 0 && m.map.targetOf(sourceJoint) >= 0 && m.map.targetOf(sourceJoint) != t)
    return "'" + m.source.skeleton.names[sourceJoint] + "' already drives '" + target.names[m.map.targetOf(sourceJoint)] + "'";
  BoneMap changed = m.map;
  changed.pairs.erase(std::remove_if(changed.pairs.begin(), changed.pairs.end(),
                                     [t](const BonePair& p) { return p.target == t; }),
                      changed.pairs.end());
  if (sourceJoint >= 0) changed.pairs.push_back(BonePair{sourceJoint, t});
  std::sort(changed.pairs.begin(), changed.pairs.end(),
            [](const BonePair& a, const BonePair& b) { return a.target < b.target; });
  if (changed.pairs.empty()) return "the map needs at least one pair";
  if (const std::string bad = changed.validate(m.source.skeleton, target); !bad.empty()) return bad;
  m.map = std::move(changed);
  refreshMotionImportRows(m, target);
  return {};
}

std::string applyMotionImport(Document& doc, const MotionImport& m) {
  if (m.clip < 0 || m.clip >= static_cast<int>(m.source.clips.size())) return m.path + ": has no clip to retarget";
  RetargetMotionInput in;
  in.source = &m.source.skeleton;
  in.clip = &m.source.clips[m.clip];
  ScenePoses sourcePoses(m.source, m.clip);  // the take as it plays (the one pipeline)
  in.sourcePoses = &sourcePoses;
  in.sourceHuman = &m.sourceHuman;
  in.target = &doc.skeleton();
  in.targetHuman = &m.targetHuman;
  in.map = &m.map;
  in.sourceLabel = m.path;
  in.targetLabel = kTargetLabel;
  Result<RetargetedMotion> retargeted = retargetMotion(in);
  if (!retargeted) return retargeted.error();
  Clip clip = std::move(retargeted->clip);
  clip.sourceMap = toClipSourceMap(m.map, m.source.skeleton, m.path, m.clip);
  LegJoints legs[2];
  if (humanoidLegs(doc.skeleton(), m.targetHuman.bones, legs).empty())
    if (std::string bad = detectFootContacts(doc.skeleton(), clip, legs, clip.contacts); !bad.empty()) return bad;
  const int replace = m.replaceClip;
  if (replace >= static_cast<int>(doc.scene().clips.size())) return "the clip to re-import is gone";
  if (replace >= 0) {
    clip.name = doc.scene().clips[replace].name;
    return doc.edit("Re-import motion " + clip.name, [&](DocumentEdit& e) {
      e.clips[replace] = clip;
      e.activeClip = replace;
      return std::string();
    });
  }
  clip.name = uniqueClipName(doc.scene().clips, clip.name.empty() ? std::string("Motion") : clip.name);
  return doc.edit("Import motion " + clip.name, [&](DocumentEdit& e) {
    e.clips.push_back(clip);
    e.activeClip = static_cast<int>(e.clips.size()) - 1;
    return std::string();
  });
}

}  // namespace kinema
