#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/pose.h"
#include "editor/model/edit_history.h"
#include "editor/model/joint_selection.h"
#include "editor/model/key_preferences.h"
#include "ik/ik_posing_job.h"
#include "ik/pose_ik_target.h"
#include "scene/scene.h"

namespace kinema {

// Per target, what the last IK solve did (for the status bar).
// The parts of a document an edit may change, handed to an edit's change function.
struct DocumentEdit {
  const Skeleton& skeleton;            // read-only (use names for renames)
  std::vector<std::string>& names;     // joint names (renames keep them unique)
  Pose& pose;                          // the working pose
  std::vector<JointLimit>& limits;     // empty or one per joint
  std::vector<PoseIkTarget>& targets;  // the IK targets
  std::vector<SkinningMethod>& skinning;  // one per scene mesh instance (linear blend / dual quaternion)
  std::vector<Clip>& clips;            // the scene's clips: keys, ranges, names (validated after the change)
  int& activeClip;                     // the clip the timeline plays and edits (clamped into clips after the change)
  SimulationSettings& simulation;      // dynamic chains and ragdolls (validated after the change)
  double& frameRate;                   // the document's frame rate (Scene::frameRate; kMinFrameRate..kMaxFrameRate)
};

// The scene being edited plus everything the editor adds to it: the working pose, the IK
// targets with their editor settings, the undo history, the selection, the file path and
// the dirty flag. No GL, no window: every operation is a plain call (tests drive it).
//
// Every change to the pose, names, limits or targets goes through edit() or a drag, so it
// is one undo step. After each change the active IK targets are solved (ik_posing.h) in
// the same step, unless autoSolveIk is off.
class Document {
 public:
  Document();  // an empty scene
  explicit Document(Scene scene, std::string path = "");

  const Scene& scene() const { return scene_; }
  const Skeleton& skeleton() const { return scene_.skeleton; }
  const Pose& pose() const { return pose_; }
  const std::vector<PoseIkTarget>& ikTargets() const { return targets_; }
  const IkRig& rig() const { return scene_.ik; }  // limits (targets live in ikTargets())
  // World transforms (model space: the scene's root frame, the skeleton's units) of the
  // working pose, one per joint: the one evaluation every panel, tool and renderer reads.
  // Computed by forward kinematics on the first call after the pose changed (poseRevision)
  // and kept until the next change, so any number of reads in a frame costs one FK. The
  // reference stays valid until the document changes or is replaced.
  const std::vector<glm::mat4>& worldTransforms() const;
  // Changes whenever the working pose may have changed (edits, drags, undo / redo, animated
  // poses); equal revisions mean the same pose. Unique within the process, so a revision
  // of a replaced document never matches one of its successor.
  long long poseRevision() const { return poseRevision_; }
  // How many times worldTransforms() ran forward kinematics (for tests of the cache).
  long long worldEvaluations() const { return worldEvaluations_; }
  // The scene as it is saved: skeleton names (and the glTF node names of renamed
  // joints), pose, limits and targets written back.
  Scene sceneForSaving() const;
  // The scene's IK data as a file keeps it: the limits and the targets with their options
  // (what the evaluation's IK stage solves; scene().ik holds the limits alone).
  IkRig savedRig() const;

  // The file this document was opened from or last saved to ("" for a new one).
  const std::string& path() const { return path_; }
  void setPath(std::string path) { path_ = std::move(path); }
  bool dirty() const;
  bool needsConfirmationToDiscard() const { return dirty(); }
  void markSaved();  // the current state is what the file holds
  void markModified();  // dirty until the next save (a recovered document)
  // Grows with every change of content (edits, undo, redo, drag updates): autosave compares it.
  long long changeCount() const { return changeCount_; }

  // ---- edits ----
  // Runs `change` as one undo step named `label`. `change` returns "" or a one-line
  // error; on error everything it did is reverted and the error returned. An edit that
  // changes nothing adds no step. Refused while a drag is in progress.
  std::string edit(const std::string& label, const std::function<std::string(DocumentEdit&)>& change);

  // Replaces the scene's meshes, skins, mesh instances and deformer stacks as one undo step:
  // `change` edits a copy of the scene (only those four arrays are taken back; the instance
  // count must stay, and the stacks must be valid: DeformerStack::validate).
  std::string editMeshes(const std::string& label, const std::function<std::string(Scene&)>& change);
  // Grows whenever the meshes, skins or instances were replaced (GPU copies must upload again).
  long long meshRevision() const { return meshRevision_; }

  // An interactive drag is one undo step: begin, any number of updates (each starts from
  // the state at begin, so the result depends only on the latest update), then commit or
  // cancel (Esc / right click: back to the start, nothing recorded).
  std::string beginDrag(const std::string& label);
  std::string updateDrag(const std::function<std::string(DocumentEdit&)>& change);
  void commitDrag();
  void cancelDrag();
  bool dragging() const { return drag_.has_value(); }

  // The auto-IK drag's temporary target (shown while dragging; cleared by commit/cancel).
  const std::optional<PoseIkTarget>& temporaryIkTarget() const { return temporaryTarget_; }
  void setTemporaryIkTarget(std::optional<PoseIkTarget> target) { temporaryTarget_ = std::move(target); }
  // The IK target an edit or drag drives (solved first, never "follows"); -1 none.
  void setDrivenIkTarget(int target) { drivenTarget_ = target; }
  int drivenIkTarget() const { return drivenTarget_; }

  // The working pose set from the animation at the current frame (scrubbing, stepping,
  // pausing): not an undo step and not a change to save, as Blender re-evaluates the action
  // on a frame change. Refused (false) during a drag or when the pose does not fit. A pose
  // equal to the current one changes nothing (not even poseRevision).
  bool setAnimatedPose(const Pose& pose);

  // The active clip: the index into scene().clips the timeline, dope sheet, curve editor
  // and onion skin play and edit (Blender's active action); 0 when the scene has none. Part
  // of the document: it changes only in an edit (DocumentEdit::activeClip, the clip list's
  // commands, clip_list.h), so undo and redo bring it back, and a save writes it (.kinema
  // "playhead.clip"). Opened from the file's playhead, else 0.
  int activeClip() const { return activeClip_; }
  // Changes whenever the active clip or the number of clips may have changed (edits, undo,
  // redo, drags): the views compare it to follow the document (timeline.h
  // followDocumentClip). Unique within the process, like poseRevision.
  long long clipListRevision() const { return clipListRevision_; }
  // The timeline's playhead: the active clip and the time in seconds, what auto-key keys at
  // and what a save writes (.kinema "playhead"). EditorState::time is the time the views
  // move; the timeline copies it here whenever it changes (timeline.h
  // syncDocumentPlayhead). Not an undo step, not a change to save. Until it is set (a
  // document no timeline showed) it is the file's, else time 0, and a save writes a
  // playhead only when the active clip is not the first: such a file opens on its clip's
  // start frame.
  ScenePlayhead playhead() const { return {activeClip_, playheadTime_.value_or(0.0)}; }
  void setPlayheadTime(double seconds) { playheadTime_ = seconds; }
  // The playhead the file was saved with (.kinema "playhead"); empty for files without one
  // (glTF, BVH, older .kinema files, a new document), which open at the clip's start.
  const std::optional<ScenePlayhead>& savedPlayhead() const { return savedPlayhead_; }

  // ---- history ----
  bool canUndo() const;
  bool canRedo() const;
  bool undo();
  bool redo();
  // Labels of the history, oldest first; historyPosition() of them are applied.
  std::vector<std::string> historyLabels() const;
  int historyPosition() const { return history_.position(); }
  // Undoes or redoes until `position` entries are applied (0: the original state).
  bool jumpToHistory(int position);

  // ---- settings, selection, IK status (not undo steps) ----
  bool xMirror = false;       // rotation edits also set the mirror partner (mirror_names.h)
  bool autoSolveIk = true;    // solve the active IK targets after every change
  IkSettings ikSettings;      // tolerance and iteration cap of those solves
  JointSelection selection;
  // Auto-key: applied inside every edit and drag update after the change and its IK solve,
  // so the keys are part of the same undo step, at the playhead (keying.h).
  AutoKeySettings autoKey;
  const std::vector<IkTargetReport>& lastIkReports() const { return ikReports_; }

 private:
  struct Snapshot {
    std::vector<std::string> names;
    std::vector<Transform> pose;
    std::vector<JointLimit> limits;
    std::vector<PoseIkTarget> targets;
    std::vector<SkinningMethod> skinning;
    std::vector<Clip> clips;
    int activeClip = 0;
    SimulationSettings simulation;
    double frameRate = kDefaultFrameRate;
  };
  struct Drag {
    std::string label;
    Snapshot start;
  };
  Snapshot capture() const;
  void syncSkinning();  // skinning_ -> scene_.meshInstances[i].skinning
  void restore(const Snapshot& s);
  DocumentEdit editView();
  std::string runChange(const std::function<std::string(DocumentEdit&)>& change, bool driven);
  EditRecord diff(const std::string& label, const Snapshot& before) const;
  void pushRecord(EditRecord record);
  void apply(const EditRecord& record, bool forward);

  Scene scene_;
  std::vector<std::string> loadedNames_;  // joint names as loaded: renames update glTF node names
  Pose pose_;
  void poseChanged();  // a new poseRevision_
  long long poseRevision_ = 0;
  mutable std::vector<glm::mat4> world_;  // worldTransforms() of pose revision worldRevision_
  mutable long long worldRevision_ = -1;
  mutable long long worldEvaluations_ = 0;
  int activeClip_ = 0;
  long long clipListRevision_ = 0;
  // A new clipListRevision_ when the active clip or the clip count differs from these.
  void noteClipList(int activeBefore, size_t countBefore);
  std::optional<double> playheadTime_;
  std::optional<ScenePlayhead> savedPlayhead_;
  std::vector<PoseIkTarget> targets_;
  long long meshRevision_ = 0;
  std::vector<SkinningMethod> skinning_;  // edited here, written into scene_.meshInstances after each change
  std::string path_;
  EditHistory history_;
  long long savedAt_ = 0;    // history_.dropped() + position() when last saved
  bool savedReachable_ = true;
  long long changeCount_ = 0;
  std::optional<Drag> drag_;
  std::optional<PoseIkTarget> temporaryTarget_;
  int drivenTarget_ = -1;
  std::vector<IkTargetReport> ikReports_;
};

}  // namespace kinema
