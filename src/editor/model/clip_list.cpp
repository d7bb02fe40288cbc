#include "editor/model/clip_list.h"

#include <algorithm>
#include <cctype>

#include "editor/model/document.h"
#include "editor/model/keying.h"
#include "editor/model/unique_name.h"
#include "io/text_file.h"

namespace kinema {

namespace {

bool nameTaken(const std::vector<Clip>& clips, const std::string& name, int except = -1) {
  for (size_t c = 0; c < clips.size(); ++c)
    if (static_cast<int>(c) != except && clips[c].name == name) return true;
  return false;
}

bool isClip(const Document& doc, int clip) {
  return clip >= 0 && clip < static_cast<int>(doc.scene().clips.size());
}

}  // namespace

std::string uniqueClipName(const std::vector<Clip>& clips, const std::string& base) {
  return uniqueName(base, [&](const std::string& name) { return nameTaken(clips, name); });
}

std::string chooseClip(Document& doc, int clip) {
  if (!isClip(doc, clip)) return "there is no clip " + std::to_string(clip) + " to choose";
  return doc.edit("Choose clip " + doc.scene().clips[clip].name, [&](DocumentEdit& e) {
    e.activeClip = clip;
    return std::string();
  });
}

std::string newClip(Document& doc) {
  Clip clip = newActionClip(doc.scene().frameGrid(-1));
  clip.name = uniqueClipName(doc.scene().clips, clip.name);
  return doc.edit("New clip " + clip.name, [&](DocumentEdit& e) {
    e.clips.push_back(clip);
    e.activeClip = static_cast<int>(e.clips.size()) - 1;
    return std::string();
  });
}

std::string duplicateClip(Document& doc) {
  const int active = doc.activeClip();
  if (!isClip(doc, active)) return "there is no clip to duplicate";
  Clip copy = doc.scene().clips[active];
  copy.name = uniqueClipName(doc.scene().clips, copy.name);
  return doc.edit("Duplicate clip " + doc.scene().clips[active].name, [&](DocumentEdit& e) {
    e.clips.insert(e.clips.begin() + active + 1, copy);
    e.activeClip = active + 1;
    return std::string();
  });
}

std::string renameClip(Document& doc, int clip, const std::string& name) {
  if (!isClip(doc, clip)) return "there is no clip " + std::to_string(clip) + " to rename";
  const std::vector<Clip>& clips = doc.scene().clips;
  if (std::all_of(name.begin(), name.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }))
    return "a clip name may not be empty";
  if (!isValidUtf8(name)) return "a clip name must be UTF-8 text";
  for (char c : name)
    if (static_cast<unsigned char>(c) < 0x20) return "a clip name may not hold control characters";
  if (nameTaken(clips, name, clip)) return "another clip is already named '" + name + "'";
  return doc.edit("Rename clip " + clips[clip].name + " to " + name, [&](DocumentEdit& e) {
    e.clips[clip].name = name;
    return std::string();
  });
}

std::string deleteClip(Document& doc) {
  const int active = doc.activeClip();
  if (!isClip(doc, active)) return "there is no clip to delete";
  // Not a posing edit: auto-key must not key the rest pose into a new "Action" at once.
  const bool autoKey = doc.autoKey.enabled;
  doc.autoKey.enabled = false;
  const std::string error = doc.edit("Delete clip " + doc.scene().clips[active].name, [&](DocumentEdit& e) {
    e.clips.erase(e.clips.begin() + active);
    const int left = static_cast<int>(e.clips.size());
    e.activeClip = std::min(active, std::max(left - 1, 0));
    // Nothing animates the character any more: back to its rest pose (as Blender shows a
    // bone without an action), so the pose does not keep a frame of a clip that is gone.
    if (left == 0) e.pose = Pose::rest(e.skeleton);
    return std::string();
  });
  doc.autoKey.enabled = autoKey;
  return error;
}

}  // namespace kinema
