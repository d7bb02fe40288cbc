#include "editor/model/lattice_editing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "anim/scalar_property.h"
#include "editor/model/editor_state.h"
#include "editor/model/keying.h"
#include "editor/model/timeline.h"
#include "evaluation/scene_deformation.h"

namespace kinema {

namespace {

const Deformer* latticeAt(const Document& doc, int instance, int deformer) {
  const DeformerStack* stack = instance >= 0 ? doc.scene().deformerStack(static_cast<size_t>(instance)) : nullptr;
  if (!stack || deformer < 0 || deformer >= static_cast<int>(stack->deformers.size())) return nullptr;
  const Deformer& d = stack->deformers[deformer];
  return d.type == DeformerType::Lattice ? &d : nullptr;
}

int playedClip(const EditorState& state) { return state.hasMotion() ? state.clip : -1; }

// The edited lattice as shown at the playhead (its animated points), in its own space.
bool sampledLattice(const EditorState& state, Deformer& out) {
  if (!editedLattice(state)) return false;
  const std::vector<DeformerStack> stacks = sampleDeformerStacks(state.doc.scene(), playedClip(state), state.time);
  out = stacks[state.lattice.instance].deformers[state.lattice.deformer];
  return true;
}

const char* const kAxes[3] = {"x", "y", "z"};

std::string pointParameter(int point, int axis) { return "point." + std::to_string(point) + "." + kAxes[axis]; }

bool parameterAnimated(const EditorState& state, int joint, const std::string& property) {
  const int clip = playedClip(state);
  if (clip < 0) return false;
  for (const Channel& ch : state.doc.scene().clips[clip].channels)
    if (ch.target == ChannelTarget::Scalar && ch.joint == joint && ch.property == property && !ch.times.empty())
      return true;
  return false;
}

std::string pointsPhrase(size_t n) { return n == 1 ? "1 lattice point" : std::to_string(n) + " lattice points"; }

// Keys every axis of the selected points with `points` (the lattice's own space) at the
// playhead: one undo step.
std::string keyPoints(EditorState& state, const Deformer& lattice, const std::vector<glm::vec3>& points,
                      const std::string& label) {
  Document& doc = state.doc;
  const int joint = doc.scene().meshInstances[state.lattice.instance].joint;
  std::vector<std::pair<std::string, float>> values;
  for (int p : state.lattice.selected)
    for (int a = 0; a < 3; ++a)
      values.emplace_back(deformerParameterProperty(lattice.name, pointParameter(p, a)), points[p][a]);
  const std::string error = keyScalarProperties(doc, state.clip, joint, values, static_cast<float>(state.time),
                                                doc.autoKey.preferences, label);
  syncDocumentPlayhead(state);
  return error;
}

}  // namespace

const Deformer* editedLattice(const EditorState& state) {
  return latticeAt(state.doc, state.lattice.instance, state.lattice.deformer);
}

bool latticeToEdit(const EditorState& state, int& instance, int& deformer) {
  if (editedLattice(state)) {
    instance = state.lattice.instance;
    deformer = state.lattice.deformer;
    return true;
  }
  const Scene& scene = state.doc.scene();
  for (size_t i = 0; i < scene.deformers.size(); ++i)
    for (size_t k = 0; k < scene.deformers[i].deformers.size(); ++k)
      if (scene.deformers[i].deformers[k].type == DeformerType::Lattice) {
        instance = static_cast<int>(i);
        deformer = static_cast<int>(k);
        return true;
      }
  return false;
}

std::string enterLatticeEdit(EditorState& state, int instance, int deformer) {
  if (instance < 0 && !latticeToEdit(state, instance, deformer))
    return "Edit Lattice: add a lattice first (Properties > Deformers > Lattice)";
  if (!latticeAt(state.doc, instance, deformer)) return "Edit Lattice: that deformer is not a lattice";
  LatticeEditState& e = state.lattice;
  e = LatticeEditState{};
  e.active = true;
  e.instance = instance;
  e.deformer = deformer;
  return "";
}

void exitLatticeEdit(EditorState& state) {
  const int instance = state.lattice.instance, deformer = state.lattice.deformer;
  state.lattice = LatticeEditState{};
  state.lattice.instance = instance;  // stays the active lattice: Tab comes back to it
  state.lattice.deformer = deformer;
}

void keepLatticeEditValid(EditorState& state) {
  LatticeEditState& e = state.lattice;
  // A G whose move was dropped (the mode left, the points gone) ends with it.
  if (state.tool.mode == ModalTool::LatticeGrab && (!e.active || !e.moving)) state.tool = ToolState{};
  if (!e.active) return;
  const Deformer* d = editedLattice(state);
  if (!d) {
    exitLatticeEdit(state);
    if (state.tool.mode == ModalTool::LatticeGrab) state.tool = ToolState{};
    return;
  }
  const int count = d->lattice.pointCount();
  e.selected.erase(std::remove_if(e.selected.begin(), e.selected.end(), [&](int p) { return p < 0 || p >= count; }),
                   e.selected.end());
  if (e.hovered >= count) e.hovered = -1;
  if (e.moving && e.selected.empty()) {
    cancelLatticeMove(state);
    if (state.tool.mode == ModalTool::LatticeGrab) state.tool = ToolState{};
  }
}

std::vector<glm::vec3> latticeWorldPoints(const EditorState& state) {
  Deformer d;
  if (!state.lattice.active || !sampledLattice(state, d)) return {};
  const glm::mat4 frame = deformerFrame(d, &state.world());
  std::vector<glm::vec3> out;
  out.reserve(d.lattice.points.size());
  for (const glm::vec3& p : d.lattice.points) out.push_back(glm::vec3(frame * glm::vec4(p, 1.0f)));
  if (state.lattice.moving)
    for (int p : state.lattice.selected) out[p] += state.lattice.offset;
  return out;
}

std::vector<std::pair<int, int>> latticeEdges(const FfdLattice& lattice) {
  std::vector<std::pair<int, int>> edges;
  const int* n = lattice.counts;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const int here = lattice.index(i, j, k);
        if (i + 1 < n[0]) edges.emplace_back(here, lattice.index(i + 1, j, k));
        if (j + 1 < n[1]) edges.emplace_back(here, lattice.index(i, j + 1, k));
        if (k + 1 < n[2]) edges.emplace_back(here, lattice.index(i, j, k + 1));
      }
  return edges;
}

bool latticePointSelected(const LatticeEditState& edit, int point) {
  return std::binary_search(edit.selected.begin(), edit.selected.end(), point);
}

void clickLatticePoint(LatticeEditState& edit, int point, bool toggle) {
  std::vector<int>& s = edit.selected;
  if (!toggle) {
    s.clear();
    if (point >= 0) s.push_back(point);
    return;
  }
  if (point < 0) return;
  const auto at = std::lower_bound(s.begin(), s.end(), point);
  if (at != s.end() && *at == point) s.erase(at);
  else s.insert(at, point);
}

void boxSelectLatticePoints(LatticeEditState& edit, const std::vector<int>& points, BoxSelectMode mode) {
  std::vector<int> inside = points;
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  std::vector<int> out;
  switch (mode) {
    case BoxSelectMode::Replace: out = inside; break;
    case BoxSelectMode::Extend:
      std::set_union(edit.selected.begin(), edit.selected.end(), inside.begin(), inside.end(), std::back_inserter(out));
      break;
    case BoxSelectMode::Subtract:
      std::set_difference(edit.selected.begin(), edit.selected.end(), inside.begin(), inside.end(),
                          std::back_inserter(out));
      break;
  }
  edit.selected = std::move(out);
}

void selectAllLatticePoints(EditorState& state) {
  const Deformer* d = editedLattice(state);
  if (!state.lattice.active || !d) return;
  state.lattice.selected.clear();
  for (int p = 0; p < d->lattice.pointCount(); ++p) state.lattice.selected.push_back(p);
}

void selectNoLatticePoints(LatticeEditState& edit) { edit.selected.clear(); }

std::string beginLatticeMove(EditorState& state) {
  if (!state.lattice.active || !editedLattice(state)) return "Move: not in lattice edit mode";
  if (state.lattice.selected.empty()) return "Move: select lattice points first (click, box, or A)";
  if (state.doc.dragging()) return "finish the current drag first";
  state.lattice.moving = true;
  state.lattice.offset = glm::vec3(0.0f);
  return "";
}

void setLatticeMoveOffset(EditorState& state, const glm::vec3& offset) {
  if (state.lattice.moving && std::isfinite(offset.x) && std::isfinite(offset.y) && std::isfinite(offset.z))
    state.lattice.offset = offset;
}

void cancelLatticeMove(EditorState& state) {
  state.lattice.moving = false;
  state.lattice.offset = glm::vec3(0.0f);
}

std::string confirmLatticeMove(EditorState& state) {
  LatticeEditState& e = state.lattice;
  const glm::vec3 offset = e.offset;
  const bool wasMoving = e.moving;
  cancelLatticeMove(state);
  Deformer d;
  if (!wasMoving || e.selected.empty() || !sampledLattice(state, d)) return "";
  if (offset == glm::vec3(0.0f)) return "";
  // The world offset in the lattice's own space (its frame is rigid: rotate back).
  const glm::mat4 frame = deformerFrame(d, &state.world());
  const glm::vec3 local = glm::transpose(glm::mat3(frame)) * offset;
  std::vector<glm::vec3> points = d.lattice.points;
  for (int p : e.selected) points[p] += local;
  Document& doc = state.doc;
  const int joint = doc.scene().meshInstances[e.instance].joint;
  bool animated = false;
  for (int p : e.selected)
    for (int a = 0; a < 3 && !animated; ++a)
      animated = parameterAnimated(state, joint, deformerParameterProperty(d.name, pointParameter(p, a)));
  const std::string label = "Move " + pointsPhrase(e.selected.size()) + " of " + d.name;
  char moved[64];
  std::snprintf(moved, sizeof moved, " by %.3f m", glm::length(offset));
  if (animated || doc.autoKey.enabled) {
    const std::string error = keyPoints(state, d, points, label);
    return error.empty() ? label + moved + " (keyed on frame " + std::to_string(currentFrame(state)) + ")" : error;
  }
  const int instance = e.instance, deformer = e.deformer;
  const std::vector<int> selected = e.selected;
  const std::string error = doc.editMeshes(label, [&](Scene& s) {
    FfdLattice& lattice = s.deformers[instance].deformers[deformer].lattice;
    for (int p : selected) lattice.points[p] = points[p];
    return std::string();
  });
  return error.empty() ? label + moved : error;
}

std::string keyLatticePoints(EditorState& state) {
  Deformer d;
  if (!state.lattice.active || !sampledLattice(state, d)) return "Insert Keyframe: not in lattice edit mode";
  if (state.lattice.selected.empty()) return "Insert Keyframe: select lattice points first";
  const std::string label = "Insert keys on " + pointsPhrase(state.lattice.selected.size()) + " of " + d.name;
  const std::string error = keyPoints(state, d, d.lattice.points, label);
  return error.empty() ? "Inserted keys on " + pointsPhrase(state.lattice.selected.size()) + " of " + d.name +
                             " on frame " + std::to_string(currentFrame(state))
                       : error;
}

void previewLatticeMove(const EditorState& state, const std::vector<glm::mat4>& world, std::vector<DeformerStack>& stacks) {
  const LatticeEditState& e = state.lattice;
  if (!e.active || !e.moving || e.instance < 0 || e.instance >= static_cast<int>(stacks.size())) return;
  std::vector<Deformer>& list = stacks[e.instance].deformers;
  if (e.deformer < 0 || e.deformer >= static_cast<int>(list.size()) || list[e.deformer].type != DeformerType::Lattice)
    return;
  Deformer& d = list[e.deformer];
  const glm::vec3 local = glm::transpose(glm::mat3(deformerFrame(d, &world))) * e.offset;
  for (int p : e.selected)
    if (p >= 0 && p < static_cast<int>(d.lattice.points.size())) d.lattice.points[p] += local;
}

}  // namespace kinema
