#include "editor/model/dope_sheet.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "editor/model/document.h"
#include "editor/model/edit_labels.h"

namespace kinema {

namespace {

// Sorted times merged within the tolerance (the first of a group stands for it).
std::vector<float> mergedTimes(std::vector<float> times) {
  std::sort(times.begin(), times.end());
  std::vector<float> out;
  for (float t : times)
    if (out.empty() || !sameKeyTime(out.back(), t)) out.push_back(t);
  return out;
}

// Whether key time t of `joint` belongs to one of the columns (sorted by joint, then time).
bool inColumns(const std::vector<KeyColumn>& columns, int joint, float t) {
  auto it = std::lower_bound(columns.begin(), columns.end(), KeyColumn{joint, t - 2 * kKeyTimeTolerance});
  for (; it != columns.end() && it->joint == joint && it->time <= t + 2 * kKeyTimeTolerance; ++it)
    if (sameKeyTime(it->time, t)) return true;
  return false;
}

std::vector<KeyColumn> sortedUnique(std::vector<KeyColumn> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

struct TakenKey {
  float time;
  glm::vec4 value;
  KeySettings settings;
};

// Removes the keys of `ch` in the columns and returns them (time order).
std::vector<TakenKey> takeKeys(Channel& ch, const std::vector<KeyColumn>& columns) {
  std::vector<TakenKey> taken;
  for (int k = ch.keyCount() - 1; k >= 0; --k) {
    if (!inColumns(columns, ch.joint, ch.times[k])) continue;
    taken.push_back({ch.times[k], ch.values[k], ch.settings(k)});
    deleteKey(ch, k);
  }
  std::reverse(taken.begin(), taken.end());
  return taken;
}

void removeEmptyChannels(Clip& clip) {
  clip.channels.erase(std::remove_if(clip.channels.begin(), clip.channels.end(),
                                     [](const Channel& c) { return c.times.empty(); }),
                      clip.channels.end());
}

}  // namespace

std::vector<DopeSheetRow> dopeSheetRows(const Clip& clip) {
  std::map<int, std::vector<float>> byJoint;
  for (const Channel& ch : clip.channels)
    if (ch.joint >= 0 && !ch.times.empty()) byJoint[ch.joint].insert(byJoint[ch.joint].end(), ch.times.begin(), ch.times.end());
  std::vector<DopeSheetRow> rows(1);
  std::vector<float> all;
  for (auto& [joint, times] : byJoint) {
    rows.push_back({joint, mergedTimes(times)});
    all.insert(all.end(), rows.back().times.begin(), rows.back().times.end());
  }
  rows[0].times = mergedTimes(all);
  return rows;
}

std::vector<KeyColumn> allKeyColumns(const Clip& clip) {
  std::vector<KeyColumn> out;
  const std::vector<DopeSheetRow> rows = dopeSheetRows(clip);
  for (size_t r = 1; r < rows.size(); ++r)
    for (float t : rows[r].times) out.push_back({rows[r].joint, t});
  return out;
}

std::vector<KeyColumn> columnsOfCell(const std::vector<DopeSheetRow>& rows, int row, float time) {
  std::vector<KeyColumn> out;
  if (row < 0 || row >= static_cast<int>(rows.size())) return out;
  for (size_t r = 1; r < rows.size(); ++r) {
    if (row != 0 && static_cast<int>(r) != row) continue;
    const std::vector<float>& times = rows[r].times;  // sorted: look near `time` only
    for (auto it = std::lower_bound(times.begin(), times.end(), time - 2 * kKeyTimeTolerance);
         it != times.end() && *it <= time + 2 * kKeyTimeTolerance; ++it)
      if (sameKeyTime(*it, time)) out.push_back({rows[r].joint, *it});
  }
  return out;
}

std::vector<KeyColumn> columnsInBox(const FrameGrid& grid, const std::vector<DopeSheetRow>& rows, double frameA,
                                    double frameB, int rowA, int rowB) {
  // Edges included, with a little slack for key times that are frames in float seconds.
  const double f0 = std::min(frameA, frameB) - 1e-4, f1 = std::max(frameA, frameB) + 1e-4;
  const int r0 = std::max(std::min(rowA, rowB), 0), r1 = std::min(std::max(rowA, rowB), static_cast<int>(rows.size()) - 1);
  std::vector<KeyColumn> out;
  for (size_t r = 1; r < rows.size(); ++r) {
    const bool inRows = (static_cast<int>(r) >= r0 && static_cast<int>(r) <= r1) || (r0 == 0 && r1 >= 0);
    if (!inRows) continue;
    for (float t : rows[r].times) {
      const double f = grid.timeToFrame(t);
      if (f >= f0 && f <= f1) out.push_back({rows[r].joint, t});
    }
  }
  return sortedUnique(out);
}

// ---- selection ----

bool KeyColumnSelection::contains(const KeyColumn& c) const { return std::binary_search(columns_.begin(), columns_.end(), c); }

bool KeyColumnSelection::containsAll(const std::vector<KeyColumn>& cells) const {
  if (cells.empty()) return false;
  for (const KeyColumn& c : cells)
    if (!contains(c)) return false;
  return true;
}

void KeyColumnSelection::set(std::vector<KeyColumn> columns) { columns_ = sortedUnique(std::move(columns)); }

void KeyColumnSelection::click(const std::vector<KeyColumn>& cell, bool extend) {
  if (!extend) return set(cell);
  if (containsAll(cell)) {
    box(cell, BoxSelectMode::Subtract);
  } else {
    box(cell, BoxSelectMode::Extend);
  }
}

void KeyColumnSelection::box(const std::vector<KeyColumn>& inside, BoxSelectMode mode) {
  if (mode == BoxSelectMode::Replace) return set(inside);
  if (mode == BoxSelectMode::Extend) {
    std::vector<KeyColumn> all = columns_;
    all.insert(all.end(), inside.begin(), inside.end());
    return set(std::move(all));
  }
  const std::vector<KeyColumn> drop = sortedUnique(inside);
  std::vector<KeyColumn> kept;
  std::set_difference(columns_.begin(), columns_.end(), drop.begin(), drop.end(), std::back_inserter(kept));
  columns_ = std::move(kept);
}

void KeyColumnSelection::prune(const Clip& clip) { prune(dopeSheetRows(clip)); }

void KeyColumnSelection::prune(const std::vector<DopeSheetRow>& rows) {
  if (columns_.empty()) return;
  // Each selected column is matched to the clip's column within the tolerance (its time as
  // the rows show it), or dropped.
  std::vector<KeyColumn> all;
  for (size_t r = 1; r < rows.size(); ++r)
    for (float t : rows[r].times) all.push_back({rows[r].joint, t});
  std::vector<KeyColumn> kept;
  for (const KeyColumn& c : columns_) {
    auto it = std::lower_bound(all.begin(), all.end(), KeyColumn{c.joint, c.time - 2 * kKeyTimeTolerance});
    for (; it != all.end() && it->joint == c.joint && it->time <= c.time + 2 * kKeyTimeTolerance; ++it)
      if (sameKeyTime(it->time, c.time)) {
        kept.push_back(*it);
        break;
      }
  }
  set(std::move(kept));
}

// ---- view ----

int DopeSheetView::rowAt(float py) const {
  return firstRow + static_cast<int>(std::floor((py - y) / rowHeight));
}

void DopeSheetView::zoomAt(double px, double factor) {
  const double f = xToFrame(px);
  pixelsPerFrame = std::clamp(pixelsPerFrame * factor, 2.0, 200.0);
  firstFrame = f - (px - x) / pixelsPerFrame;
}

void DopeSheetView::frameRange(double first, double last) {
  const double span = std::max(last - first, 1.0) + 2.0;  // a frame of margin each side
  pixelsPerFrame = std::clamp(width / span, 2.0, 200.0);
  firstFrame = first - 1.0;
}

bool hitKeyColumn(const std::vector<DopeSheetRow>& rows, const DopeSheetView& view, const FrameGrid& grid, glm::vec2 p,
                  float radius, int& row, float& time) {
  const int r = view.rowAt(p.y);
  if (r < 0 || r >= static_cast<int>(rows.size()) || p.y < view.y || p.x < view.x) return false;
  double best = radius;
  bool found = false;
  for (float t : rows[r].times) {
    const double d = std::abs(view.frameToX(grid.timeToFrame(t)) - p.x);
    if (d <= best) {
      best = d;
      row = r;
      time = t;
      found = true;
    }
  }
  return found;
}

// ---- clip edits ----

void moveKeyColumns(Clip& clip, const FrameGrid& grid, const std::vector<KeyColumn>& columnsIn, double frameOffset,
                    std::vector<KeyColumn>* moved) {
  const std::vector<KeyColumn> columns = sortedUnique(columnsIn);
  std::vector<KeyColumn> out;
  const auto target = [&](float t) {
    return grid.frameToTime(std::llround(grid.timeToFrame(t) + frameOffset));
  };
  for (Channel& ch : clip.channels) {
    if (ch.joint < 0) continue;
    const bool perKey = !ch.keys.empty();
    const std::vector<TakenKey> taken = takeKeys(ch, columns);  // all out first
    for (const TakenKey& k : taken) {
      const float t = target(k.time);  // onto a staying key: insertKey replaces it
      if (perKey) insertKey(ch, t, k.value, k.settings);
      else insertKey(ch, t, k.value);
    }
  }
  // The columns at their new times, as the rows will show them.
  if (moved) {
    for (const KeyColumn& c : columns) out.push_back({c.joint, target(c.time)});
    KeyColumnSelection s;
    s.set(out);
    s.prune(clip);
    *moved = s.columns();
  }
}

void deleteKeyColumns(Clip& clip, const std::vector<KeyColumn>& columnsIn) {
  const std::vector<KeyColumn> columns = sortedUnique(columnsIn);
  for (Channel& ch : clip.channels)
    if (ch.joint >= 0) takeKeys(ch, columns);
  removeEmptyChannels(clip);
}

KeyClipboard copyKeyColumns(const Clip& clip, const FrameGrid& grid, const std::vector<KeyColumn>& columnsIn) {
  const std::vector<KeyColumn> columns = sortedUnique(columnsIn);
  KeyClipboard out;
  double first = 0.0;
  for (const Channel& ch : clip.channels) {
    if (ch.joint < 0) continue;
    for (int k = 0; k < ch.keyCount(); ++k) {
      if (!inColumns(columns, ch.joint, ch.times[k])) continue;
      CopiedKey c;
      c.joint = ch.joint;
      c.frameOffset = grid.timeToFrame(ch.times[k]);
      c.target = ch.target;
      c.property = ch.property;
      c.eulerOrder = ch.eulerOrder;
      c.channelInterpolation = ch.interpolation;
      c.value = ch.values[k];
      c.settings = ch.settings(k);
      first = out.keys.empty() ? c.frameOffset : std::min(first, c.frameOffset);
      out.keys.push_back(c);
    }
  }
  for (CopiedKey& c : out.keys) c.frameOffset -= first;
  return out;
}

std::string pasteKeys(Clip& clip, const FrameGrid& grid, const Skeleton& skeleton, const KeyClipboard& clipboard, long long frame,
                      const std::vector<int>& ontoJoints, std::vector<KeyColumn>* pasted) {
  if (clipboard.empty()) return "Paste keys: copy keys first (Ctrl+C in the dope sheet)";
  std::set<int> copiedSet;
  for (const CopiedKey& c : clipboard.keys) copiedSet.insert(c.joint);
  const std::vector<int> copied(copiedSet.begin(), copiedSet.end());
  // Where each copied joint's keys go.
  std::map<int, std::vector<int>> destination;
  if (ontoJoints.empty()) {
    for (int j : copied) destination[j] = {j};
  } else if (copied.size() == 1) {
    destination[copied[0]] = ontoJoints;
  } else if (copied.size() == ontoJoints.size()) {
    for (size_t i = 0; i < copied.size(); ++i) destination[copied[i]] = {ontoJoints[i]};
  } else {
    return "Paste keys: the keys of " + std::to_string(copied.size()) + " joints cannot go onto " +
           std::to_string(ontoJoints.size()) + " selected joints (select one joint per copied joint, or copy one joint)";
  }
  for (const auto& [from, tos] : destination)
    for (int to : tos)
      if (to < 0 || to >= skeleton.size()) return "Paste keys: joint " + std::to_string(to) + " does not exist";
  std::vector<KeyColumn> out;
  for (const CopiedKey& c : clipboard.keys) {
    const float t = grid.frameToTime(frame + std::llround(c.frameOffset));
    for (int joint : destination[c.joint]) {
      auto it = std::find_if(clip.channels.begin(), clip.channels.end(), [&](const Channel& ch) {
        return ch.joint == joint && ch.target == c.target && ch.property == c.property;
      });
      if (it == clip.channels.end()) {
        Channel ch;
        ch.joint = joint;
        ch.target = c.target;
        ch.property = c.property;
        ch.eulerOrder = c.eulerOrder;
        ch.interpolation = c.channelInterpolation;
        clip.channels.push_back(ch);
        it = clip.channels.end() - 1;
      }
      insertKey(*it, t, c.value, c.settings);
      out.push_back({joint, t});
    }
  }
  if (pasted) {
    KeyColumnSelection s;
    s.set(out);
    s.prune(clip);
    *pasted = s.columns();
  }
  return {};
}

// ---- document edits ----

namespace {
// "3 keys": the selected cells (one joint's keys at one frame each, as the dope sheet shows them).
std::string keysPhrase(const KeyColumnSelection& selection) { return countPhrase(selection.columns().size(), "key"); }

std::string clipEdit(Document& doc, const std::string& label, int clipIndex,
                     const std::function<std::string(Clip&, const Skeleton&)>& change) {
  return doc.edit(label, [&](DocumentEdit& e) -> std::string {
    if (clipIndex < 0 || clipIndex >= static_cast<int>(e.clips.size())) return label + ": no clip to edit";
    return change(e.clips[clipIndex], e.skeleton);
  });
}
}  // namespace

std::string moveKeysEdit(Document& doc, int clipIndex, KeyColumnSelection& selection, double frameOffset) {
  if (selection.empty()) return "Move keys: select keys first";
  std::vector<KeyColumn> moved;
  const std::string error = clipEdit(doc, "Move " + keysPhrase(selection), clipIndex, [&](Clip& clip, const Skeleton&) {
    moveKeyColumns(clip, doc.scene().frameGrid(clipIndex), selection.columns(), frameOffset, &moved);
    return std::string();
  });
  if (error.empty()) selection.set(moved);
  return error;
}

std::string deleteKeysEdit(Document& doc, int clipIndex, KeyColumnSelection& selection) {
  if (selection.empty()) return "Delete keys: select keys first";
  const std::string error = clipEdit(doc, "Delete " + keysPhrase(selection), clipIndex, [&](Clip& clip, const Skeleton&) {
    deleteKeyColumns(clip, selection.columns());
    return std::string();
  });
  if (error.empty()) selection.clear();
  return error;
}

std::string pasteKeysEdit(Document& doc, int clipIndex, KeyColumnSelection& selection, const KeyClipboard& clipboard,
                          long long frame, const std::vector<int>& ontoJoints) {
  std::vector<KeyColumn> pasted;
  const std::string error = clipEdit(doc, "Paste " + countPhrase(clipboard.keys.size(), "key") + " at frame " + std::to_string(frame), clipIndex, [&](Clip& clip, const Skeleton& skeleton) {
    return pasteKeys(clip, doc.scene().frameGrid(clipIndex), skeleton, clipboard, frame, ontoJoints, &pasted);
  });
  if (error.empty()) selection.set(pasted);
  return error;
}

std::string KeyMoveDrag::begin(Document& doc, int clipIndex, const KeyColumnSelection& selection) {
  if (selection.empty()) return "Move keys: select keys first";
  if (clipIndex < 0 || clipIndex >= static_cast<int>(doc.scene().clips.size())) return "Move keys: no clip to edit";
  const std::string error = doc.beginDrag("Move " + keysPhrase(selection));
  if (!error.empty()) return error;
  active_ = true;
  clip_ = clipIndex;
  offset_ = 0.0;
  start_ = selection.columns();
  return {};
}

std::string KeyMoveDrag::update(Document& doc, KeyColumnSelection& selection, double frameOffset) {
  if (!active_) return {};
  offset_ = frameOffset;
  std::vector<KeyColumn> moved;
  const std::string error = doc.updateDrag([&](DocumentEdit& e) {
    moveKeyColumns(e.clips[clip_], doc.scene().frameGrid(clip_), start_, frameOffset, &moved);
    return std::string();
  });
  if (error.empty()) selection.set(moved);
  return error;
}

void KeyMoveDrag::commit(Document& doc) {
  if (!active_) return;
  doc.commitDrag();
  active_ = false;
}

void KeyMoveDrag::cancel(Document& doc, KeyColumnSelection& selection) {
  if (!active_) return;
  doc.cancelDrag();
  selection.set(start_);
  active_ = false;
}

}  // namespace kinema
