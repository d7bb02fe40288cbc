#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"
#include "editor/model/joint_selection.h"

namespace kinema {

class Document;

// The dope sheet's model (Blender's Dope Sheet, Action editor): rows are the joints that have
// keys in the edited clip under a summary row, columns are frames, and a diamond stands for
// a "key column": every channel key of one joint at one time. No GL, no window.

// A key column: all channel keys of `joint` at `time` (seconds). The summary row's diamond
// at a time stands for the key columns of every joint at that time.
struct KeyColumn {
  int joint = -1;
  float time = 0.0f;
  bool operator==(const KeyColumn& o) const { return joint == o.joint && time == o.time; }
  bool operator<(const KeyColumn& o) const { return joint != o.joint ? joint < o.joint : time < o.time; }
};

// Keys of one joint at the same key time (sameKeyTime, anim/clip.h: channels keyed on one
// frame by different tools can differ in the last float bits) share a column. Frames are
// the clip's own grid (Clip::timeToFrame / frameToTime), the timeline's.

// One row: a joint's key columns (times ascending), or the summary (joint -1) with the
// times of all of them.
struct DopeSheetRow {
  int joint = -1;
  std::vector<float> times;
};
// The summary row, then each joint with keys, in skeleton (index) order.
std::vector<DopeSheetRow> dopeSheetRows(const Clip& clip);
// Every key column of the clip, sorted.
std::vector<KeyColumn> allKeyColumns(const Clip& clip);
// The key columns a diamond stands for: the row's joint at `time`, or on the summary row
// every joint keyed at `time`.
std::vector<KeyColumn> columnsOfCell(const std::vector<DopeSheetRow>& rows, int row, float time);
// The key columns whose frame lies in [min(frameA, frameB), max] on rows min(rowA, rowB) ..
// max (the summary row takes in every joint at its times).
std::vector<KeyColumn> columnsInBox(const FrameGrid& grid, const std::vector<DopeSheetRow>& rows, double frameA,
                                    double frameB, int rowA, int rowB);

// The selected key columns (sorted, unique). Not undo steps, as the joint selection.
class KeyColumnSelection {
 public:
  const std::vector<KeyColumn>& columns() const { return columns_; }
  bool empty() const { return columns_.empty(); }
  bool contains(const KeyColumn& c) const;
  // True when every column in `cells` is selected (and there is one): a summary diamond
  // shows selected when all the keys it stands for are.
  bool containsAll(const std::vector<KeyColumn>& cells) const;
  void clear() { columns_.clear(); }
  void set(std::vector<KeyColumn> columns);
  // A click on a diamond: select its columns alone, or with extend (Shift) toggle them:
  // deselect when all were selected, else add them.
  void click(const std::vector<KeyColumn>& cell, bool extend);
  void box(const std::vector<KeyColumn>& inside, BoxSelectMode mode);
  // Drops columns that no longer hold keys (after undo, redo or edits elsewhere); `rows`
  // are the clip's dopeSheetRows.
  void prune(const Clip& clip);
  void prune(const std::vector<DopeSheetRow>& rows);

 private:
  std::vector<KeyColumn> columns_;
};

// The panel's layout (dope_sheet_panel.cpp): joint names in a column on the left, the frame
// ruler along the top; the rest of the animation editor area is the key area.
constexpr float kDopeSheetNameWidth = 160.0f;
constexpr float kDopeSheetRulerHeight = 22.0f;

// Pixels <-> (frame, row). The key area is the part of the panel right of the joint names
// and below the frame ruler; frame f is at x = x + (f - firstFrame) * pixelsPerFrame and
// row r (0 = summary) spans y + (r - firstRow) * rowHeight .. + rowHeight.
struct DopeSheetView {
  float x = 0.0f, y = 0.0f, width = 1.0f, height = 1.0f;  // the key area, window pixels
  double firstFrame = -2.0;      // frame at the left edge
  double pixelsPerFrame = 12.0;
  float rowHeight = 20.0f;
  int firstRow = 0;              // scrolled rows

  double frameToX(double frame) const { return x + (frame - firstFrame) * pixelsPerFrame; }
  double xToFrame(double px) const { return firstFrame + (px - x) / pixelsPerFrame; }
  float rowCenterY(int row) const { return y + (static_cast<float>(row - firstRow) + 0.5f) * rowHeight; }
  // The row under pixel row py (may be out of the rows' range).
  int rowAt(float py) const;
  // Zooms the time axis by `factor` keeping the frame under pixel px in place (2 .. 200 px per frame).
  void zoomAt(double px, double factor);
  // Shows frames first .. last across the width (Home: view all).
  void frameRange(double first, double last);
};

// The diamond under pixel p within `radius` pixels (nearest), as row and key time; false when none.
bool hitKeyColumn(const std::vector<DopeSheetRow>& rows, const DopeSheetView& view, const FrameGrid& grid, glm::vec2 p,
                  float radius, int& row, float& time);

// Copied keys: per channel key, its joint, the channel's identity and the key's value and
// settings, at a frame offset from the earliest copied key.
struct CopiedKey {
  int joint = -1;
  double frameOffset = 0.0;
  ChannelTarget target = ChannelTarget::Rotation;
  std::string property;
  EulerOrder eulerOrder = EulerOrder::XYZ;
  Interpolation channelInterpolation = Interpolation::Linear;
  glm::vec4 value{0.0f};
  KeySettings settings;
};
struct KeyClipboard {
  std::vector<CopiedKey> keys;
  bool empty() const { return keys.empty(); }
};

// ---- Edits of a clip (pure; the Document wrappers below make each one undo step) ----
// Moves every key of the columns by `frameOffset` frames, each landing on the nearest whole
// frame (Blender's snap to nearest frame). All moving keys are taken out before any is put
// back, so a key never replaces another that is itself moving; a moved key landing on a
// key that stays replaces it. `moved` gets the columns at their new times.
void moveKeyColumns(Clip& clip, const FrameGrid& grid, const std::vector<KeyColumn>& columns, double frameOffset,
                    std::vector<KeyColumn>* moved = nullptr);
// Deletes every key of the columns; channels left without keys are removed.
void deleteKeyColumns(Clip& clip, const std::vector<KeyColumn>& columns);
KeyClipboard copyKeyColumns(const Clip& clip, const FrameGrid& grid, const std::vector<KeyColumn>& columns);
// Pastes with the earliest copied key at `frame` (offsets kept, snapped to whole frames),
// into the channels of the same joint and target (created when missing). `ontoJoints`
// empty: onto the joints they were copied from; else the copied joints, in index order, go
// to these joints in order (one copied joint goes to each of them). Returns "" or an error.
std::string pasteKeys(Clip& clip, const FrameGrid& grid, const Skeleton& skeleton, const KeyClipboard& clipboard, long long frame,
                      const std::vector<int>& ontoJoints, std::vector<KeyColumn>* pasted = nullptr);

// ---- The same as undo steps of the document's clip `clipIndex` ----
std::string moveKeysEdit(Document& doc, int clipIndex, KeyColumnSelection& selection, double frameOffset);
std::string deleteKeysEdit(Document& doc, int clipIndex, KeyColumnSelection& selection);
std::string pasteKeysEdit(Document& doc, int clipIndex, KeyColumnSelection& selection, const KeyClipboard& clipboard,
                          long long frame, const std::vector<int>& ontoJoints);

// An interactive move (mouse drag or G): one undo step, each update from the start.
class KeyMoveDrag {
 public:
  std::string begin(Document& doc, int clipIndex, const KeyColumnSelection& selection);
  // Moves the start columns by `frameOffset`; the selection follows them.
  std::string update(Document& doc, KeyColumnSelection& selection, double frameOffset);
  void commit(Document& doc);
  void cancel(Document& doc, KeyColumnSelection& selection);  // back to the start
  bool active() const { return active_; }
  double offset() const { return offset_; }

 private:
  bool active_ = false;
  int clip_ = -1;
  double offset_ = 0.0;
  std::vector<KeyColumn> start_;
};

// What the editor keeps for the dope sheet between frames (EditorState::dopeSheet).
struct DopeSheetState {
  KeyColumnSelection selection;
  DopeSheetView view;
  KeyClipboard clipboard;
  KeyMoveDrag move;
  // Mouse interaction of the panel: a left press on empty space (box select on drag, clear
  // on click), on a diamond (select; drag moves), G's modal move, middle-drag pan.
  enum class Gesture { None, Press, Box, DragKeys, GrabKeys, Pan } gesture = Gesture::None;
  glm::vec2 pressMouse{0.0f};
  double pressFrame = 0.0;
  bool pressExtend = false;
};

}  // namespace kinema
