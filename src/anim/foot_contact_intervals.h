#pragma once
// When each foot of a clip is planted: per foot (left, right) a list of frame intervals of
// the clip's frame grid (Clip::frameToTime), kept with the clip so the editor shows, edits
// and saves them (.kinema clips[c].foot_contacts) and foot locking reads them.
#include <string>
#include <vector>

namespace kinema {

struct FrameGrid;  // anim/frame_grid.h (which includes this through anim/clip.h)

// Frames first..last (inclusive) of the clip's frame grid; 0 <= first <= last.
struct ContactInterval {
  int first = 0, last = 0;
  bool operator==(const ContactInterval& o) const { return first == o.first && last == o.last; }
  bool operator!=(const ContactInterval& o) const { return !(*this == o); }
  int frames() const { return last - first + 1; }
};

enum class Foot { Left = 0, Right = 1 };
const char* toString(Foot foot);  // "left", "right"

// Both feet's contacts, each list sorted and without overlaps (two intervals that touch,
// 5..9 and 10..12, stay two: a foot lifted for no frame is still two steps).
struct FootContacts {
  std::vector<ContactInterval> feet[2];  // [Foot::Left], [Foot::Right]

  std::vector<ContactInterval>& of(Foot f) { return feet[static_cast<int>(f)]; }
  const std::vector<ContactInterval>& of(Foot f) const { return feet[static_cast<int>(f)]; }
  bool empty() const { return feet[0].empty() && feet[1].empty(); }
  bool operator==(const FootContacts& o) const { return feet[0] == o.feet[0] && feet[1] == o.feet[1]; }
  bool operator!=(const FootContacts& o) const { return !(*this == o); }
  // "" or what is wrong: "left contact 2 starts before contact 1 ends" and the like.
  std::string validate() const;
};

// `contacts`, counted on grid `from`, counted again on grid `to` (the clip's rate changed):
// each interval keeps its moments (the planted feet are in the keys, which keep their times),
// its first and last frame the nearest of `to`; intervals that then overlap are merged.
FootContacts contactsOnGrid(const FootContacts& contacts, const FrameGrid& from, const FrameGrid& to);

}  // namespace kinema
