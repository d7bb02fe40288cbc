#pragma once
// Foot contacts of a clip (Clip::contacts, frames of its grid) as the timeline shows and edits
// them, like Blender's strips: detect them, add one over a frame range, delete one, drag a
// bar's start or end (or the whole bar, or a new bar drawn on an empty lane). Each edit is
// one undo step (a drag one step at release). No GL, no window.
#include <string>

#include "anim/clip.h"

namespace kinema {

class Document;

// The contact a click chose (Foot Contacts panel, timeline bars): not an undo step, like the
// joint selection. index -1: none.
struct FootContactSelection {
  Foot foot = Foot::Left;
  int index = -1;
  bool valid(const Clip& clip) const {
    return index >= 0 && index < static_cast<int>(clip.contacts.of(foot).size());
  }
};

// Detects the contacts of clip `clip` from the document skeleton's humanoid legs (the
// detection `kinema retarget` runs, retarget/motion_cleanup.h) and replaces the clip's
// contacts with them: one undo step "Detect foot contacts". "" or why nothing changed (no
// clip, no humanoid legs).
std::string detectFootContactsEdit(Document& doc, int clip);
// Adds a contact on `foot` over frames first..last (either order; clamped to frame 0); the
// contacts it overlaps merge into it. One undo step "Add foot contact". `added` gets the new
// contact's index.
std::string addFootContactEdit(Document& doc, int clip, Foot foot, int first, int last, int* added = nullptr);
// Deletes contact `index` of `foot`: one undo step "Delete foot contact".
std::string deleteFootContactEdit(Document& doc, int clip, Foot foot, int index);
// Sets contact `index`'s frames (clamped as a drag clamps, footContactClamp): one undo step.
std::string setFootContactEdit(Document& doc, int clip, Foot foot, int index, int first, int last);

// What part of a bar a drag moves.
enum class ContactDragPart { Start, End, Whole, New };

// `wanted` frames for contact `index` of `list`, kept at frame >= 0, first <= last and clear
// of its neighbours (prev.last < first, last < next.first): a dragged end stops at the next
// bar, a moved bar keeps its length.
ContactInterval footContactClamp(const std::vector<ContactInterval>& list, int index, ContactInterval wanted,
                                 ContactDragPart part);

// A drag of a bar's part with the mouse: one undo step from begin to commit (Document drag:
// Esc cancels back to the start). Frames are the clip's grid; `grabFrame` is the frame under
// the mouse at the press, each update the frame under it now.
class FootContactDrag {
 public:
  // part New: a new contact grows from `grabFrame` on `foot` (index ignored); it refuses a
  // frame inside an existing contact.
  std::string begin(Document& doc, int clip, Foot foot, int index, ContactDragPart part, long long grabFrame);
  std::string update(Document& doc, long long frame);
  void commit(Document& doc);
  void cancel(Document& doc);
  bool active() const { return active_; }
  Foot foot() const { return foot_; }
  int index() const { return index_; }  // the contact being dragged (after begin: New's too)
  ContactDragPart part() const { return part_; }

 private:
  bool active_ = false;
  int clip_ = 0;
  Foot foot_ = Foot::Left;
  int index_ = -1;
  ContactDragPart part_ = ContactDragPart::Whole;
  long long grab_ = 0;
  ContactInterval start_;
};

}  // namespace kinema
