#pragma once
// File > Import Motion onto Character…: a motion file's clip (BVH, glTF, .kinema) put onto the
// open document's skeleton through a bone map (retarget/retarget_motion.h, the computation
// `kinema retarget` runs without --fix-feet and --reduce). prepareMotionImport reads the file
// and finds the map (names, then topology) for the dialog to show; applyMotionImport adds the
// retargeted clip as a new clip, made active, in one undo step. No GL, no ImGui.
#include <string>
#include <vector>

#include "core/result.h"
#include "io/input_limits.h"
#include "scene/scene.h"
#include "io/up_axis.h"
#include "retarget/bone_map.h"

namespace kinema {

class Document;

// One row of the dialog's table: a canonical bone either reading has, with the joint each
// side plays it with (-1: that side has none, or the pair is not in the map).
struct MotionImportRow {
  std::string bone;  // canonical name ("LeftUpperLeg")
  int source = -1;   // joint of the source skeleton
  int target = -1;   // joint of the document's skeleton
};

struct MotionImport {
  std::string path;    // the motion file
  Scene source;        // what it holds (its skeleton and clips)
  int clip = 0;        // the clip played (the file's first unless the dialog chose another)
  // -1: Apply adds a new clip; else the document clip whose bone map was opened again
  // (prepareMotionImportOfClip), which Apply replaces.
  int replaceClip = -1;
  HumanoidReading sourceHuman;
  HumanoidReading targetHuman;
  BoneMap map;
  std::string mapBy;  // "names", "topology" or "names and topology"
  std::vector<MotionImportRow> rows;  // in canonical order
  std::vector<int> unmappedSource;    // source joints no pair names
  std::vector<int> unmappedTarget;    // document joints no pair names (they keep their rest)
};

// Reads `path` and maps its skeleton onto the document's. Fails with one line (a file that
// cannot be read, one with no clip, either skeleton not a humanoid, an incompatible map);
// the document is not touched either way.
Result<MotionImport> prepareMotionImport(const Document& doc, const std::string& path, const InputLimits& limits = {},
                                         UpAxis bvhUp = UpAxis::Y);
// The import a retargeted clip came from, opened again with the bone map it keeps
// (Clip::sourceMap: the file read again, the saved pairs) so the dialog shows and edits it;
// Apply then replaces that clip. Fails with one line (no saved map, the file gone, a saved
// joint the file no longer has).
Result<MotionImport> prepareMotionImportOfClip(const Document& doc, int clip, const InputLimits& limits = {},
                                               UpAxis bvhUp = UpAxis::Y);
// Rebuilds rows and the unmapped lists from `import.map` (after the map changed).
void refreshMotionImportRows(MotionImport& import, const Skeleton& target);
// Sets the source joint playing canonical row `row` (-1: none) and rebuilds the rows.
// Returns "" or why not (that joint already plays another row, hierarchy disagrees).
std::string setMotionImportSource(MotionImport& import, const Skeleton& target, int row, int sourceJoint);

// Retargets the clip onto the document's skeleton and appends it as a new clip named after
// the source clip (uniqueClipName), made active: one undo step "Import motion NAME". The
// clip keeps its bone map (Clip::sourceMap) and, on a skeleton with humanoid legs, the foot
// contacts detected on it (Clip::contacts). With replaceClip the clip there is replaced
// instead (its name kept): "Re-import motion NAME".
// Returns "" or a one-line reason nothing changed.
std::string applyMotionImport(Document& doc, const MotionImport& import);

}  // namespace kinema
