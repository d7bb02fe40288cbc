#include "editor/model/pose_clipboard.h"

#include "editor/model/edit_labels.h"
#include "editor/model/mirror_names.h"

namespace kinema {

glm::quat mirrorRotationX(const glm::quat& q) { return glm::quat(q.w, q.x, -q.y, -q.z); }
glm::vec3 mirrorTranslationX(const glm::vec3& t) { return glm::vec3(-t.x, t.y, t.z); }

PoseClipboard copyPose(const Document& doc, const std::vector<int>& joints) {
  PoseClipboard clip;
  const Skeleton& s = doc.skeleton();
  for (int j : joints) {
    if (j < 0 || j >= s.size()) continue;
    PoseClipboard::Entry e;
    e.joint = s.names[j];
    e.rotation = doc.pose().local[j].rotation;
    e.hasTranslation = s.parents[j] < 0;
    e.translation = doc.pose().local[j].translation;
    clip.entries.push_back(e);
  }
  return clip;
}

std::string pastePose(Document& doc, const PoseClipboard& clipboard, bool flipped) {
  if (clipboard.empty()) return "the pose clipboard is empty";
  std::vector<std::pair<int, const PoseClipboard::Entry*>> matches;
  for (const PoseClipboard::Entry& e : clipboard.entries) {
    std::string name = e.joint;
    if (flipped) {
      const std::string partner = mirroredJointName(name);
      if (!partner.empty()) name = partner;  // centre joints paste onto themselves
    }
    const int j = doc.skeleton().find(name);
    if (j >= 0) matches.push_back({j, &e});
  }
  if (matches.empty())
    return "none of the copied joints (" + clipboard.entries.front().joint + (clipboard.entries.size() > 1 ? ", ..." : "") +
           ") is in this skeleton";
  std::vector<int> onto;
  for (const auto& m : matches) onto.push_back(m.first);
  return doc.edit(std::string(flipped ? "Paste flipped pose onto " : "Paste pose onto ") + jointsPhrase(doc.skeleton(), onto),
                  [&](DocumentEdit& e) {
    for (const auto& [j, entry] : matches) {
      e.pose.local[j].rotation = flipped ? mirrorRotationX(entry->rotation) : entry->rotation;
      if (entry->hasTranslation)
        e.pose.local[j].translation = flipped ? mirrorTranslationX(entry->translation) : entry->translation;
    }
    return std::string();
  });
}

}  // namespace kinema
