#pragma once
// Crowds in the editor (issue 24), window-free: adding, editing and removing a crowd, the
// naive-average toggle and baking a crowd to a clip per member (each one undo step); and the
// crowd run for the viewport (the members' joints at the playhead and one member's impulse
// vectors, as in the seed's figure 16.28). The crowd itself is sim/crowd.h's, the one
// `kinema simulate` runs.
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "sim/crowd.h"

namespace kinema {

class Document;

// A new crowd of the document's own character, scaled to its size (metres or centimetres):
// 50 members starting left of an obstacle sphere at the origin, walking towards a goal past
// it on the right; the document's active clip.
CrowdSettings defaultCrowd(const Document& doc);

std::string addCrowdEdit(Document& doc, const CrowdSettings& crowd);             // "Add crowd"
std::string setCrowdEdit(Document& doc, int index, const CrowdSettings& crowd);  // "Crowd settings"
std::string removeCrowdEdit(Document& doc, int index);                          // "Remove crowd"
// Flips crowd `index` between the seed's priority allocation and the naive average.
std::string toggleNaiveAverageEdit(Document& doc, int index);
// Bakes crowd `index` over frames first..last (of its clip's frame grid): each member's clip
// ("crowd_0007") added to the document, replacing clips of the same names: one undo step
// "Bake crowd". Only a crowd of the document's own character (its clips must fit the
// skeleton). `clips` gets how many clips were written.
std::string bakeCrowdEdit(Document& doc, int index, long long first, long long last, int* clips = nullptr);

// One impulse of the debug member as a line in the viewport.
struct CrowdDebugVector {
  glm::vec3 from{0.0f}, to{0.0f};
  glm::vec4 color{1.0f};
  const char* label = "";
};
// The colours of the five impulses (avoidance, separation, alignment, cohesion, goal) and of
// the resulting acceleration; the Crowd panel's legend uses the same.
const glm::vec4& crowdImpulseColor(int impulse);  // 0..kBoidImpulseCount (the last: the result)

// The crowd drawn live: the run is computed again only when the document or the crowd changed
// (or a later frame is asked for); each frame then poses every member at the playhead.
struct CrowdPreview {
  long long changeCount = -1;
  int crowd = -1;
  std::string documentPath;
  std::shared_ptr<const Scene> character;  // the crowd's character (a copy of the document's own, or its file)
  CrowdClipMotion motion;
  CrowdRun run;
  std::string error;  // why there is no run ("" when there is)
  // At the frame shown:
  long long frame = -1;
  std::vector<std::vector<glm::mat4>> world;  // each member's joints (model space)
  std::vector<CrowdDebugVector> vectors;      // the debug member's impulses and their sum
  long long runs = 0;                         // how many times the crowd was run (tests)
};

// Brings `preview` to crowd `index` of the document at time `time` seconds (the frame of the
// crowd clip's grid nearest it). Returns false (preview.error says why) when there is no crowd
// to show. The debug vectors start at the debug member's position raised by `height` (< 0: by
// the mean height of its joints) and
// show each desired acceleration scaled by `seconds` (m/s^2 * s = m).
bool updateCrowdPreview(CrowdPreview& preview, const Document& doc, int index, double time, float height = 0.0f,
                        float seconds = 0.25f);

}  // namespace kinema

namespace kinema {

// The editor's crowd state (EditorState::crowds): the Crowd panel, the crowd it edits, the
// live drawing.
struct CrowdEditorState {
  bool windowOpen = false;
  int active = 0;     // the crowd the panel edits, Bake Crowd bakes and the viewport draws
  bool live = true;   // draw the flock in the viewport
  // Members drawn as bodies (the first ones and the debug member); the rest as bones. Each body
  // is two passes of the whole mesh, which a software renderer (llvmpipe) cannot afford for
  // hundreds of members at interactive rates.
  int bodyBudget = 24;
  CrowdPreview preview;
};

}  // namespace kinema
