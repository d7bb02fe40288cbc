#pragma once
#include "anim/key_preferences.h"

namespace kinema {

// Auto-key (the timeline's record button): while enabled, every posing edit and drag keys
// the joints whose local transform it changed at the document's playhead (its time in its
// clip, created as "Action" when the scene has none), in the same undo step as the edit.
struct AutoKeySettings {
  bool enabled = false;
  KeyPreferences preferences;
};

}  // namespace kinema
