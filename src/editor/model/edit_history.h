#pragma once
#include <memory>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/mesh.h"
#include "core/transform.h"
#include "ik/pose_ik_target.h"
#include "deform/deformer_stack.h"
#include "ik/joint_limits.h"
#include "sim/simulation_settings.h"

namespace kinema {

// What one undo step changed: before/after copies of exactly what the edit touched
// (simple and exact: undo/redo restore the stored values bit for bit).
// The scene's mesh data an edit may replace as a whole (binding a mesh to the skeleton).
struct SceneMeshes {
  std::vector<Mesh> meshes;
  std::vector<Skin> skins;
  std::vector<MeshInstance> instances;
  std::vector<DeformerStack> deformers;  // Scene::deformers: empty or one stack per instance
};

struct EditRecord {
  struct JointChange {
    int joint = -1;
    Transform before, after;
  };
  struct NameChange {
    int joint = -1;
    std::string before, after;
  };
  std::string label;
  std::vector<JointChange> pose;
  std::vector<NameChange> names;
  bool limitsChanged = false;
  std::vector<JointLimit> limitsBefore, limitsAfter;
  bool targetsChanged = false;
  std::vector<PoseIkTarget> targetsBefore, targetsAfter;
  bool skinningChanged = false;  // the mesh instances' skinning methods
  std::vector<SkinningMethod> skinningBefore, skinningAfter;
  std::shared_ptr<const SceneMeshes> meshesBefore, meshesAfter;  // both or neither
  // Clips (keys, ranges, names): each clip that differs, as a whole before and after
  // (nullptr where the clip does not exist on that side), and the clip counts.
  struct ClipChange {
    int clip = -1;
    std::shared_ptr<const Clip> before, after;
  };
  std::vector<ClipChange> clips;
  int clipCountBefore = 0, clipCountAfter = 0;
  // The active clip (Document::activeClip) before and after, when the edit chose another.
  bool activeClipChanged = false;
  int activeClipBefore = 0, activeClipAfter = 0;
  // Dynamic chains and ragdolls (the scene's simulation settings), whole, when they changed.
  bool simulationChanged = false;
  std::shared_ptr<const SimulationSettings> simulationBefore, simulationAfter;
  // The document's frame rate (Scene::frameRate), when it changed.
  bool frameRateChanged = false;
  double frameRateBefore = 0.0, frameRateAfter = 0.0;

  bool empty() const { return pose.empty() && names.empty() && !limitsChanged && !targetsChanged && !skinningChanged &&
                        !meshesBefore && clips.empty() && !activeClipChanged &&
                        !simulationChanged && !frameRateChanged; }
};

// A linear undo history: entries [0, position) are applied, [position, size) can be redone.
// A new edit drops the redo tail. At most `capacity` entries; the oldest go first.
class EditHistory {
 public:
  explicit EditHistory(int capacity = 500) : capacity_(capacity) {}

  void push(EditRecord record);
  bool canUndo() const { return position_ > 0; }
  bool canRedo() const { return position_ < size(); }
  // The record to revert / re-apply next (moves the position); nullptr when none.
  const EditRecord* stepBack();
  const EditRecord* stepForward();

  int size() const { return static_cast<int>(entries_.size()); }
  int position() const { return position_; }  // how many entries are applied
  const std::vector<EditRecord>& entries() const { return entries_; }
  // Counts entries dropped from the front (by the capacity): a saved position older than
  // that can never be reached again.
  long long dropped() const { return dropped_; }
  void clear();

 private:
  std::vector<EditRecord> entries_;
  int position_ = 0;
  int capacity_;
  long long dropped_ = 0;
};

}  // namespace kinema
