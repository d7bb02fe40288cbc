// Foot contact edits on the document's clips (foot_contact_edits.h): each through
// Document::edit or a Document drag, so undo and redo restore the clip's contacts exactly.
#include "editor/model/foot_contact_edits.h"

#include <algorithm>
#include <climits>

#include "editor/model/document.h"
#include "retarget/bone_map.h"
#include "retarget/motion_cleanup.h"

namespace kinema {

namespace {

bool hasClip(const Document& doc, int clip) { return clip >= 0 && clip < static_cast<int>(doc.scene().clips.size()); }

std::string noClip() { return "Foot contacts: the document has no clip (import or key a motion first)"; }

}  // namespace

std::string detectFootContactsEdit(Document& doc, int clip) {
  if (!hasClip(doc, clip)) return noClip();
  const Skeleton& s = doc.skeleton();
  const Result<HumanoidReading> human = findHumanoid(s);
  if (!human) return "Detect foot contacts: the skeleton is not a humanoid (" + human.error() + ")";
  LegJoints legs[2];
  if (std::string bad = humanoidLegs(s, human->bones, legs); !bad.empty())
    return "Detect foot contacts: " + bad;
  FootContacts found;
  if (std::string bad = detectFootContacts(s, doc.scene().clips[clip], legs, found); !bad.empty())
    return "Detect foot contacts: " + bad;
  return doc.edit("Detect foot contacts", [&](DocumentEdit& e) {
    e.clips[clip].contacts = found;
    return std::string();
  });
}

ContactInterval footContactClamp(const std::vector<ContactInterval>& list, int index, ContactInterval wanted,
                                 ContactDragPart part) {
  const int n = static_cast<int>(list.size());
  const long long lo = index > 0 ? static_cast<long long>(list[index - 1].last) + 1 : 0;
  const long long hi = index + 1 < n ? static_cast<long long>(list[index + 1].first) - 1 : INT_MAX;
  long long first = wanted.first, last = wanted.last;
  switch (part) {
    case ContactDragPart::Start:
      first = std::clamp(first, lo, std::max(last, lo));
      break;
    case ContactDragPart::End:
      last = std::clamp(last, std::min(first, hi), hi);
      break;
    case ContactDragPart::Whole: {
      const long long length = last - first;
      if (first < lo) first = lo;
      if (first + length > hi) first = hi - length;
      first = std::max(first, lo);
      last = std::min(first + length, hi);
      break;
    }
    case ContactDragPart::New:
      if (first > last) std::swap(first, last);
      first = std::clamp(first, lo, hi);
      last = std::clamp(last, first, hi);
      break;
  }
  return ContactInterval{static_cast<int>(first), static_cast<int>(last)};
}

std::string addFootContactEdit(Document& doc, int clip, Foot foot, int first, int last, int* added) {
  if (!hasClip(doc, clip)) return noClip();
  if (first > last) std::swap(first, last);
  first = std::max(first, 0);
  last = std::max(last, 0);
  int at = -1;
  const std::string error = doc.edit("Add foot contact", [&](DocumentEdit& e) {
    std::vector<ContactInterval>& list = e.clips[clip].contacts.of(foot);
    ContactInterval merged{first, last};
    std::vector<ContactInterval> kept;
    for (const ContactInterval& c : list) {
      if (c.last < first || c.first > last) {
        kept.push_back(c);
        continue;
      }
      merged.first = std::min(merged.first, c.first);  // overlapping contacts join the new one
      merged.last = std::max(merged.last, c.last);
    }
    const auto pos = std::lower_bound(kept.begin(), kept.end(), merged,
                                      [](const ContactInterval& a, const ContactInterval& b) { return a.first < b.first; });
    at = static_cast<int>(pos - kept.begin());
    kept.insert(pos, merged);
    list = std::move(kept);
    return std::string();
  });
  if (error.empty() && added) *added = at;
  return error;
}

std::string deleteFootContactEdit(Document& doc, int clip, Foot foot, int index) {
  if (!hasClip(doc, clip)) return noClip();
  const std::vector<ContactInterval>& list = doc.scene().clips[clip].contacts.of(foot);
  if (index < 0 || index >= static_cast<int>(list.size()))
    return std::string("Delete foot contact: select a contact first (click its bar on the timeline)");
  return doc.edit("Delete foot contact", [&](DocumentEdit& e) {
    std::vector<ContactInterval>& l = e.clips[clip].contacts.of(foot);
    l.erase(l.begin() + index);
    return std::string();
  });
}

std::string setFootContactEdit(Document& doc, int clip, Foot foot, int index, int first, int last) {
  if (!hasClip(doc, clip)) return noClip();
  const std::vector<ContactInterval>& list = doc.scene().clips[clip].contacts.of(foot);
  if (index < 0 || index >= static_cast<int>(list.size())) return "Set foot contact: no such contact";
  ContactInterval c = footContactClamp(list, index, ContactInterval{first, std::max(first, last)}, ContactDragPart::Start);
  c = footContactClamp(list, index, c, ContactDragPart::End);
  return doc.edit("Set foot contact frames", [&](DocumentEdit& e) {
    e.clips[clip].contacts.of(foot)[index] = c;
    return std::string();
  });
}

std::string FootContactDrag::begin(Document& doc, int clip, Foot foot, int index, ContactDragPart part,
                                   long long grabFrame) {
  if (active_) return "a contact drag is already running";
  if (!hasClip(doc, clip)) return noClip();
  const std::vector<ContactInterval>& list = doc.scene().clips[clip].contacts.of(foot);
  grabFrame = std::clamp(grabFrame, 0LL, static_cast<long long>(INT_MAX));
  if (part == ContactDragPart::New) {
    for (const ContactInterval& c : list)
      if (grabFrame >= c.first && grabFrame <= c.last) return "Add foot contact: frame " + std::to_string(grabFrame) + " is in a contact already";
    index = static_cast<int>(std::lower_bound(list.begin(), list.end(), static_cast<int>(grabFrame),
                                              [](const ContactInterval& c, int f) { return c.first < f; }) -
                             list.begin());
    start_ = ContactInterval{static_cast<int>(grabFrame), static_cast<int>(grabFrame)};
  } else {
    if (index < 0 || index >= static_cast<int>(list.size())) return "no such foot contact";
    start_ = list[index];
  }
  static const char* const labels[] = {"Move foot contact start", "Move foot contact end", "Move foot contact",
                                       "Add foot contact"};
  if (std::string error = doc.beginDrag(labels[static_cast<int>(part)]); !error.empty()) return error;
  active_ = true;
  clip_ = clip;
  foot_ = foot;
  index_ = index;
  part_ = part;
  grab_ = grabFrame;
  const std::string error = update(doc, grabFrame);
  if (!error.empty()) cancel(doc);
  return error;
}

std::string FootContactDrag::update(Document& doc, long long frame) {
  if (!active_) return "no contact drag is running";
  frame = std::clamp(frame, 0LL, static_cast<long long>(INT_MAX));
  const long long delta = frame - grab_;
  return doc.updateDrag([&](DocumentEdit& e) {
    std::vector<ContactInterval>& list = e.clips[clip_].contacts.of(foot_);
    if (part_ == ContactDragPart::New) list.insert(list.begin() + index_, start_);  // the state at begin lacks it
    ContactInterval wanted = start_;
    switch (part_) {
      case ContactDragPart::Start: wanted.first = static_cast<int>(std::clamp<long long>(start_.first + delta, 0, INT_MAX)); break;
      case ContactDragPart::End: wanted.last = static_cast<int>(std::clamp<long long>(start_.last + delta, 0, INT_MAX)); break;
      case ContactDragPart::Whole:
        wanted.first = static_cast<int>(std::clamp<long long>(start_.first + delta, 0, INT_MAX));
        wanted.last = wanted.first + (start_.last - start_.first);
        break;
      case ContactDragPart::New:
        wanted = ContactInterval{static_cast<int>(grab_), static_cast<int>(frame)};
        break;
    }
    list[index_] = footContactClamp(list, index_, wanted, part_);
    return std::string();
  });
}

void FootContactDrag::commit(Document& doc) {
  if (!active_) return;
  doc.commitDrag();
  active_ = false;
}

void FootContactDrag::cancel(Document& doc) {
  if (!active_) return;
  doc.cancelDrag();
  active_ = false;
}

}  // namespace kinema
