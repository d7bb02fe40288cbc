#include "editor/model/contact_lanes.h"

#include <cmath>

#include "editor/model/editor_state.h"

namespace kinema {

bool contactLanesWanted(const EditorState& s) { return s.bottomPanels().contactLanes; }

ContactLanes contactLanes(const EditorState& s, const PanelRect& strip) {
  ContactLanes l;
  // The ruler's own mapping (timelineRuler takes x and width from its strip; the height does
  // not matter for x).
  l.frames = timelineRuler(s, strip.x, strip.y, strip.w, kTimelineHeight);
  l.y = strip.y + 1.0f;
  l.laneHeight = std::max((strip.h - 2.0f) * 0.5f, 1.0f);
  return l;
}

ContactHit hitContactLanes(const ContactLanes& l, const Clip& clip, glm::vec2 p, float handle) {
  ContactHit hit;
  if (!(p.y >= l.y && p.y < l.y + 2.0f * l.laneHeight) || p.x < l.frames.x || p.x > l.frames.x + l.frames.w) return hit;
  hit.lane = true;
  hit.foot = p.y < l.y + l.laneHeight ? Foot::Left : Foot::Right;
  hit.frame = l.frames.frameAtX(p.x);
  const std::vector<ContactInterval>& list = clip.contacts.of(hit.foot);
  float best = handle + 1.0f;
  for (int i = 0; i < static_cast<int>(list.size()); ++i) {
    const float x0 = l.barLeft(list[i]), x1 = l.barRight(list[i]);
    if (p.x < x0 - handle || p.x > x1 + handle) continue;
    const float d0 = std::abs(p.x - x0), d1 = std::abs(p.x - x1);
    // The nearer end within `handle` (the end on a one-frame bar: it grows), else the middle.
    if (d0 <= handle || d1 <= handle) {
      const float d = std::min(d0, d1);
      if (d < best) {
        best = d;
        hit.index = i;
        hit.part = d1 <= d0 ? ContactDragPart::End : ContactDragPart::Start;
      }
    } else if (hit.index < 0 && p.x > x0 && p.x < x1) {
      hit.index = i;
      hit.part = ContactDragPart::Whole;
    }
  }
  return hit;
}

}  // namespace kinema
