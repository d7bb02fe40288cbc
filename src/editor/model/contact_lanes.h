#pragma once
// The foot contact strip over the timeline: a lane per foot (left on top) with a bar per
// contact of the edited clip, on the timeline ruler's frame scale so a bar's ends line up
// with the ruler's frames. Pixels <-> contacts for the panel's clicks and drags. No GL.
#include <algorithm>

#include <glm/glm.hpp>

#include "anim/clip.h"
#include "editor/model/editor_layout.h"
#include "editor/model/foot_contact_edits.h"
#include "editor/model/timeline.h"

namespace kinema {

struct EditorState;

// Whether the strip shows: on a clip with contacts, or while the Clean Up window (where
// contacts are added and detected) is open.
bool contactLanesWanted(const EditorState& state);

struct ContactLanes {
  TimelineRuler frames;   // x <-> frame exactly as the timeline's ruler below
  float y = 0, laneHeight = 1;
  float laneTop(Foot foot) const { return y + laneHeight * static_cast<float>(foot); }
  // A contact's bar, window pixels: from its first frame's x to its last's (at least 3 px).
  float barLeft(const ContactInterval& c) const { return frames.xOfFrame(c.first); }
  float barRight(const ContactInterval& c) const { return std::max(frames.xOfFrame(c.last), barLeft(c) + 3.0f); }
};
// The lanes in `strip` (EditorState::layout.contactLanes).
ContactLanes contactLanes(const EditorState& state, const PanelRect& strip);

// What is under window pixel p: a bar's start or end (within `handle` px of it), its
// middle (Whole), or an empty lane (New, at `frame`); `lane` false when p is on no lane.
struct ContactHit {
  bool lane = false;
  Foot foot = Foot::Left;
  int index = -1;  // the contact (-1 for New)
  ContactDragPart part = ContactDragPart::New;
  long long frame = 0;  // the frame under p (the ruler's nearest, clamped to its range)
};
ContactHit hitContactLanes(const ContactLanes& lanes, const Clip& clip, glm::vec2 p, float handle);

}  // namespace kinema
