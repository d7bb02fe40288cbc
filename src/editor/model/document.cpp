#include "editor/model/document.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <set>

#include "core/forward_kinematics.h"
#include "ik/ik_posing_job.h"
#include "editor/model/keying.h"

namespace kinema {

namespace {

bool sameBits(const Transform& a, const Transform& b) { return std::memcmp(&a, &b, sizeof(Transform)) == 0; }

// JointLimit holds only 4-byte members (no padding), so its bytes are its value.
static_assert(sizeof(JointLimit) == 64, "JointLimit layout changed: compare it field by field");
bool sameBits(const JointLimit& a, const JointLimit& b) { return std::memcmp(&a, &b, sizeof(JointLimit)) == 0; }

bool sameLimits(const std::vector<JointLimit>& a, const std::vector<JointLimit>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!sameBits(a[i], b[i])) return false;
  return true;
}

bool sameSimulation(const SimulationSettings& a, const SimulationSettings& b) {
  return a.springChains == b.springChains && a.ragdolls == b.ragdolls && a.crowds == b.crowds &&
         a.particles == b.particles;
}

bool sameTargets(const std::vector<PoseIkTarget>& a, const std::vector<PoseIkTarget>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!sameBits(a[i], b[i])) return false;
  return true;
}

template <typename T>
bool sameBitsArray(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameChannel(const Channel& a, const Channel& b) {
  return a.joint == b.joint && a.target == b.target && a.interpolation == b.interpolation &&
         a.eulerOrder == b.eulerOrder && a.property == b.property && sameBitsArray(a.times, b.times) &&
         sameBitsArray(a.values, b.values) && a.keys == b.keys && a.modifiers == b.modifiers;
}

bool sameClip(const Clip& a, const Clip& b) {
  if (a.name != b.name || a.frameTime != b.frameTime || a.loop != b.loop || a.hasRange != b.hasRange ||
      a.rangeStart != b.rangeStart || a.rangeEnd != b.rangeEnd || a.channels.size() != b.channels.size() ||
      a.contacts != b.contacts || a.sourceMap != b.sourceMap)
    return false;
  for (size_t i = 0; i < a.channels.size(); ++i)
    if (!sameChannel(a.channels[i], b.channels[i])) return false;
  return true;
}

// Process-wide, so that revisions of different documents differ.
std::atomic<long long> nextPoseRevision{1};

}  // namespace

Document::Document() {
  poseChanged();
  clipListRevision_ = nextPoseRevision++;
}

void Document::poseChanged() { poseRevision_ = nextPoseRevision++; }

void Document::noteClipList(int activeBefore, size_t countBefore) {
  if (activeBefore != activeClip_ || countBefore != scene_.clips.size()) clipListRevision_ = nextPoseRevision++;
}

Document::Document(Scene scene, std::string path) : scene_(std::move(scene)), path_(std::move(path)) {
  poseChanged();
  clipListRevision_ = nextPoseRevision++;
  const int n = scene_.skeleton.size();
  pose_ = scene_.pose.size() == n && scene_.pose.validate(scene_.skeleton).empty() ? scene_.pose
                                                                                 : Pose::rest(scene_.skeleton);
  scene_.pose = Pose{};  // the document's pose_ is the one truth
  savedPlayhead_ = scene_.playhead;
  if (scene_.playhead) {
    playheadTime_ = scene_.playhead->time;
    if (scene_.playhead->clip >= 0 && scene_.playhead->clip < static_cast<int>(scene_.clips.size()))
      activeClip_ = scene_.playhead->clip;
  }
  scene_.playhead.reset();  // activeClip_ and playheadTime_ are what the document saves
  if (!scene_.ik.limits.empty()) scene_.ik.limits.resize(n);
  for (size_t i = 0; i < scene_.ik.targets.size(); ++i) {
    PoseIkTarget p;
    p.target = scene_.ik.targets[i];
    if (i < scene_.ik.targetOptions.size()) {
      const IkTargetOptions& o = scene_.ik.targetOptions[i];
      p.solver = o.solver;
      p.chainLength = o.chainLength;
      p.pinned = o.pinned;
      p.active = o.active;
    }
    targets_.push_back(p);
  }
  scene_.ik.targets.clear();  // targets_ hold them with their editor settings
  scene_.ik.targetOptions.clear();
  loadedNames_ = scene_.skeleton.names;
  for (const MeshInstance& m : scene_.meshInstances) skinning_.push_back(m.skinning);
}

void Document::syncSkinning() {
  for (size_t i = 0; i < scene_.meshInstances.size() && i < skinning_.size(); ++i)
    scene_.meshInstances[i].skinning = skinning_[i];
}

const std::vector<glm::mat4>& Document::worldTransforms() const {
  if (worldRevision_ != poseRevision_) {
    computeWorld(scene_.skeleton, pose_, world_);
    worldRevision_ = poseRevision_;
    ++worldEvaluations_;
  }
  return world_;
}

IkRig Document::savedRig() const {
  IkRig rig = scene_.ik;
  // The chain length is saved both as the root it resolves to (for other readers) and as
  // itself, with the solver, pinned and active flags.
  for (const PoseIkTarget& t : targets_) {
    rig.targets.push_back(t.resolved(scene_.skeleton));
    rig.targetOptions.push_back({t.solver, t.chainLength, t.pinned, t.active});
  }
  return rig;
}

Scene Document::sceneForSaving() const {
  Scene s = scene_;
  s.pose = pose_;
  if (playheadTime_ || activeClip_ != 0) s.playhead = playhead();
  s.ik = savedRig();
  // glTF scenes report and export the file's node names: a renamed joint renames its node.
  for (int j = 0; j < s.skeleton.size() && j < static_cast<int>(s.nodeOfJoint.size()); ++j) {
    const int node = s.nodeOfJoint[j];
    if (node >= 0 && node < static_cast<int>(s.nodeNames.size()) && j < static_cast<int>(loadedNames_.size()) &&
        s.skeleton.names[j] != loadedNames_[j])
      s.nodeNames[node] = s.skeleton.names[j];
  }
  return s;
}

bool Document::dirty() const {
  return drag_.has_value() || !savedReachable_ || history_.dropped() + history_.position() != savedAt_;
}

void Document::markSaved() {
  savedAt_ = history_.dropped() + history_.position();
  savedReachable_ = true;
}

void Document::markModified() { savedReachable_ = false; }

Document::Snapshot Document::capture() const {
  return Snapshot{scene_.skeleton.names, pose_.local, scene_.ik.limits, targets_, skinning_, scene_.clips, activeClip_,
                  scene_.simulation, scene_.frameRate};
}

void Document::restore(const Snapshot& s) {
  scene_.skeleton.names = s.names;
  pose_.local = s.pose;
  poseChanged();
  scene_.ik.limits = s.limits;
  targets_ = s.targets;
  skinning_ = s.skinning;
  scene_.clips = s.clips;
  activeClip_ = s.activeClip;
  scene_.simulation = s.simulation;
  scene_.frameRate = s.frameRate;
  syncSkinning();
}

DocumentEdit Document::editView() {
  return DocumentEdit{scene_.skeleton, scene_.skeleton.names, pose_, scene_.ik.limits, targets_, skinning_,
                      scene_.clips, activeClip_, scene_.simulation, scene_.frameRate};
}

std::string Document::runChange(const std::function<std::string(DocumentEdit&)>& change, bool /*driven*/) {
  const std::vector<Transform> poseBefore = pose_.local;  // what auto-key compares with
  DocumentEdit view = editView();
  poseChanged();  // the change may set the pose (an error restores it, another change)
  std::string error = change(view);
  if (!error.empty()) return error;
  // The change function is ours (pose_edits.cpp...), but a window may pass its own: keep
  // the document's invariants whatever it did.
  const int n = scene_.skeleton.size();
  if (pose_.size() != n || static_cast<int>(scene_.skeleton.names.size()) != n)
    return "an edit may not add or remove joints";
  if (!scene_.ik.limits.empty() && static_cast<int>(scene_.ik.limits.size()) != n)
    return "joint limits must be empty or one per joint";
  std::set<std::string> names;
  for (const std::string& name : scene_.skeleton.names) {
    if (name.empty()) return "a joint name may not be empty";
    if (!names.insert(name).second) return "two joints may not share the name '" + name + "'";
  }
  for (size_t i = 0; i < targets_.size(); ++i) {
    const std::string bad = targets_[i].validate(scene_.skeleton);
    if (!bad.empty()) return "IK target " + std::to_string(i) + ": " + bad;
  }
  if (skinning_.size() != scene_.meshInstances.size()) return "an edit may not add or remove mesh instances";
  for (size_t c = 0; c < scene_.clips.size(); ++c) {
    const std::string bad = scene_.clips[c].validate(scene_.skeleton);
    if (!bad.empty()) return "clip " + std::to_string(c) + ": " + bad;
  }
  if (!scene_.simulation.empty())
    if (std::string bad = scene_.simulation.validate(scene_.skeleton); !bad.empty()) return "simulation: " + bad;
  if (!(scene_.frameRate >= kMinFrameRate && scene_.frameRate <= kMaxFrameRate))
    return "the frame rate must be 1 to 1000 frames per second";
  // A change that removed clips without choosing another leaves the last one active.
  activeClip_ = std::clamp(activeClip_, 0, std::max(static_cast<int>(scene_.clips.size()) - 1, 0));
  syncSkinning();
  if (autoSolveIk) {
    IkPosingInput in;
    in.skeleton = &scene_.skeleton;
    in.limits = &scene_.ik.limits;
    in.targets = &targets_;
    in.temporary = temporaryTarget_ ? &*temporaryTarget_ : nullptr;
    in.driven = drivenTarget_ >= 0 && drivenTarget_ < static_cast<int>(targets_.size()) ? drivenTarget_ : -1;
    in.settings = ikSettings;
    in.settings.trace = nullptr;
    ikReports_ = solveIkPosing(in, pose_);
  }
  if (autoKey.enabled) {
    std::vector<int> changed;
    for (int j = 0; j < n; ++j)
      if (!sameBits(poseBefore[j], pose_.local[j])) changed.push_back(j);
    ScenePlayhead at = playhead();
    if (keyJoints(scene_.clips, at.clip, scene_.skeleton, pose_, changed, static_cast<float>(at.time),
                  autoKey.preferences, scene_.frameGrid(-1)) > 0) {
      activeClip_ = at.clip;  // a new "Action" when the scene had no clip
      const int clip = at.clip;
      const std::string bad = scene_.clips[clip].validate(scene_.skeleton);
      if (!bad.empty()) return "auto-key: clip " + std::to_string(clip) + ": " + bad;
    }
  }
  return {};
}

EditRecord Document::diff(const std::string& label, const Snapshot& before) const {
  EditRecord r;
  r.label = label;
  for (int i = 0; i < pose_.size(); ++i)
    if (!sameBits(before.pose[i], pose_.local[i])) r.pose.push_back({i, before.pose[i], pose_.local[i]});
  for (size_t i = 0; i < before.names.size(); ++i)
    if (before.names[i] != scene_.skeleton.names[i])
      r.names.push_back({static_cast<int>(i), before.names[i], scene_.skeleton.names[i]});
  if (!sameLimits(before.limits, scene_.ik.limits)) {
    r.limitsChanged = true;
    r.limitsBefore = before.limits;
    r.limitsAfter = scene_.ik.limits;
  }
  if (before.skinning != skinning_) {
    r.skinningChanged = true;
    r.skinningBefore = before.skinning;
    r.skinningAfter = skinning_;
  }
  if (!sameTargets(before.targets, targets_)) {
    r.targetsChanged = true;
    r.targetsBefore = before.targets;
    r.targetsAfter = targets_;
  }
  const size_t clipCount = std::max(before.clips.size(), scene_.clips.size());
  for (size_t c = 0; c < clipCount; ++c) {
    const Clip* was = c < before.clips.size() ? &before.clips[c] : nullptr;
    const Clip* now = c < scene_.clips.size() ? &scene_.clips[c] : nullptr;
    if (was && now && sameClip(*was, *now)) continue;
    EditRecord::ClipChange change;
    change.clip = static_cast<int>(c);
    if (was) change.before = std::make_shared<const Clip>(*was);
    if (now) change.after = std::make_shared<const Clip>(*now);
    r.clips.push_back(std::move(change));
  }
  r.clipCountBefore = static_cast<int>(before.clips.size());
  r.clipCountAfter = static_cast<int>(scene_.clips.size());
  if (!sameSimulation(before.simulation, scene_.simulation)) {
    r.simulationChanged = true;
    r.simulationBefore = std::make_shared<const SimulationSettings>(before.simulation);
    r.simulationAfter = std::make_shared<const SimulationSettings>(scene_.simulation);
  }
  if (before.frameRate != scene_.frameRate) {
    r.frameRateChanged = true;
    r.frameRateBefore = before.frameRate;
    r.frameRateAfter = scene_.frameRate;
  }
  if (before.activeClip != activeClip_) {
    r.activeClipChanged = true;
    r.activeClipBefore = before.activeClip;
    r.activeClipAfter = activeClip_;
  }
  return r;
}

void Document::pushRecord(EditRecord record) {
  // A saved state in the redo tail that this edit drops can never come back.
  if (savedAt_ > history_.dropped() + history_.position()) savedReachable_ = false;
  history_.push(std::move(record));
  if (savedAt_ < history_.dropped()) savedReachable_ = false;
}

std::string Document::edit(const std::string& label, const std::function<std::string(DocumentEdit&)>& change) {
  if (drag_) return "finish the current drag first";
  const Snapshot before = capture();
  const std::string error = runChange(change, false);
  if (!error.empty()) {
    restore(before);
    return error;
  }
  EditRecord record = diff(label, before);
  noteClipList(before.activeClip, before.clips.size());
  if (!record.empty()) {
    pushRecord(std::move(record));
    ++changeCount_;
  }
  return {};
}

std::string Document::editMeshes(const std::string& label, const std::function<std::string(Scene&)>& change) {
  if (drag_) return "finish the current drag first";
  Scene scratch = scene_;
  const std::string error = change(scratch);
  if (!error.empty()) return error;
  if (scratch.meshInstances.size() != scene_.meshInstances.size())
    return "an edit may not add or remove mesh instances";
  if (scratch.deformers.size() > scratch.meshInstances.size()) return "a deformer stack for a missing mesh instance";
  for (size_t i = 0; i < scratch.deformers.size(); ++i) {
    const int mesh = scratch.meshInstances[i].mesh;
    if (mesh < 0 || mesh >= static_cast<int>(scratch.meshes.size())) continue;
    if (std::string e = scratch.deformers[i].validate(scratch.meshes[mesh], scratch.skeleton.size()); !e.empty())
      return "mesh instance " + std::to_string(i) + ": " + e;
  }
  auto before =
      std::make_shared<SceneMeshes>(SceneMeshes{scene_.meshes, scene_.skins, scene_.meshInstances, scene_.deformers});
  auto after = std::make_shared<SceneMeshes>(SceneMeshes{std::move(scratch.meshes), std::move(scratch.skins),
                                                         std::move(scratch.meshInstances), std::move(scratch.deformers)});
  EditRecord record;
  record.label = label;
  record.meshesBefore = before;
  record.meshesAfter = after;
  apply(record, true);
  pushRecord(std::move(record));
  return {};
}

std::string Document::beginDrag(const std::string& label) {
  if (drag_) return "a drag is already in progress";
  drag_ = Drag{label, capture()};
  return {};
}

std::string Document::updateDrag(const std::function<std::string(DocumentEdit&)>& change) {
  if (!drag_) return "no drag in progress";
  const int active = activeClip_;
  const size_t count = scene_.clips.size();
  restore(drag_->start);
  const std::string error = runChange(change, true);
  if (!error.empty()) restore(drag_->start);
  noteClipList(active, count);
  ++changeCount_;
  return error;
}

void Document::commitDrag() {
  if (!drag_) return;
  EditRecord record = diff(drag_->label, drag_->start);
  drag_.reset();
  temporaryTarget_.reset();
  drivenTarget_ = -1;
  if (!record.empty()) pushRecord(std::move(record));
  ++changeCount_;
}

void Document::cancelDrag() {
  if (!drag_) return;
  const int active = activeClip_;
  const size_t count = scene_.clips.size();
  restore(drag_->start);
  noteClipList(active, count);
  drag_.reset();
  temporaryTarget_.reset();
  drivenTarget_ = -1;
  ++changeCount_;
}

void Document::apply(const EditRecord& r, bool forward) {
  for (const EditRecord::JointChange& c : r.pose) pose_.local[c.joint] = forward ? c.after : c.before;
  if (!r.pose.empty()) poseChanged();
  for (const EditRecord::NameChange& c : r.names) scene_.skeleton.names[c.joint] = forward ? c.after : c.before;
  if (r.limitsChanged) scene_.ik.limits = forward ? r.limitsAfter : r.limitsBefore;
  if (r.targetsChanged) targets_ = forward ? r.targetsAfter : r.targetsBefore;
  if (r.simulationChanged) scene_.simulation = forward ? *r.simulationAfter : *r.simulationBefore;
  if (r.frameRateChanged) scene_.frameRate = forward ? r.frameRateAfter : r.frameRateBefore;
  if (r.meshesBefore && r.meshesAfter) {
    const SceneMeshes& m = forward ? *r.meshesAfter : *r.meshesBefore;
    scene_.meshes = m.meshes;
    scene_.skins = m.skins;
    scene_.meshInstances = m.instances;
    scene_.deformers = m.deformers;
    skinning_.clear();
    for (const MeshInstance& i : scene_.meshInstances) skinning_.push_back(i.skinning);
    ++meshRevision_;
  }
  if (r.skinningChanged) {
    skinning_ = forward ? r.skinningAfter : r.skinningBefore;
    syncSkinning();
  }
  const int activeBefore = activeClip_;
  const size_t countBefore = scene_.clips.size();
  if (!r.clips.empty()) {
    scene_.clips.resize(static_cast<size_t>(forward ? r.clipCountAfter : r.clipCountBefore));
    for (const EditRecord::ClipChange& c : r.clips) {
      const std::shared_ptr<const Clip>& value = forward ? c.after : c.before;
      if (value) scene_.clips[c.clip] = *value;
    }
  }
  if (r.activeClipChanged) activeClip_ = forward ? r.activeClipAfter : r.activeClipBefore;
  noteClipList(activeBefore, countBefore);
  ikReports_.clear();
  ++changeCount_;
}

bool Document::setAnimatedPose(const Pose& pose) {
  if (drag_ || pose.size() != scene_.skeleton.size() || !pose.validate(scene_.skeleton).empty()) return false;
  // Playback and the second evaluation of a frame set the pose they already set: no change.
  if (sameBitsArray(pose.local, pose_.local)) return true;
  pose_ = pose;
  poseChanged();
  ikReports_.clear();
  return true;
}

bool Document::canUndo() const { return !drag_ && history_.canUndo(); }
bool Document::canRedo() const { return !drag_ && history_.canRedo(); }

bool Document::undo() {
  if (drag_) return false;
  const EditRecord* r = history_.stepBack();
  if (!r) return false;
  apply(*r, false);
  return true;
}

bool Document::redo() {
  if (drag_) return false;
  const EditRecord* r = history_.stepForward();
  if (!r) return false;
  apply(*r, true);
  return true;
}

std::vector<std::string> Document::historyLabels() const {
  std::vector<std::string> labels;
  for (const EditRecord& r : history_.entries()) labels.push_back(r.label);
  return labels;
}

bool Document::jumpToHistory(int position) {
  if (drag_ || position < 0 || position > history_.size()) return false;
  while (history_.position() > position) undo();
  while (history_.position() < position) redo();
  return true;
}

}  // namespace kinema
