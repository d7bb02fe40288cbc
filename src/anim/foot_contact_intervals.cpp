#include "anim/foot_contact_intervals.h"

#include <algorithm>

#include "anim/frame_grid.h"

namespace kinema {

const char* toString(Foot foot) { return foot == Foot::Left ? "left" : "right"; }

std::string FootContacts::validate() const {
  for (int f = 0; f < 2; ++f) {
    const std::string side = toString(static_cast<Foot>(f));
    for (size_t i = 0; i < feet[f].size(); ++i) {
      const ContactInterval& c = feet[f][i];
      const std::string where = side + " contact " + std::to_string(i);
      if (c.first < 0) return where + " starts before frame 0";
      if (c.last < c.first) return where + " ends (frame " + std::to_string(c.last) + ") before it starts (frame " +
                                   std::to_string(c.first) + ")";
      if (i > 0 && c.first <= feet[f][i - 1].last)
        return where + " starts at frame " + std::to_string(c.first) + ", not after contact " + std::to_string(i - 1) +
               " ends (frame " + std::to_string(feet[f][i - 1].last) + ")";
    }
  }
  return {};
}

FootContacts contactsOnGrid(const FootContacts& contacts, const FrameGrid& from, const FrameGrid& to) {
  FootContacts out;
  for (int f = 0; f < 2; ++f)
    for (const ContactInterval& c : contacts.feet[f]) {
      const ContactInterval moved{static_cast<int>(to.nearestFrame(from.frameToTime(c.first))),
                                  static_cast<int>(to.nearestFrame(from.frameToTime(c.last)))};
      std::vector<ContactInterval>& foot = out.feet[f];
      if (!foot.empty() && moved.first <= foot.back().last)
        foot.back().last = std::max(foot.back().last, moved.last);
      else
        foot.push_back(moved);
    }
  return out;
}

}  // namespace kinema
