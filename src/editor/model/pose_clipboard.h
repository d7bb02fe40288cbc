#pragma once
#include <string>
#include <vector>

#include "editor/model/document.h"

namespace kinema {

// Copied local rotations (and root translations) of joints, by joint name, so they paste
// onto any skeleton with the same names.
struct PoseClipboard {
  struct Entry {
    std::string joint;
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    bool hasTranslation = false;  // roots: their translation is copied too
    glm::vec3 translation{0.0f};
  };
  std::vector<Entry> entries;
  bool empty() const { return entries.empty(); }
};

// A rotation mirrored across the X = 0 plane: (w, x, y, z) -> (w, x, -y, -z).
glm::quat mirrorRotationX(const glm::quat& q);
// A translation mirrored across X = 0: x -> -x.
glm::vec3 mirrorTranslationX(const glm::vec3& t);

// Copies the given joints (Ctrl+C: the selection).
PoseClipboard copyPose(const Document& doc, const std::vector<int>& joints);
// Pastes onto joints of the same names (one undo step). flipped: onto the mirror partners
// (mirror_names.h; centre joints onto themselves) with the values X-mirrored. Names the
// document lacks are skipped; an error when nothing matched.
std::string pastePose(Document& doc, const PoseClipboard& clipboard, bool flipped = false);

}  // namespace kinema
